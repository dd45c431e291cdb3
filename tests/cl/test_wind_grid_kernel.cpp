// boreas tests: the force-field grid kernel against the double-precision reference of
// the same scheme (host/src/reference), with waves, every primitive kind and obstacles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "reference/wind_reference.h"
#include "support/test_support.h"

namespace boreas::test {
namespace {

TEST(WindGridKernel, MatchesDoubleReferenceOverManySteps) {
  boreas_grid_def g = boreas_default_grid_def();
  g.origin[0] = -12.0f;
  g.origin[1] = 0.0f;
  g.origin[2] = -10.0f;
  g.cell_size = 1.5f;
  g.resolution[0] = 16;
  g.resolution[1] = 6;
  g.resolution[2] = 14;
  g.diffusion = 0.3f;
  g.decay_rate = 0.1f;
  g.response_time = 0.4f;
  auto world = make_world(&g);
  boreas_wave waves[2] = {steady_wave(1, 0.2f, 2.0f), boreas_default_wave()};
  world->wind().set_waves(waves, 2, 0.0f, world->time());

  boreas_flow_primitive_def vortex = boreas_default_flow_primitive_def();
  vortex.type = BOREAS_FLOW_VORTEX;
  vortex.position[0] = 2.0f;
  vortex.position[1] = 3.0f;
  vortex.direction[0] = 0.0f;
  vortex.direction[1] = 1.0f;
  vortex.strength = 4.0f;
  vortex.radius = 8.0f;
  boreas_flow_primitive_def source = vortex;
  source.type = BOREAS_FLOW_SOURCE;
  source.position[0] = -6.0f;
  source.strength = 2.0f;
  boreas_flow_primitive_def uniform = boreas_default_flow_primitive_def();
  uniform.direction[0] = 0.0f;
  uniform.direction[2] = 1.0f;
  uniform.strength = 1.5f;
  uniform.radius = 6.0f;
  uniform.position[2] = 5.0f;
  world->wind().add_primitive(vortex, world->time());
  world->wind().add_primitive(source, world->time());
  world->wind().add_primitive(uniform, world->time());
  float lo[3] = {-3.0f, 0.0f, -3.0f}, hi[3] = {0.0f, 4.0f, 0.0f};
  world->wind().add_solid_box(lo, hi);

  impl::reference::Grid ref;
  ref.g = world->wind().grid().gpu();
  std::vector<float> initial = world->wind().grid().read();
  ref.cells.resize(initial.size() / 4);
  for (size_t i = 0; i < ref.cells.size(); ++i)
    ref.cells[i] = {initial[4 * i], initial[4 * i + 1], initial[4 * i + 2], initial[4 * i + 3]};

  const float dts[] = {0.05f, 0.2f, 1.0f};
  double worst = 0.0, scale = 0.0;
  for (int s = 0; s < 30; ++s) {
    float dt = dts[s % 3];
    world->step(dt);
    double t = world->time();
    std::vector<BoreasGpuForcing> forcing;
    {
      // The same forcing list the world gave the device (no lifetimes, no gusts here).
      impl::FlowField f(impl::claim_world_serial());
      f.add_primitive(impl::checked_primitive(vortex, "v"), 0);
      f.add_primitive(impl::checked_primitive(source, "s"), 0);
      f.add_primitive(impl::checked_primitive(uniform, "u"), 0);
      forcing = f.forcing(t);
    }
    impl::reference::grid_step(
        ref, world->wind().grid().def(), dt,
        [&](double x, double z) {
          return impl::reference::sine_sum(world->wind().wave_layers(), x, z, t);
        },
        forcing);
    std::vector<float> dev = world->wind().grid().read();
    for (size_t i = 0; i < ref.cells.size(); ++i)
      for (int a = 0; a < 4; ++a) {
        worst = std::max(worst, std::fabs(dev[4 * i + a] - ref.cells[i][a]));
        scale = std::max(scale, std::fabs(ref.cells[i][a]));
      }
  }
  RecordProperty("max_abs_error", testing::PrintToString(worst));
  EXPECT_GT(scale, 1.0) << "the scene must actually drive the grid";
  EXPECT_LT(worst, 2e-4 * scale);
}

}  // namespace
}  // namespace boreas::test
