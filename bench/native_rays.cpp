// boreas: the native twin of the ray cast (native_rays.h). Built as the other twins are
// (bench/CMakeLists.txt) but without -ffinite-math-only: the traversal relies on infinities
// (a direction's reciprocal, a miss's distance). No SIMD: each ray branches on what it
// meets, as each work-item of the kernel does (cl/shared/ray_math.h).
#include "native_rays.h"

#include <cstdint>

#include "rays/host_scene.h"

namespace boreas::bench {

namespace {

// One ray, everything inlined into it ([[gnu::flatten]]): ray_cast.h's C++ build declares
// its functions plain `static inline`, and GCC leaves the larger ones (a branch, a leaf,
// the attachment frame) as calls that pass their curves and frames through memory, where
// PoCL inlines every one (BOREAS_FN is always_inline in OpenCL C).
[[gnu::flatten]] void cast_one(const BoreasRayScene* s, const boreas_ray* ray, boreas_hit* hit) {
  boreas_ray_cast_record(s, reinterpret_cast<const float*>(ray), reinterpret_cast<float*>(hit),
                         reinterpret_cast<int*>(hit));
}

}  // namespace

void native_ray_cast(const impl::RayScene::HostCopy& c, const boreas_ray* rays, int count,
                     boreas_hit* hits) {
  const BoreasRayScene s = impl::host_scene(c);
  static_assert(sizeof(boreas_ray) == BOREAS_RAY_RAY_FLOATS * sizeof(float), "ray record");
  static_assert(sizeof(boreas_hit) == BOREAS_RAY_HIT_WORDS * sizeof(float), "hit record");
  // Dynamic: rays differ by orders of magnitude in cost (a miss above the crown against
  // one through it).
#pragma omp parallel for schedule(dynamic, 64)
  for (int i = 0; i < count; ++i) cast_one(&s, &rays[i], &hits[i]);
}

}  // namespace boreas::bench
