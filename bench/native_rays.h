// boreas: the native twin of the ray cast (cl/ray_cast.cl): the same traversal,
// cl/shared/ray_cast.h compiled as C++, over the same structure read back from the device
// (RayScene::host_copy), OpenMP threads over the rays. The yardstick BM_Rays' native rows
// compare the kernel with.
#pragma once

#include "boreas/boreas.h"
#include "rays/ray_scene.h"

namespace boreas::bench {

// cl/ray_cast.cl for `count` rays: hits[i] the nearest hit of rays[i] (rays already
// checked, as boreas_world_cast_rays checks them).
void native_ray_cast(const impl::RayScene::HostCopy& scene, const boreas_ray* rays, int count,
                     boreas_hit* hits);

}  // namespace boreas::bench
