// boreas: the waves' device copy.
#include "wind/wave_buffer.h"

#include <algorithm>
#include <vector>

#include "runtime/kernel_defines.h"

namespace boreas::impl {

void WaveBuffer::upload(const WaveLayers& layers, double t) {
  std::vector<BoreasGpuWave> gpu = layers.gpu_waves(t);
  // Padded with silent waves (amplitude 0) up to the kernels' unrolled slot count.
  const int slots = pad_to_slots(gpu, BoreasGpuWave{});
  if (gpu.size() > capacity_ || buffer_() == nullptr) {
    // Allocated before anything is replaced: a refused allocation keeps the old buffer.
    const size_t capacity = std::max<size_t>(gpu.size(), 16);
    cl::Buffer bigger =
        runtime_.buffer(CL_MEM_READ_ONLY, capacity * sizeof(BoreasGpuWave), "wave buffer");
    buffer_ = std::move(bigger);
    capacity_ = capacity;
  }
  if (!gpu.empty()) {
    BOREAS_CL_CHECK(runtime_.queue().enqueueWriteBuffer(
        buffer_, CL_TRUE, 0, gpu.size() * sizeof(BoreasGpuWave), gpu.data()));
  }
  count_ = static_cast<int>(gpu.size());
  slots_ = slots;
  host_ = std::move(gpu);
}

}  // namespace boreas::impl
