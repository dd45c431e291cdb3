// boreas command: the run summary as JSON.
#include "cli/run_summary.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "cli/cli_error.h"

namespace boreas::render {

namespace {

// The value with digits significant digits: floats widened to double would otherwise print
// as 0.041666701436042786 where the scene said 0.0416667.
double tidy(double v, int digits = 7) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return std::strtod(text, nullptr);
}

// A 64-bit hash as 16 hex digits: exact for readers whose numbers are doubles.
std::string hex64(uint64_t v) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

nlohmann::ordered_json v3(const float* v) {
  return nlohmann::ordered_json::array({tidy(v[0]), tidy(v[1]), tidy(v[2])});
}

// One frame's entry of frame_stats.
nlohmann::ordered_json frame_json(const RunSummary& s, const FrameStats& f) {
  nlohmann::ordered_json frame = {{"index", f.index}, {"time", tidy(f.time)}};
  // The trails view films only its first frame, into trails.png.
  frame["file"] = f.file.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(f.file);
  // The wind speeds are the slice's pixels: the 3D view samples no slice.
  if (s.run.view == ViewMode::slice) {
    frame["max_speed"] = tidy(f.max_speed);
    frame["mean_speed"] = tidy(f.mean_speed);
  }
  if (!s.trees.empty()) frame["max_sway"] = tidy(f.max_sway, 5);
  if (!s.meadows.empty()) frame["max_bend"] = tidy(f.max_bend, 5);
  if (f.has_lod) {
    frame["step_s"] = {{"wind", tidy(f.wind, 5)},
                       {"trees", tidy(f.trees, 5)},
                       {"underbrush", tidy(f.underbrush, 5)}};
    frame["trees_by_lod"] = {{"full", f.trees_by_lod[0]},
                             {"reduced", f.trees_by_lod[1]},
                             {"far", f.trees_by_lod[2]},
                             {"frozen", f.trees_by_lod[3]}};
    frame["branches"] = {{"stepped", f.branches_stepped},
                         {"carried", f.branches_carried},
                         {"broken", f.branches_broken}};
    frame["components_by_rate"] = {{"every_step", f.components_by_rate[0]},
                                   {"every_4th", f.components_by_rate[1]},
                                   {"every_16th", f.components_by_rate[2]},
                                   {"resting", f.components_by_rate[3]}};
  }
  return frame;
}

nlohmann::ordered_json trees_json(const RunSummary& s) {
  nlohmann::ordered_json trees = nlohmann::ordered_json::array();
  for (const TreeStats& t : s.trees) {
    trees.push_back({{"species", t.species},
                     {"position", {tidy(t.position[0]), tidy(t.position[1]), tidy(t.position[2])}},
                     {"branches", t.branches},
                     {"leaves", t.leaves}});
  }
  return trees;
}

nlohmann::ordered_json mesh_trees_json(const RunSummary& s) {
  nlohmann::ordered_json mesh_trees = nlohmann::ordered_json::array();
  for (const MeshTreeStats& t : s.mesh_trees) {
    const boreas_mesh_tree_info& i = t.info;
    mesh_trees.push_back({{"model", t.model},
                          {"position", v3(t.position)},
                          {"trunk_vertices", i.trunk_vertices},
                          {"trunk_triangles", i.trunk_triangles},
                          {"leaf_vertices", i.leaf_vertices},
                          {"leaf_triangles", i.leaf_triangles},
                          {"branches", i.branches},
                          {"levels", i.levels},
                          {"orphans", i.orphans},
                          {"leaves", i.leaves},
                          {"from_cache", i.from_cache != 0}});
  }
  return mesh_trees;
}

// The meadows, their components in all, the colliders and the emitters.
nlohmann::ordered_json underbrush_json(const RunSummary& s) {
  nlohmann::ordered_json meadows = nlohmann::ordered_json::array();
  long long components = 0;
  for (const MeadowStats& m : s.meadows) {
    meadows.push_back({{"species", m.species},
                       {"center", {tidy(m.center[0]), tidy(m.center[1]), tidy(m.center[2])}},
                       {"size", {tidy(m.size[0]), tidy(m.size[1])}},
                       {"density", tidy(m.density)},
                       {"components", m.components}});
    components += m.components;
  }
  nlohmann::ordered_json colliders = nlohmann::ordered_json::array();
  for (const ColliderStats& c : s.colliders) {
    colliders.push_back({{"shape", c.shape},
                         {"radius", tidy(c.radius)},
                         {"half_height", tidy(c.half_height)},
                         {"half_extents", v3(c.half_extents)},
                         {"start", v3(c.start)},
                         {"velocity", v3(c.velocity)},
                         {"end", v3(c.end)}});
  }
  return {{"components", components},
          {"top_view_stride", s.top_stride},
          {"meadows", meadows},
          {"colliders", colliders},
          {"emitters", s.emitters}};
}

// The timings of a 3D run (scene_view) or of a slice run.
nlohmann::ordered_json timings_json(const StageTimes& t, bool scene_view) {
  if (scene_view) {
    // The stages: wind, trees and underbrush (device time of the steps), interop,
    // render; then what the command adds around them.
    return {{"world_create", tidy(t.world_create, 4)},
            {"textures", tidy(t.textures, 4)},
            {"impostors", tidy(t.impostors, 4)},
            {"wind", tidy(t.wind, 4)},
            {"trees", tidy(t.trees, 4)},
            {"underbrush", tidy(t.underbrush, 4)},
            {"step_wall", tidy(t.wind_step, 4)},
            {"interop", tidy(t.interop, 4)},
            {"render", tidy(t.render, 4)},
            {"render_cpu", tidy(t.render_cpu, 4)},
            {"readback", tidy(t.readback, 4)},
            {"image_writing", tidy(t.image_writing, 4)},
            {"sensors", tidy(t.sensors, 4)},
            {"contact_sheet", tidy(t.contact_sheet, 4)},
            {"animation", tidy(t.animation, 4)},
            {"total", tidy(t.total, 4)}};
  }
  return {{"world_create", tidy(t.world_create, 4)},
          {"wind_step", tidy(t.wind_step, 4)},
          {"sampling", tidy(t.sampling, 4)},
          {"tree_readback", tidy(t.tree_readback, 4)},
          {"drawing", tidy(t.drawing, 4)},
          {"tree_drawing", tidy(t.tree_drawing, 4)},
          {"meadow_readback", tidy(t.meadow_readback, 4)},
          {"meadow_drawing", tidy(t.meadow_drawing, 4)},
          {"image_writing", tidy(t.image_writing, 4)},
          {"sensors", tidy(t.sensors, 4)},
          {"contact_sheet", tidy(t.contact_sheet, 4)},
          {"animation", tidy(t.animation, 4)},
          {"total", tidy(t.total, 4)}};
}

// The 3D views' renderer: OpenGL, interop, camera, sun and the frame's settings.
nlohmann::ordered_json parts_json(const std::map<std::string, double>& parts) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [name, seconds] : parts) out[name] = tidy(seconds, 4);
  return out;
}

nlohmann::ordered_json render_json(const RenderStats& r) {
  return {{"gl", r.gl},
          {"interop",
           {{"strategy", r.interop},
            {"choice", r.interop_choice},
            {"in_place", r.in_place},
            {"mb_per_frame", tidy(r.interop_mb_per_frame, 3)},
            {"tree_records",
             {{"trees", r.tree_ranges}, {"branches", r.tree_branches}, {"leaves", r.tree_leaves},
              {"impostors", r.tree_impostors}}}}},
          {"camera", {{"eye", v3(r.eye)}, {"target", v3(r.target)}, {"fov_deg", tidy(r.fov_deg)}}},
          {"sun",
           {{"elevation_deg", tidy(r.sun_elevation_deg)},
            {"azimuth_deg", tidy(r.sun_azimuth_deg)},
            {"turbidity", tidy(r.turbidity)}}},
          {"shadows", r.shadows},
          {"msaa", r.msaa},
          {"exr", r.exr},
          {"parts_s", parts_json(r.parts)}};
}

nlohmann::ordered_json sensors_json(const RunSummary& s) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const SensorStats& sensor : s.sensors) {
    nlohmann::ordered_json one = {{"name", sensor.name},
                                  {"type", sensor.type},
                                  {"folder", sensor.folder},
                                  {"frames", sensor.frames}};
    if (sensor.type == "lidar") {
      one["points"] = sensor.frame_points;
      one["sweeps"] = sensor.frame_sweeps;
    }
    out.push_back(one);
  }
  return out;
}

}  // namespace

nlohmann::ordered_json summary_json(const RunSummary& s) {
  nlohmann::ordered_json frames = nlohmann::ordered_json::array();
  for (const FrameStats& f : s.frames) frames.push_back(frame_json(s, f));
  const bool scene_view = s.run.view != ViewMode::slice;  // 3D: the scene and trails views
  nlohmann::ordered_json out = {
      {"scene", s.scene_name},
      {"scene_source", s.scene_source},
      {"seed", s.seed ? nlohmann::ordered_json(*s.seed) : nlohmann::ordered_json()},
      {"device",
       {{"name", s.device.device_name},
        {"platform", s.device.platform_name},
        {"type", s.device.is_gpu ? "GPU" : "CPU"},
        {"index",
         std::to_string(s.device.platform_index) + ":" + std::to_string(s.device.device_index)}}},
      {"frames", s.run.frames},
      {"steps_per_frame", s.run.steps_per_frame},
      {"steps", s.steps},
      {"dt", tidy(s.run.dt)},
      {"sim_time", tidy(s.sim_time)},
      {"state_hash", hex64(s.state_hash)},
      {"slice_height", tidy(s.run.slice_height)},
      {"image_size", {s.run.image_width, s.run.image_height}},
      {"color_max", tidy(s.run.color_max)},
      {"contact_sheet", s.contact_sheet},
      {"animation",
       s.animation.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(s.animation)},
      {"trees", trees_json(s)},
      {"mesh_trees", mesh_trees_json(s)},
      {"underbrush", underbrush_json(s)},
      {"sensors", sensors_json(s)},
      {"frame_stats", frames},
  };
  if (scene_view) out["render"] = render_json(s.render);
  out["view"] = s.run.view == ViewMode::slice    ? "slice"
                : s.run.view == ViewMode::trails ? "trails"
                : s.run.view == ViewMode::lidar  ? "lidar"
                                                 : "scene";
  if (s.run.view == ViewMode::trails) {
    out["trails"] = {
        {"file", s.trails}, {"branch_tips", s.branch_trails}, {"blade_tips", s.blade_trails}};
  }
  out["timings"] = timings_json(s.times, scene_view);
  return out;
}

void write_summary(const std::string& path, const RunSummary& summary) {
  std::ofstream out(path);
  out << summary_json(summary).dump(2) << "\n";
  if (!out) throw CliError(kExitFailure, path + ": cannot write the run summary");
}

}  // namespace boreas::render
