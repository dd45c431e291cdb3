// boreas: the sine-sum wave sets sounding now, and their blend weights.
// A new set fades in over the blend time while everything sounding fades out from the
// strength it had (smoothstep in time), so the wind never jumps (Skjermo sec. 6 proposes
// blending a set out before a new one comes in; overlapping the two keeps the wind alive
// during the change). At most two layers: the fading one and the new one.
#pragma once

#include <vector>

#include "shared/wind_types.h"
#include "wind/wind_params.h"

namespace boreas::impl {

class WaveLayers {
 public:
  struct Layer {
    std::vector<WaveParams> waves;
    double weight_from = 1.0;
    double weight_to = 1.0;
    double start = 0.0;     // s
    double duration = 0.0;  // s; 0 = at weight_to from start on
  };

  // Replaces the set at time now; blend_seconds >= 0 (checked by the caller).
  void set(std::vector<WaveParams> waves, double blend_seconds, double now);

  // Drops layers that have faded out by time t.
  void prune(double t);

  // Every wave with its weight folded into the amplitude and its phase at time t reduced
  // modulo 2 pi in double, as the kernels read them. Waves of zero weight are left out.
  std::vector<BoreasGpuWave> gpu_waves(double t) const;

  static double weight(const Layer& layer, double t);
  const std::vector<Layer>& layers() const { return layers_; }

 private:
  std::vector<Layer> layers_;
};

}  // namespace boreas::impl
