// boreas render: OpenGL object names owned by RAII handles, so a renderer that throws
// half-way through its constructor leaves no buffers or textures behind.
#pragma once

#include <utility>

namespace boreas::render {

class GlObject {
 public:
  using Destroy = void (*)(unsigned);
  GlObject() = default;
  GlObject(unsigned id, Destroy destroy) : id_(id), destroy_(destroy) {}
  ~GlObject() { reset(); }
  GlObject(GlObject&& other) noexcept
      : id_(std::exchange(other.id_, 0u)), destroy_(other.destroy_) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0u);
      destroy_ = other.destroy_;
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  unsigned id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_ != 0) destroy_(id_);
    id_ = 0;
  }

 private:
  unsigned id_ = 0;
  Destroy destroy_ = nullptr;
};

// glCreate* through the DSA entry points (OpenGL 4.5).
GlObject make_buffer();
GlObject make_texture(unsigned target);
GlObject make_framebuffer();
GlObject make_vertex_array();

}  // namespace boreas::render
