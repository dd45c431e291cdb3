// boreas: native C++ twins of the underbrush kernels (cl/underbrush_step.cl,
// cl/underbrush_vertices.cl), the yardstick boreas_bench compares them with. They include
// cl/shared/underbrush_math.h with BOREAS_FAST_MATH 1, so the per-component math is the
// kernels' own text, and read and write the planes of cl/shared/underbrush_types.h in the
// layout UnderbrushBatch gives a batch of one meadow (host/src/underbrush/underbrush_batch.h).
// OpenMP threads over blocks of components, SIMD within a block; the wind is
// native_wind_block (bench/native_wind.h).
#pragma once

#include <cstdint>

#include "native_trees.h"
#include "shared/collider_types.h"
#include "shared/underbrush_types.h"

namespace boreas::bench {

// The device planes of a batch, host copies: state (BOREAS_UB_STATE_PLANES), frame
// (BOREAS_UB_FRAME_PLANES) and index (BOREAS_UB_INDEX_PLANES) planes of stride n; part
// records (decay written for the step's dt) whose offsets point into tables.
struct NativeMeadowPlanes {
  const float* frame = nullptr;
  const int32_t* index = nullptr;
  const BoreasGpuPart* parts = nullptr;
  const float* tables = nullptr;
  int n = 0;
};

// cl/underbrush_step.cl over all n components: state_in to state_out (both n-strided
// state planes), dt in s, gravity in m/s^2 along -y, the wind the kernel reads
// (NativeTreeWind is PlantWind's host form, for trees and underbrush alike), colliders
// and impulses unpadded. Same arguments, same result.
void native_underbrush_step(const NativeMeadowPlanes& m, const float* state_in, float* state_out,
                            float dt, float gravity, const NativeTreeWind& wind,
                            const BoreasGpuCollider* colliders, int collider_count,
                            const BoreasGpuImpulse* impulses, int impulse_count);

// cl/underbrush_vertices.cl over all n components: BOREAS_UB_JOINTS * 2 vertices of 8
// floats per component into out, each component's vertex count at its LOD from the camera
// (camera xyz in m, lod the three distances in m) into counts.
void native_underbrush_vertices(const NativeMeadowPlanes& m, const float* state,
                                const float camera[3], const float lod[3], float* out,
                                int32_t* counts);

}  // namespace boreas::bench
