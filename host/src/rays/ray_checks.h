// boreas: the checks of rays passed in (boreas_world_cast_rays): every ray checked before
// anything is cast, errors naming the ray's index and field.
#pragma once

#include "boreas/boreas.h"
#include "rays/ray_reach.h"
#include "runtime/runtime.h"

namespace boreas::impl {

// Throws Error(INVALID_ARGUMENT) for a NULL array with count > 0, count < 0, or a ray whose
// origin is not finite, whose direction is zero or not finite, or whose max_distance is
// negative or NaN. Returns what the rays reach (rays/ray_reach.h: their box, infinite
// sides where a ray is unbounded, and cones over runs of them): what the ray structure must
// cover.
RayReach checked_rays(const boreas_ray* rays, int count, const boreas_hit* hits);

// The same for rays in a device buffer (boreas_world_enqueue_cast_rays): count checked, the
// buffers' sizes checked, the rays checked on the device (one small read back: the first
// bad ray and the box they reach: no cones, the rays stay on the device).
RayReach checked_device_rays(Runtime& runtime, const cl::Buffer& rays, size_t first_ray, int count,
                        const cl::Buffer& hits, size_t first_hit);

}  // namespace boreas::impl
