// boreas: the C API of ray casting (boreas_world_cast_rays), over World::cast_rays.
#include "api/c_api_guard.h"
#include "boreas/boreas.h"

extern "C" {

boreas_status boreas_world_cast_rays(boreas_world world, const boreas_ray* rays, int count,
                                     boreas_hit* hits) {
  return boreas::api::guarded(__func__, [&] {
    boreas::api::world_of(world).cast_rays(rays, count, hits);
  });
}

}  // extern "C"
