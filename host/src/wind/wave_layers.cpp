// boreas: wave-set blending.
#include "wind/wave_layers.h"

#include <algorithm>
#include <cmath>

namespace boreas::impl {

namespace {
constexpr size_t kMaxFadingWaves = 4096;  // waves kept fading at once (4 full sets)

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}
}  // namespace

double WaveLayers::weight(const Layer& layer, double t) {
  if (layer.duration <= 0.0) return t >= layer.start ? layer.weight_to : layer.weight_from;
  double s = smoothstep((t - layer.start) / layer.duration);
  return layer.weight_from + (layer.weight_to - layer.weight_from) * s;
}

void WaveLayers::set(std::vector<WaveParams> waves, double blend_seconds, double now) {
  if (blend_seconds <= 0.0) {
    layers_.clear();
  } else {
    // Everything sounding now is folded into one layer at its present strength (weights
    // multiplied into the amplitudes), which fades from there: the wind is continuous, and
    // however often the set changes there are never more than two layers.
    Layer fading;
    fading.weight_from = 1.0;
    fading.weight_to = 0.0;
    fading.start = now;
    fading.duration = blend_seconds;
    for (const Layer& layer : layers_) {
      double w = weight(layer, now);
      if (w <= 0.0) continue;
      for (WaveParams p : layer.waves) {
        p.amplitude *= w;
        fading.waves.push_back(p);
      }
    }
    // A caller changing sets much faster than they fade piles waves up: beyond the bound
    // the weakest go at once (the only case where the wind can step, by their amplitude).
    if (fading.waves.size() > kMaxFadingWaves) {
      std::partial_sort(fading.waves.begin(), fading.waves.begin() + kMaxFadingWaves,
                        fading.waves.end(), [](const WaveParams& a, const WaveParams& b) {
                          return a.amplitude > b.amplitude;
                        });
      fading.waves.resize(kMaxFadingWaves);
    }
    layers_.clear();
    if (!fading.waves.empty()) layers_.push_back(std::move(fading));
  }
  Layer fresh;
  fresh.waves = std::move(waves);
  fresh.weight_from = blend_seconds > 0.0 ? 0.0 : 1.0;
  fresh.weight_to = 1.0;
  fresh.start = now;
  fresh.duration = blend_seconds;
  if (!fresh.waves.empty()) layers_.push_back(std::move(fresh));
}

void WaveLayers::prune(double t) {
  layers_.erase(std::remove_if(layers_.begin(), layers_.end(),
                               [t](const Layer& l) {
                                 return l.weight_to == 0.0 && t >= l.start + l.duration;
                               }),
                layers_.end());
}

std::vector<BoreasGpuWave> WaveLayers::gpu_waves(double t) const {
  std::vector<BoreasGpuWave> out;
  for (const Layer& layer : layers_) {
    double w = weight(layer, t);
    if (w <= 0.0) continue;
    for (const WaveParams& p : layer.waves) {
      BoreasGpuWave g{};
      g.dir_x = static_cast<float>(p.dir_x);
      g.dir_z = static_cast<float>(p.dir_z);
      g.amplitude = static_cast<float>(p.amplitude * w);
      g.cycles_per_meter = static_cast<float>(1.0 / p.wavelength);
      // Skjermo eq. 11 writes + t phi with phi = speed w, which moves crests against D.
      // boreas uses phi = -speed w so a positive speed carries gust fronts downwind, along
      // D, as a user setting a wind direction expects (see WaveParams::phase_rate).
      double cycles = t * p.phase_rate() / (2.0 * M_PI);
      g.phase_cycles = static_cast<float>(cycles - std::floor(cycles));
      g.sharpness = static_cast<float>(p.sharpness);
      out.push_back(g);
    }
  }
  return out;
}

}  // namespace boreas::impl
