// boreas interop: an OpenGL 4.5 core context through GLFW, in a window or hidden (the
// window is never shown: tests and `boreas run` without --window draw into framebuffers).
// Under Xvfb (xvfb-run -a) Mesa's llvmpipe provides it on machines without a GPU.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

struct GLFWwindow;

namespace boreas::interop {

// Why there is no context: no display, no OpenGL 4.5, GLFW failing. The message says what
// to do about it (run under xvfb-run -a, install Mesa's drivers).
struct GlError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct GlContextDef {
  int width = 1280, height = 720;  // the window's, in screen units
  bool visible = false;
  const char* title = "boreas";
  // EGL instead of GLX for the context (cl_khr_gl_sharing through EGL on NVIDIA).
  bool egl = false;
};

class GlContext {
 public:
  explicit GlContext(const GlContextDef& def = {});
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  GLFWwindow* window() const { return window_; }
  void make_current();
  // "4.5 (Core Profile) Mesa 22.3.6 | llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string description() const;
  // Whether the renderer is a software rasterizer (llvmpipe, softpipe, swrast).
  bool software() const;

  // The OpenCL context properties that make a CL context share this GL context's objects
  // (CL_GL_CONTEXT_KHR and the GLX or EGL display), ending in 0: boreas_world_def's
  // cl_context_properties. Empty if GLFW cannot say (no native access).
  std::vector<intptr_t> cl_sharing_properties() const;

  // OpenGL errors and debug messages of high severity since the last call (KHR_debug).
  std::vector<std::string> take_messages();

 private:
  GLFWwindow* window_ = nullptr;
  bool egl_ = false;
};

}  // namespace boreas::interop
