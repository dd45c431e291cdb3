// boreas interop: the three ways a kernel's output reaches a GL buffer (shared_buffer.h).
#include "shared_buffer.h"

#include <epoxy/gl.h>

#include <CL/cl_gl.h>

#include <string>

namespace boreas::interop {
namespace {

[[noreturn]] void fail(Strategy s, const std::string& what) {
  throw SharedBufferError(std::string("interop (") + strategy_name(s) + "): " + what);
}

void check_cl(Strategy s, cl_int err, const char* call) {
  if (err != CL_SUCCESS) fail(s, std::string(call) + " failed with OpenCL error " + std::to_string(err));
}

constexpr GLbitfield kPersistent = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;

}  // namespace

SharedBuffer::SharedBuffer(Strategy strategy, cl_context context, cl_command_queue queue, size_t bytes)
    : strategy_(strategy), context_(context), queue_(queue), bytes_(bytes == 0 ? 4 : bytes) {
  glCreateBuffers(1, &gl_);
  if (gl_ == 0) fail(strategy_, "glCreateBuffers gave no buffer (is a GL context current?)");
  cl_int err = CL_SUCCESS;
  try {
    switch (strategy_) {
      case Strategy::copy:
        glNamedBufferStorage(gl_, GLsizeiptr(bytes_), nullptr, GL_DYNAMIC_STORAGE_BIT);
        cl_ = clCreateBuffer(context_, CL_MEM_READ_WRITE, bytes_, nullptr, &err);
        check_cl(strategy_, err, "clCreateBuffer");
        staging_.resize(bytes_);
        break;
      case Strategy::zero_copy:
        glNamedBufferStorage(gl_, GLsizeiptr(bytes_), nullptr, kPersistent);
        mapped_ = glMapNamedBufferRange(gl_, 0, GLsizeiptr(bytes_), kPersistent);
        if (!mapped_) fail(strategy_, "glMapNamedBufferRange (persistent, coherent) failed");
        cl_ = clCreateBuffer(context_, CL_MEM_READ_WRITE | CL_MEM_USE_HOST_PTR, bytes_, mapped_, &err);
        check_cl(strategy_, err, "clCreateBuffer(CL_MEM_USE_HOST_PTR)");
        // Between frames the buffer is mapped for the host, which is when GL reads it.
        cl_mapped_ = clEnqueueMapBuffer(queue_, cl_, CL_TRUE, CL_MAP_READ, 0, bytes_, 0, nullptr, nullptr, &err);
        check_cl(strategy_, err, "clEnqueueMapBuffer");
        break;
      case Strategy::gl_sharing:
        glNamedBufferStorage(gl_, GLsizeiptr(bytes_), nullptr, 0);
        glFinish();
        cl_ = clCreateFromGLBuffer(context_, CL_MEM_READ_WRITE, gl_, &err);
        check_cl(strategy_, err, "clCreateFromGLBuffer (was the world's context made from this GL context?)");
        break;
    }
  } catch (...) {
    release();
    throw;
  }
}

SharedBuffer::~SharedBuffer() { release(); }

void SharedBuffer::release() noexcept {
  if (cl_mapped_) clEnqueueUnmapMemObject(queue_, cl_, cl_mapped_, 0, nullptr, nullptr);
  if (cl_) {
    clFinish(queue_);
    clReleaseMemObject(cl_);
  }
  cl_mapped_ = nullptr;
  cl_ = nullptr;
  if (fence_) glDeleteSync(static_cast<GLsync>(fence_));
  fence_ = nullptr;
  if (mapped_) glUnmapNamedBuffer(gl_);
  mapped_ = nullptr;
  if (gl_) glDeleteBuffers(1, &gl_);
  gl_ = 0;
}

void SharedBuffer::begin_write() {
  cl_int err = CL_SUCCESS;
  switch (strategy_) {
    case Strategy::copy:
      break;
    case Strategy::zero_copy:
      // GL must be done drawing from the memory before the kernels overwrite it.
      if (fence_) {
        GLenum r;
        do r = glClientWaitSync(static_cast<GLsync>(fence_), GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000ull);
        while (r == GL_TIMEOUT_EXPIRED);
        glDeleteSync(static_cast<GLsync>(fence_));
        fence_ = nullptr;
        if (r == GL_WAIT_FAILED) fail(strategy_, "glClientWaitSync failed");
      }
      err = clEnqueueUnmapMemObject(queue_, cl_, cl_mapped_, 0, nullptr, nullptr);
      cl_mapped_ = nullptr;
      check_cl(strategy_, err, "clEnqueueUnmapMemObject");
      break;
    case Strategy::gl_sharing:
      glFinish();  // without cl_khr_gl_event, GL must be done with it before CL acquires it
      check_cl(strategy_, clEnqueueAcquireGLObjects(queue_, 1, &cl_, 0, nullptr, nullptr),
               "clEnqueueAcquireGLObjects");
      break;
  }
}

void SharedBuffer::end_write() {
  cl_int err = CL_SUCCESS;
  switch (strategy_) {
    case Strategy::copy:
      check_cl(strategy_, clEnqueueReadBuffer(queue_, cl_, CL_TRUE, 0, bytes_, staging_.data(), 0, nullptr, nullptr),
               "clEnqueueReadBuffer");
      glNamedBufferSubData(gl_, 0, GLsizeiptr(bytes_), staging_.data());
      break;
    case Strategy::zero_copy:
      // A blocking map waits for the writes and, by the OpenCL rules for USE_HOST_PTR,
      // leaves the data in the host memory, which is GL's (PoCL writes it there directly).
      cl_mapped_ = clEnqueueMapBuffer(queue_, cl_, CL_TRUE, CL_MAP_READ, 0, bytes_, 0, nullptr, nullptr, &err);
      check_cl(strategy_, err, "clEnqueueMapBuffer");
      break;
    case Strategy::gl_sharing:
      check_cl(strategy_, clEnqueueReleaseGLObjects(queue_, 1, &cl_, 0, nullptr, nullptr),
               "clEnqueueReleaseGLObjects");
      check_cl(strategy_, clFinish(queue_), "clFinish");
      break;
  }
}

void SharedBuffer::end_draw() {
  if (strategy_ != Strategy::zero_copy) return;
  if (fence_) glDeleteSync(static_cast<GLsync>(fence_));
  fence_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

}  // namespace boreas::interop
