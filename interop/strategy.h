// boreas interop: how a buffer the kernels write reaches OpenGL.
//   gl_sharing  cl_khr_gl_sharing: the CL buffer is the GL buffer (clCreateFromGLBuffer);
//               the world's CL context must be made from the GL context. GPU drivers.
//   zero_copy   a GL buffer mapped once, persistently and coherently, backs a CL buffer
//               made with CL_MEM_USE_HOST_PTR: on a CPU device (PoCL) the kernels write the
//               memory GL draws from. Fences keep GL and CL off each other's frames.
//   copy        CL writes its own buffer; the host reads it back and uploads it to GL.
// All three give the same buffer contents (tests/interop).
#pragma once

#include <optional>
#include <string>

namespace boreas::interop {

enum class Strategy { gl_sharing, zero_copy, copy };

const char* strategy_name(Strategy s);
// "gl_sharing", "zero_copy", "copy"; nullopt for anything else.
std::optional<Strategy> parse_strategy(const std::string& name);

// What decides the automatic choice.
struct InteropSupport {
  bool device_is_cpu = false;       // the OpenCL device (PoCL: true)
  bool context_shares_gl = false;   // the world's CL context was made from the GL context
};

// gl_sharing when the context shares GL objects, zero_copy on CPU devices, else copy.
Strategy choose_strategy(const InteropSupport& support);

}  // namespace boreas::interop
