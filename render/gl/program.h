// boreas render: a linked GLSL program from shader files (render/shaders/), with
// `#version 450 core` and the caller's #defines put in front of each stage.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace boreas::render {

struct ShaderStage {
  unsigned type;     // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, ...
  std::string file;  // e.g. "branch.vert"
};

class Program {
 public:
  // Compiles and links; a failure throws ShaderError with the file name and the
  // driver's log.
  Program(const std::vector<ShaderStage>& stages, const std::string& defines = "");
  ~Program();
  Program(Program&& other) noexcept;
  Program& operator=(Program&&) = delete;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  unsigned id() const { return id_; }
  void use() const;
  // The uniform's location, -1 if the linker dropped it (unused): setting -1 is a no-op.
  int uniform(const char* name) const;

 private:
  unsigned id_ = 0;
};

}  // namespace boreas::render
