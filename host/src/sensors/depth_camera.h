// boreas: a pinhole depth camera (boreas_world_capture_depth): one ray per pixel, and from
// the hits the depth along the optical axis and a label per pixel.
#pragma once

#include <vector>

#include "boreas/boreas.h"
#include "sensors/lidar.h"
#include "pose.h"

namespace boreas::impl {

struct DepthCamera {
  int width = 0, height = 0;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;  // pixels
  double max_depth = 0.0;                         // m
  Pose pose;
};

boreas_depth_camera_def default_depth_camera_def();
// Every field checked (errors name it) before anything is cast.
DepthCamera checked_depth_camera_def(const boreas_depth_camera_def& def);

// Pixel (u, v)'s ray direction in the camera's axes, ((u - cx) / fx, -(v - cy) / fy, -1):
// its depth along the optical axis is its distance divided by this vector's length.
Vec3d pixel_direction(const DepthCamera& camera, int u, int v);

// Row by row from the top: the ray through each pixel, up to max_depth along the axis.
std::vector<boreas_ray> depth_rays(const DepthCamera& camera);

// Casts the image's rays and writes depth and labels (either may be NULL) only once every
// ray has been cast.
void capture_depth(const DepthCamera& camera, const RayCaster& caster, float* depth,
                   boreas_pixel_label* labels);

}  // namespace boreas::impl
