// boreas: the C API of the sensors (boreas.h, "Sensors"): LiDARs, their presets and points,
// and depth images. Every entry point catches everything (c_api_guard.h).
#include <string>
#include <vector>

#include "api/c_api_guard.h"
#include "boreas/boreas.h"
#include "enum_as_int.h"
#include "errors.h"
#include "sensors/depth_camera.h"
#include "sensors/lidar_params.h"
#include "sensors/lidar_presets.h"
#include "pose.h"
#include "validation.h"

namespace {

using boreas::api::copy_out;
using boreas::api::guarded;
using boreas::api::world_of;
using boreas::impl::fail_argument;

}  // namespace

extern "C" {

boreas_pose boreas_default_pose(void) { return boreas::impl::default_pose(); }

boreas_status boreas_pose_between(const boreas_pose* a, const boreas_pose* b, float s,
                                  boreas_pose* out) {
  return guarded(__func__, [&] {
    if (!a) fail_argument("a is NULL");
    if (!b) fail_argument("b is NULL");
    if (!out) fail_argument("out is NULL");
    boreas::impl::check_range(s, 0.0, 1.0, "s");
    const boreas::impl::Pose p = boreas::impl::between(boreas::impl::checked_pose(*a, "a"),
                                                       boreas::impl::checked_pose(*b, "b"), s);
    // The origin in between in double and the position from it: as exact as a and b.
    for (int i = 0; i < 3; ++i) {
      out->origin[i] = a->origin[i] + double(s) * (b->origin[i] - a->origin[i]);
      out->position[i] = float(p.position[size_t(i)] - out->origin[i]);
    }
    for (int i = 0; i < 4; ++i) out->orientation[i] = float(p.rotation[size_t(i)]);
  });
}

boreas_lidar_def boreas_default_lidar_def(void) { return boreas::impl::default_lidar_def(); }

boreas_status boreas_lidar_preset(const char* name, boreas_lidar_def* out) {
  return guarded(__func__, [&] {
    if (!name) fail_argument("name is NULL");
    if (!out) fail_argument("out is NULL");
    *out = boreas::impl::lidar_preset(name);
  });
}

const char* boreas_lidar_preset_name(int index) { return boreas::impl::lidar_preset_name(index); }

boreas_status boreas_world_add_lidar(boreas_world world, const boreas_lidar_def* def,
                                     boreas_lidar_id* out) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!def) fail_argument("def is NULL");
    const boreas_lidar_id id = w.add_lidar(*def);
    if (out) *out = id;
  });
}

boreas_status boreas_world_remove_lidar(boreas_world world, boreas_lidar_id lidar) {
  return guarded(__func__, [&] { world_of(world).remove_lidar(lidar); });
}

boreas_status boreas_lidar_set_pose(boreas_world world, boreas_lidar_id lidar,
                                    const boreas_pose* pose) {
  return guarded(__func__, [&] { world_of(world).set_lidar_pose(lidar, pose); });
}

boreas_status boreas_lidar_get_points(boreas_world world, boreas_lidar_id lidar,
                                      boreas_lidar_points which, boreas_lidar_point* out,
                                      int capacity, int* count) {
  return guarded(__func__, [&] {
    const boreas::impl::Lidar& l = world_of(world).lidar(lidar);
    const int w = boreas::impl::enum_as_int(which);
    if (w != BOREAS_LIDAR_LAST_STEP && w != BOREAS_LIDAR_LAST_SWEEP)
      fail_argument("which must be BOREAS_LIDAR_LAST_STEP or BOREAS_LIDAR_LAST_SWEEP (got " +
                    std::to_string(w) + ")");
    copy_out(w == BOREAS_LIDAR_LAST_STEP ? l.last_step() : l.last_sweep(), out, capacity, count);
  });
}

boreas_status boreas_lidar_get_info(boreas_world world, boreas_lidar_id lidar,
                                    boreas_lidar_info* out) {
  return guarded(__func__, [&] {
    const boreas::impl::Lidar& l = world_of(world).lidar(lidar);
    if (!out) fail_argument("out is NULL");
    *out = l.info();
  });
}

boreas_depth_camera_def boreas_default_depth_camera_def(void) {
  return boreas::impl::default_depth_camera_def();
}

boreas_status boreas_world_capture_depth(boreas_world world, const boreas_depth_camera_def* camera,
                                         float* depth, boreas_pixel_label* labels) {
  return guarded(__func__, [&] {
    boreas::impl::World& w = world_of(world);
    if (!camera) fail_argument("camera is NULL");
    w.capture_depth(*camera, depth, labels);
  });
}

}  // extern "C"
