// boreas interop: the OpenGL context (gl_context.h).
#include "gl_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <epoxy/glx.h>
// GLFW after epoxy, which defines the GL types and must come first. The native handles
// come from GLX and EGL themselves (through epoxy): glfw3native.h would need Xrandr's
// headers for nothing.
#include <GLFW/glfw3.h>

#include <CL/cl_gl.h>
#include <CL/cl_egl.h>

#include <cstdlib>
#include <mutex>

namespace boreas::interop {
namespace {

thread_local std::string g_glfw_error;

void on_glfw_error(int code, const char* text) {
  g_glfw_error = "GLFW error " + std::to_string(code) + ": " + (text ? text : "?");
}

// GLFW is initialized once per process and never terminated while a context may live.
void init_glfw() {
  static std::once_flag once;
  static bool ok = false;
  std::call_once(once, [] {
    glfwSetErrorCallback(on_glfw_error);
    ok = glfwInit() == GLFW_TRUE;
  });
  if (!ok) {
    const char* display = std::getenv("DISPLAY");
    throw GlError("OpenGL is not available: " + g_glfw_error +
                  (display ? "" : " (no DISPLAY: run under `xvfb-run -a`, or on a desktop)"));
  }
}

void GLAPIENTRY on_gl_message(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* text,
                              const void* user) {
  if (severity != GL_DEBUG_SEVERITY_HIGH && type != GL_DEBUG_TYPE_ERROR) return;
  auto* out = static_cast<std::vector<std::string>*>(const_cast<void*>(user));
  out->push_back(text ? text : "?");
}

thread_local std::vector<std::string> g_gl_messages;

}  // namespace

GlContext::GlContext(const GlContextDef& def) : egl_(def.egl) {
  init_glfw();
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, def.visible ? GLFW_TRUE : GLFW_FALSE);
  if (def.egl) glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
  g_glfw_error.clear();
  window_ = glfwCreateWindow(def.width, def.height, def.title, nullptr, nullptr);
  if (!window_)
    throw GlError("no OpenGL 4.5 core context: " + g_glfw_error +
                  " (boreas needs OpenGL 4.5: Mesa's llvmpipe gives it, under `xvfb-run -a` without a display)");
  make_current();
  glDebugMessageCallback(on_gl_message, &g_gl_messages);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
}

GlContext::~GlContext() {
  if (window_) glfwDestroyWindow(window_);
}

void GlContext::make_current() { glfwMakeContextCurrent(window_); }

std::string GlContext::description() const {
  auto str = [](GLenum e) {
    const GLubyte* s = glGetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  };
  return str(GL_VERSION) + " | " + str(GL_RENDERER);
}

bool GlContext::software() const {
  const std::string renderer = description();
  for (const char* soft : {"llvmpipe", "softpipe", "swrast"})
    if (renderer.find(soft) != std::string::npos) return true;
  return false;
}

std::vector<intptr_t> GlContext::cl_sharing_properties() const {
  glfwMakeContextCurrent(window_);
  std::vector<intptr_t> props;
  if (egl_) {
    EGLContext ctx = eglGetCurrentContext();
    EGLDisplay dpy = eglGetCurrentDisplay();
    if (ctx == EGL_NO_CONTEXT || dpy == EGL_NO_DISPLAY) return {};
    props = {CL_GL_CONTEXT_KHR, reinterpret_cast<intptr_t>(ctx), CL_EGL_DISPLAY_KHR, reinterpret_cast<intptr_t>(dpy)};
  } else {
    GLXContext ctx = glXGetCurrentContext();
    Display* dpy = glXGetCurrentDisplay();
    if (!ctx || !dpy) return {};
    props = {CL_GL_CONTEXT_KHR, reinterpret_cast<intptr_t>(ctx), CL_GLX_DISPLAY_KHR, reinterpret_cast<intptr_t>(dpy)};
  }
  props.push_back(0);
  return props;
}

std::vector<std::string> GlContext::take_messages() {
  std::vector<std::string> out;
  out.swap(g_gl_messages);
  GLenum e;
  while ((e = glGetError()) != GL_NO_ERROR) out.push_back("glGetError " + std::to_string(e));
  return out;
}

}  // namespace boreas::interop
