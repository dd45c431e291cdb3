// boreas: validation of the wind's public parameters.
#include "wind/wind_params.h"

#include <cmath>

#include "enum_as_int.h"
#include "errors.h"
#include "validation.h"

namespace boreas::impl {

namespace {

void require(bool ok, const std::string& what, const std::string& rule, double got) {
  if (!ok) fail_argument(what + " must be " + rule + " (got " + num(got) + ")");
}

// Normalizes a 3-vector in place; throws for non-finite or zero.
void normalize3(float v[3], const std::string& what) {
  for (int i = 0; i < 3; ++i) check_finite(v[i], what + "[" + std::to_string(i) + "]");
  double len = std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]);
  if (!(len > 1e-12)) fail_argument(what + " must not be the zero vector");
  for (int i = 0; i < 3; ++i) v[i] = static_cast<float>(v[i] / len);
}

}  // namespace

double WaveParams::wavenumber() const { return 2.0 * M_PI / wavelength; }
double WaveParams::phase_rate() const { return -speed * wavenumber(); }

WaveParams checked_wave(const boreas_wave& w, const std::string& where) {
  check_finite(w.direction[0], where + ".direction[0]");
  check_finite(w.direction[1], where + ".direction[1]");
  check_finite(w.amplitude, where + ".amplitude");
  check_finite(w.wavelength, where + ".wavelength");
  check_finite(w.speed, where + ".speed");
  check_finite(w.sharpness, where + ".sharpness");
  double len = std::hypot(double(w.direction[0]), double(w.direction[1]));
  if (!(len > 1e-12)) fail_argument(where + ".direction must not be the zero vector");
  require(w.amplitude >= 0 && w.amplitude <= BOREAS_WIND_MAX_SPEED, where + ".amplitude",
          "in [0, " + num(BOREAS_WIND_MAX_SPEED) + "] m/s", w.amplitude);
  require(w.wavelength > 0 && w.wavelength <= 1e7, where + ".wavelength", "in (0, 1e7] m",
          w.wavelength);
  require(std::fabs(w.speed) <= BOREAS_WIND_MAX_SPEED, where + ".speed",
          "in [-" + num(BOREAS_WIND_MAX_SPEED) + ", " + num(BOREAS_WIND_MAX_SPEED) + "] m/s",
          w.speed);
  require(w.sharpness >= 0 && w.sharpness <= 64, where + ".sharpness", "in [0, 64]", w.sharpness);
  WaveParams p;
  p.dir_x = w.direction[0] / len;
  p.dir_z = w.direction[1] / len;
  p.amplitude = w.amplitude;
  p.wavelength = w.wavelength;
  p.speed = w.speed;
  p.sharpness = w.sharpness;
  return p;
}

boreas_flow_primitive_def checked_primitive(const boreas_flow_primitive_def& in,
                                            const std::string& where) {
  boreas_flow_primitive_def p = in;
  const int type = enum_as_int(p.type);
  if (type < BOREAS_FLOW_UNIFORM || type > BOREAS_FLOW_VORTEX)
    fail_argument(where + ".type must be one of BOREAS_FLOW_UNIFORM, _SOURCE, _SINK, _VORTEX (got " +
                  std::to_string(type) + ")");
  for (int i = 0; i < 3; ++i) check_finite(p.position[i], where + ".position[" + std::to_string(i) + "]");
  check_finite(p.strength, where + ".strength");
  check_finite(p.radius, where + ".radius");
  check_finite(p.lifetime, where + ".lifetime");
  require(std::fabs(p.strength) <= BOREAS_WIND_MAX_SPEED, where + ".strength",
          "within +-" + num(BOREAS_WIND_MAX_SPEED) + " m/s", p.strength);
  require(p.radius >= 0, where + ".radius", ">= 0 m", p.radius);
  require(p.lifetime >= 0, where + ".lifetime", ">= 0 s", p.lifetime);
  if (p.type != BOREAS_FLOW_UNIFORM)
    require(p.radius > 0, where + ".radius", "> 0 m for sources, sinks and vortices", p.radius);
  if (p.type == BOREAS_FLOW_UNIFORM || p.type == BOREAS_FLOW_VORTEX) {
    normalize3(p.direction, where + ".direction");
  } else {
    p.direction[0] = 0.0f;
    p.direction[1] = 1.0f;
    p.direction[2] = 0.0f;
  }
  return p;
}

boreas_gust_def checked_gust(const boreas_gust_def& in, const std::string& where) {
  boreas_gust_def g = in;
  normalize3(g.direction, where + ".direction");
  for (int i = 0; i < 3; ++i) check_finite(g.center[i], where + ".center[" + std::to_string(i) + "]");
  const std::pair<const char*, float> times[] = {
      {"delay", g.delay}, {"rise", g.rise}, {"hold", g.hold}, {"fall", g.fall}, {"radius", g.radius}};
  for (const auto& [name, v] : times) {
    check_finite(v, where + "." + name);
    require(v >= 0, where + "." + name, ">= 0", v);
  }
  check_finite(g.strength, where + ".strength");
  require(std::fabs(g.strength) <= BOREAS_WIND_MAX_SPEED, where + ".strength",
          "within +-" + num(BOREAS_WIND_MAX_SPEED) + " m/s", g.strength);
  return g;
}

boreas_grid_def checked_grid(const boreas_grid_def& g, const std::string& where) {
  for (int i = 0; i < 3; ++i) check_finite(g.origin[i], where + ".origin[" + std::to_string(i) + "]");
  check_finite(g.cell_size, where + ".cell_size");
  check_finite(g.diffusion, where + ".diffusion");
  check_finite(g.decay_rate, where + ".decay_rate");
  check_finite(g.response_time, where + ".response_time");
  // Lower bounds keep dt / cell_size and dt / response_time finite in float for every
  // accepted dt; the extent bound keeps the padding primitives (at 1e18 m) out of reach.
  require(g.cell_size >= 1e-3f && g.cell_size <= 1e4f, where + ".cell_size", "in [1e-3, 1e4] m",
          g.cell_size);
  static_assert(BOREAS_WORLD_MAX_COORDINATE == 1e7 && BOREAS_GRID_MAX_CELLS == 1 << 26,
                "the messages below spell the limits 1e7 and 2^26");
  for (int i = 0; i < 3; ++i)
    require(std::fabs(g.origin[i]) <= BOREAS_WORLD_MAX_COORDINATE,
            where + ".origin[" + std::to_string(i) + "]", "within +-1e7 m", g.origin[i]);
  long long cells = 1;
  for (int i = 0; i < 3; ++i) {
    require(g.resolution[i] >= 2 && g.resolution[i] <= BOREAS_GRID_MAX_RESOLUTION,
            where + ".resolution[" + std::to_string(i) + "]",
            "in [2, " + std::to_string(BOREAS_GRID_MAX_RESOLUTION) + "]", g.resolution[i]);
    cells *= g.resolution[i];
  }
  require(cells <= BOREAS_GRID_MAX_CELLS, where + ".resolution", "at most 2^26 cells in all",
          double(cells));
  require(g.diffusion >= 0 && g.diffusion <= 1e6, where + ".diffusion", "in [0, 1e6] m^2/s",
          g.diffusion);
  require(g.decay_rate >= 0 && g.decay_rate <= 1e6, where + ".decay_rate", "in [0, 1e6] 1/s",
          g.decay_rate);
  require(g.response_time >= 1e-4f && g.response_time <= 1e6f, where + ".response_time",
          "in [1e-4, 1e6] s", g.response_time);
  check_finite(g.edge_fade, where + ".edge_fade");
  require(g.edge_fade >= 0 && g.edge_fade <= 1e6, where + ".edge_fade", "in [0, 1e6] cells",
          g.edge_fade);
  require(g.follow_focus == 0 || g.follow_focus == 1, where + ".follow_focus", "0 or 1",
          g.follow_focus);
  const int sampling = enum_as_int(g.wind_sampling);
  require(sampling == BOREAS_WIND_SAMPLING_EXACT || sampling == BOREAS_WIND_SAMPLING_INTERPOLATED,
          where + ".wind_sampling",
          "BOREAS_WIND_SAMPLING_EXACT (0) or BOREAS_WIND_SAMPLING_INTERPOLATED (1)", sampling);
  return g;
}

std::vector<WaveParams> checked_waves(const boreas_wave* waves, int count, const char* where,
                                      const char* count_name) {
  if (count < 0)
    fail_argument(std::string(count_name) + " must be >= 0 (got " + std::to_string(count) + ")");
  if (count > BOREAS_WIND_MAX_WAVES)
    fail_argument(std::string(count_name) + " must be <= " + std::to_string(BOREAS_WIND_MAX_WAVES) +
                  " (got " + std::to_string(count) + ")");
  if (count > 0 && waves == nullptr)
    fail_argument(std::string(where) + " is NULL with " + count_name + " " + std::to_string(count));
  std::vector<WaveParams> out;
  out.reserve(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i)
    out.push_back(checked_wave(waves[i], std::string(where) + "[" + std::to_string(i) + "]"));
  return out;
}

}  // namespace boreas::impl
