// boreas command: `--view lidar`: a LiDAR's latest sweep drawn over the 3D view's frame,
// each point projected through the frame's camera and colored by the surface it hit, so
// a person sees at a glance that the scan moves with the trees. Drawn on the CPU into
// the frame after the renderer read it back; the points are not hidden by what stands
// before them (the scan is the subject).
#pragma once

#include <glm/mat4x4.hpp>
#include <vector>

#include "boreas/boreas.h"
#include "image/image.h"

namespace boreas::render {

// The color of a point by the LiDAR surface its hit kind falls under (boreas_lidar_surface:
// bark orange, leaf cyan, grass yellow, ground magenta, solid white): chosen to stand out
// from the greens and browns of the rendered scene.
Rgb lidar_surface_color(int hit_kind);

// Draws each point in front of the camera as a small square (2 pixels across, 3 above
// 640 pixels wide); returns how many fell inside the image.
int draw_lidar_points(Image& image, const std::vector<boreas_lidar_point>& points,
                      const glm::mat4& view_proj);

// A key of the five colors in the image's top-left corner.
void draw_lidar_legend(Image& image);

}  // namespace boreas::render
