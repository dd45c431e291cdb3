// boreas interop: one buffer written by OpenCL kernels and drawn by OpenGL (strategy.h).
// A frame, for all of a renderer's shared buffers:
//   begin_write()   before anything is enqueued that writes the CL buffer
//   ... enqueue the writes on `queue` (boreas_tree_enqueue_branch_records, ...)
//   end_write()     after them: once it returns, GL commands issued next see the data
//   ... GL draws reading gl()
//   end_draw()      after the last GL command that reads it this frame
// The GL context must be current on the calling thread throughout.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <vector>

#include <CL/cl.h>

#include "strategy.h"

namespace boreas::interop {

struct SharedBufferError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class SharedBuffer {
 public:
  // A buffer of `bytes` in the CL context (its queue: the world's), made for `strategy`.
  // gl_sharing needs a context made from the current GL context. Throws SharedBufferError
  // naming the strategy and the OpenCL or OpenGL failure.
  SharedBuffer(Strategy strategy, cl_context context, cl_command_queue queue, size_t bytes);
  ~SharedBuffer();
  SharedBuffer(const SharedBuffer&) = delete;
  SharedBuffer& operator=(const SharedBuffer&) = delete;

  Strategy strategy() const { return strategy_; }
  size_t bytes() const { return bytes_; }
  unsigned gl() const { return gl_; }   // the GL buffer name
  cl_mem cl() const { return cl_; }     // what the kernels write

  // zero_copy: whether OpenCL's map of the buffer is GL's mapping itself (true on PoCL),
  // so that no copy is made anywhere; false for the other strategies.
  bool maps_in_place() const { return cl_mapped_ != nullptr && cl_mapped_ == mapped_; }

  void begin_write();
  void end_write();
  void end_draw();

 private:
  void release() noexcept;

  Strategy strategy_;
  cl_context context_;
  cl_command_queue queue_;
  size_t bytes_;
  unsigned gl_ = 0;
  cl_mem cl_ = nullptr;
  void* mapped_ = nullptr;           // zero_copy: GL's persistent mapping
  void* cl_mapped_ = nullptr;        // zero_copy: CL's map while GL may read
  void* fence_ = nullptr;            // zero_copy: GLsync after the last draw that read it
  std::vector<unsigned char> staging_;  // copy
};

}  // namespace boreas::interop
