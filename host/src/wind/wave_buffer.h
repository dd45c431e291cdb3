// boreas: the device copy of the sounding waves, as the kernels read them: every wave of
// the layers at one time (weights folded in, phases reduced), padded with silent waves to
// the kernels' unrolled slot count. Rewritten at every step's time.
#pragma once

#include <cstddef>
#include <vector>

#include "runtime/runtime.h"
#include "wind/wave_layers.h"

namespace boreas::impl {

class WaveBuffer {
 public:
  explicit WaveBuffer(Runtime& runtime) : runtime_(runtime) {}

  // Writes the layers' waves at time t (s), blocking. The buffer grows when it must; a
  // refused allocation keeps the old buffer and its contents.
  void upload(const WaveLayers& layers, double t);

  const cl::Buffer& buffer() const { return buffer_; }
  int count() const { return count_; }  // waves in the buffer, padding included
  int slots() const { return slots_; }  // BOREAS_WAVE_SLOTS of the kernels that read them
  // The host's copy of the buffer (count() waves).
  const std::vector<BoreasGpuWave>& waves() const { return host_; }

 private:
  Runtime& runtime_;
  cl::Buffer buffer_;
  size_t capacity_ = 0;
  int count_ = 0;
  int slots_ = 0;
  std::vector<BoreasGpuWave> host_;
};

}  // namespace boreas::impl
