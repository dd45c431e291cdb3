// boreas: the depth camera (depth_camera.h).
#include "sensors/depth_camera.h"

#include <cmath>
#include <string>

#include "errors.h"
#include "sensors/lidar_params.h"
#include "validation.h"

namespace boreas::impl {

boreas_depth_camera_def default_depth_camera_def() {
  boreas_depth_camera_def d{};
  d.width = 640;
  d.height = 480;
  d.fx = d.fy = 525.0f;  // a Kinect-class camera: about 63 degrees across
  d.cx = 319.5f;
  d.cy = 239.5f;
  d.max_depth = 100.0f;
  d.pose = default_pose();
  return d;
}

DepthCamera checked_depth_camera_def(const boreas_depth_camera_def& def) {
  DepthCamera c;
  if (def.width < 1) fail_argument("width must be >= 1 (got " + std::to_string(def.width) + ")");
  if (def.height < 1) fail_argument("height must be >= 1 (got " + std::to_string(def.height) + ")");
  static_assert(BOREAS_DEPTH_CAMERA_MAX_PIXELS == 1 << 24, "the message spells it 2^24");
  if (int64_t(def.width) * def.height > BOREAS_DEPTH_CAMERA_MAX_PIXELS)
    fail_argument("width * height must be at most 2^24 pixels (got " + std::to_string(def.width) +
                  " * " + std::to_string(def.height) + ")");
  check_range(def.fx, 1e-3, 1e7, "fx (pixels)");
  check_range(def.fy, 1e-3, 1e7, "fy (pixels)");
  check_range(def.cx, -1e7, 1e7, "cx (pixels)");
  check_range(def.cy, -1e7, 1e7, "cy (pixels)");
  check_range(def.max_depth, 1e-3, 1e5, "max_depth (m)");
  c.width = def.width;
  c.height = def.height;
  c.fx = def.fx;
  c.fy = def.fy;
  c.cx = def.cx;
  c.cy = def.cy;
  c.max_depth = def.max_depth;
  c.pose = checked_pose(def.pose, "pose");
  return c;
}

Vec3d pixel_direction(const DepthCamera& camera, int u, int v) {
  return {(u - camera.cx) / camera.fx, -(v - camera.cy) / camera.fy, -1.0};
}

std::vector<boreas_ray> depth_rays(const DepthCamera& camera) {
  std::vector<boreas_ray> rays(size_t(camera.width) * size_t(camera.height));
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const Vec3d local = pixel_direction(camera, u, v);
      const double length =
          std::sqrt(local[0] * local[0] + local[1] * local[1] + local[2] * local[2]);
      const Vec3d d = camera.pose.turn(local);
      boreas_ray& r = rays[size_t(v) * size_t(camera.width) + size_t(u)];
      for (size_t a = 0; a < 3; ++a) {
        r.origin[a] = float(camera.pose.position[a]);
        r.direction[a] = float(d[a] / length);
      }
      r.max_distance = float(camera.max_depth * length);
    }
  }
  return rays;
}

void capture_depth(const DepthCamera& camera, const RayCaster& caster, float* depth,
                   boreas_pixel_label* labels) {
  const std::vector<boreas_ray> rays = depth_rays(camera);
  std::vector<boreas_hit> hits(rays.size());
  caster(rays.data(), int(rays.size()), hits.data());
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      const size_t i = size_t(v) * size_t(camera.width) + size_t(u);
      const boreas_hit& h = hits[i];
      const bool hit = h.kind != BOREAS_HIT_NONE;
      if (depth) {
        const Vec3d local = pixel_direction(camera, u, v);
        const double length =
            std::sqrt(local[0] * local[0] + local[1] * local[1] + local[2] * local[2]);
        depth[i] = hit ? float(double(h.distance) / length) : INFINITY;
      }
      if (labels) {
        labels[i].kind = hit ? h.kind : BOREAS_HIT_NONE;
        labels[i].object = hit ? h.object : boreas_object_id{0, 0, 0};
        labels[i].part = hit ? h.part : -1;
      }
    }
  }
}

}  // namespace boreas::impl
