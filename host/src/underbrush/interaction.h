// boreas: what pushes underbrush besides the wind and the colliders (colliders/): impulse
// emitters (rain drops, footsteps).
#pragma once

#include <cstdint>
#include <vector>

#include "boreas/boreas.h"
#include "shared/underbrush_types.h"

namespace boreas::impl {

// An emitter's events follow a fixed schedule: event k (0, 1, ...) happens at start +
// (k + 1/2) / rate, at a point drawn from its own random stream (seed, k), so where and
// when drops fall does not depend on how time is cut into steps.
struct Emitter {
  boreas_emitter_def def{};
  double start = 0.0;   // s, world time when added
  uint64_t fired = 0;   // events delivered so far

  // The impulses of the events in (t0, t1]; advances `fired`.
  std::vector<BoreasGpuImpulse> events(double t0, double t1);
  // Whether it is done at time t (lifetime over, or its single event delivered).
  bool expired(double t) const;
};

boreas_emitter_def checked_emitter_def(const boreas_emitter_def& def);

}  // namespace boreas::impl
