// boreas tests: a meadow's ground into an EmbreeWorld as boreas's rays see it, part for
// part (the agreement tests compare ground hits' triangles).
#pragma once

#include <stdexcept>
#include <vector>

#include "api/c_api_guard.h"
#include "embree_world.h"
#include "rays/ray_scene.h"
#include "underbrush/underbrush_batch.h"
#include "world.h"

namespace boreas::reference {

// A meadow's ground as boreas's rays see it (host/src/rays/ray_scene.cpp, add_ground): its
// height grid's samples, each cell two triangles (i0, i1, i2), (i1, i3, i2), cell (x, z)
// giving triangles 2 (x + (nx - 1) z) and the one after. Read from the meadow's own
// height field (internal: boreas.h has no getter for the ground).
inline void add_ground_grid(boreas_world world, boreas_meadow_id meadow, EmbreeWorld* embree) {
  impl::RaySources sources = api::world_of(world).ray_sources(true);
  const impl::Terrain* ground = nullptr;
  for (const impl::RaySources::Meadow& m : sources.meadows)
    if (boreas_meadow_id_equal(m.id, meadow)) ground = &m.meadow->meadow.terrain;
  if (!ground) throw std::invalid_argument("add_ground_grid: no such meadow");
  const impl::GroundGrid& g = ground->grid;
  std::vector<float> positions;
  for (int z = 0; z < g.nz; ++z)
    for (int x = 0; x < g.nx; ++x)
      positions.insert(positions.end(),
                       {float(g.origin_x + g.size_x * x / (g.nx - 1)),
                        ground->height[size_t(z) * size_t(g.nx) + size_t(x)],
                        float(g.origin_z + g.size_z * z / (g.nz - 1))});
  std::vector<uint32_t> indices;
  for (int z = 0; z + 1 < g.nz; ++z)
    for (int x = 0; x + 1 < g.nx; ++x) {
      const uint32_t i0 = uint32_t(z * g.nx + x), i1 = i0 + 1, i2 = i0 + uint32_t(g.nx),
                     i3 = i2 + 1;
      indices.insert(indices.end(), {i0, i1, i2, i1, i3, i2});
    }
  embree->add_triangles(BOREAS_HIT_GROUND, {meadow.index, meadow.generation, meadow.tag},
                        std::move(positions), std::move(indices));
}

}  // namespace boreas::reference
