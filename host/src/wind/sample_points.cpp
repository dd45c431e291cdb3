// boreas: sampling the wind at the caller's points.
#include "wind/sample_points.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "runtime/launch.h"

namespace boreas::impl {

namespace {

void check_points(const float* xyz, int count, const float* force_xyz) {
  if (count < 0) fail_argument("count must be >= 0 (got " + std::to_string(count) + ")");
  if (count > BOREAS_WIND_SAMPLE_MAX_POINTS)
    fail_argument("count must be <= " + std::to_string(BOREAS_WIND_SAMPLE_MAX_POINTS) +
                  " per call (got " + std::to_string(count) + "); split the batch");
  if (count == 0) return;
  if (!xyz || !force_xyz) fail_argument("xyz or force_xyz is NULL");
  for (int i = 0; i < 3 * count; ++i) {
    if (!std::isfinite(xyz[i]))
      fail_argument("xyz[" + std::to_string(i) + "] (point " + std::to_string(i / 3) +
                    ") must be finite (got " + std::to_string(xyz[i]) + ")");
  }
}

}  // namespace

void SamplePoints::sample(const PlantWind& wind, const float* xyz, int count, float* force_xyz) {
  check_points(xyz, count, force_xyz);
  if (count == 0) return;
  const size_t n = static_cast<size_t>(count);
  const size_t bytes = n * 3 * sizeof(float);
  if (n > capacity_) {
    // Both allocated before either is replaced: a refused allocation keeps the old pair.
    const size_t capacity = std::max<size_t>(n, 1024);
    cl::Buffer points =
        runtime_.buffer(CL_MEM_READ_ONLY, capacity * 3 * sizeof(float), "sample points");
    cl::Buffer results =
        runtime_.buffer(CL_MEM_WRITE_ONLY, capacity * 3 * sizeof(float), "sample results");
    points_ = std::move(points);
    results_ = std::move(results);
    capacity_ = capacity;
  }
  // The kernel reads and writes planes (x..., y..., z...), relative to the grid's corner,
  // with the waves' phases there: see wind_sample_points.cl.
  const double corner[3] = {wind.grid_layout.origin_x, wind.grid_layout.origin_y,
                            wind.grid_layout.origin_z};
  planar_.resize(3 * n);
  for (size_t i = 0; i < n; ++i)
    for (size_t a = 0; a < 3; ++a) planar_[a * n + i] = float(double(xyz[3 * i + a]) - corner[a]);
  phases_host_.assign(size_t(std::max(wind.wave_count, 1)), 0.0f);
  wind.phases_at(corner[0], corner[2], phases_host_.data());
  if (phases_host_.size() > phase_capacity_ || phases_() == nullptr) {
    const size_t capacity = std::max<size_t>(phases_host_.size(), 16);
    phases_ = runtime_.buffer(CL_MEM_READ_ONLY, capacity * sizeof(float), "sample phases");
    phase_capacity_ = capacity;
  }
  cl::CommandQueue& q = runtime_.queue();
  cl::Kernel& kernel =
      runtime_.kernel("wind_sample_points.cl", "boreas_wind_sample_points", wind.defines());
  BOREAS_CL_CHECK(q.enqueueWriteBuffer(points_, CL_TRUE, 0, bytes, planar_.data()));
  BOREAS_CL_CHECK(q.enqueueWriteBuffer(phases_, CL_TRUE, 0, phases_host_.size() * sizeof(float),
                                       phases_host_.data()));
  launch(runtime_, kernel, Items(n).per_work_item(size_t(runtime_.simd_width())), points_, results_,
         count, *wind.waves, wind.wave_count, phases_, *wind.grid, wind.grid_layout);
  BOREAS_CL_CHECK(q.enqueueReadBuffer(results_, CL_TRUE, 0, bytes, planar_.data()));
  for (size_t i = 0; i < n; ++i)
    for (size_t a = 0; a < 3; ++a) force_xyz[3 * i + a] = planar_[a * n + i];
}

}  // namespace boreas::impl
