// boreas textures: tangent-space normal maps from height fields by finite differences.
#pragma once

#include <vector>

namespace boreas::render {

// What lies beyond the edge of a height field: the field repeats (tiling textures such as
// bark), or nothing does and the edge texels use one-sided differences (the leaf).
enum class HeightEdges { kClamp, kWrap };

// Unit normals (x, y, z per texel, row 0 first) of the surface z = height(x, y), with x along
// the rows (u) and y along the columns (v), both in the same length unit as height:
//   n = normalize(-dh/dx, -dh/dy, 1),
// dh/dx by central differences (one-sided at clamped edges, so a linear ramp gives its exact
// slope everywhere). texel_x and texel_y are the texel's size in that unit.
std::vector<float> normals_from_height(const std::vector<double>& height, int width,
                                       int height_texels, double texel_x, double texel_y,
                                       HeightEdges edges);

}  // namespace boreas::render
