// boreas: what the animated glTF's two meadow writers (morph_export.cpp, exact; clump_export.cpp,
// looped clumps) read the same way: World::meadow_vertices' layout, a part's color and a
// strip's triangles.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace boreas::impl {

constexpr size_t kMeadowFloats = 8;  // World::meadow_vertices: position, normal, uv

// A part's color for COLOR_0, which is linear: sRGB decoded.
inline float linear(float srgb) {
  return srgb <= 0.04045f ? srgb / 12.92f : float(std::pow((srgb + 0.055) / 1.055, 2.4));
}

// A strip's triangles, every other one turned back so all face the strip's normal side.
inline void strip_triangles(uint32_t first, uint32_t count, std::vector<uint32_t>* indices) {
  for (uint32_t j = 0; j + 2 < count; ++j) {
    const uint32_t a = first + j, b = first + j + 1, c = first + j + 2;
    if (j % 2 == 0)
      indices->insert(indices->end(), {a, b, c});
    else
      indices->insert(indices->end(), {b, a, c});
  }
}

}  // namespace boreas::impl
