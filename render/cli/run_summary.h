// boreas command: <out>/summary.json, what a run did and how long each stage took, for
// people and for scripts (the tests read it). Its fields are listed in render/SCENES.md.
#pragma once

#include <nlohmann/json.hpp>
#include <cstdint>
#include <optional>
#include <map>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "cli/sensor_recorder.h"
#include "cli/stage_times.h"
#include "scene/scene.h"

namespace boreas::render {

struct FrameStats {
  int index = 0;
  double time = 0.0;        // s, simulated time the frame shows
  std::string file;         // relative to the output folder
  float max_speed = 0.0f;   // m/s over the slice's pixels
  float mean_speed = 0.0f;  // m/s over the slice's pixels (solid ones count as 0)
  float max_sway = 0.0f;    // m: the farthest any branch end stands from its rest pose
                            // (of the kSwayTrees trees nearest the camera)
  float max_bend = 0.0f;    // m: the farthest any component's center of mass stands from rest
  // The 3D view: the device time of the frame's steps by stage (s), and the levels of detail
  // of its last step (boreas_step_stats).
  double wind = 0.0, trees = 0.0, underbrush = 0.0;
  int64_t trees_by_lod[4] = {0, 0, 0, 0};
  int64_t branches_stepped = 0, branches_carried = 0;
  int64_t branches_broken = 0;  // in the frame's steps
  int64_t components_by_rate[4] = {0, 0, 0, 0};
  bool has_lod = false;
};

// The 3D view follows the sway of at most this many trees (the nearest the camera): a
// forest's every branch read back every frame would cost more than the frame.
constexpr size_t kSwayTrees = 64;

struct TreeStats {
  std::string species;  // as the library was given it (files resolved)
  float position[3] = {0.0f, 0.0f, 0.0f};
  int branches = 0;
  int leaves = 0;
};

// An imported tree as preprocessed (boreas_mesh_tree_info).
struct MeshTreeStats {
  std::string model;  // the file (resolved against the scene's folder)
  float position[3] = {0.0f, 0.0f, 0.0f};
  boreas_mesh_tree_info info{};
};

struct MeadowStats {
  std::vector<std::string> species;  // as planted (files resolved; the default mix named)
  float center[3] = {0.0f, 0.0f, 0.0f};
  float size[2] = {0.0f, 0.0f};
  float density = 0.0f;  // components per m^2 asked for
  int components = 0;    // planted
};

struct ColliderStats {
  std::string shape = "sphere";  // sphere, capsule or box
  float radius = 0.0f;           // m: a sphere's or capsule's (0 for a box)
  float half_height = 0.0f;      // m: a capsule's
  float half_extents[3] = {0.0f, 0.0f, 0.0f};  // m: a box's
  float start[3] = {0.0f, 0.0f, 0.0f};     // m, at time 0
  float velocity[3] = {0.0f, 0.0f, 0.0f};  // m/s
  float end[3] = {0.0f, 0.0f, 0.0f};       // m, after the last step
};

// The 3D view's renderer and how the kernels' buffers reached it.
struct RenderStats {
  std::string gl;              // "4.5 (Core Profile) Mesa ... | llvmpipe ..."
  std::string interop;         // strategy: gl_sharing, zero_copy or copy
  std::string interop_choice;  // "auto" or "requested"
  bool in_place = false;       // zero_copy: CL writes GL's memory itself
  double interop_mb_per_frame = 0.0;
  // The last frame's records' one call (WorldBuffers::tree_counts): trees drawn (range
  // records), branch, leaf and impostor records written.
  long long tree_ranges = 0, tree_branches = 0, tree_leaves = 0, tree_impostors = 0;
  float eye[3] = {0.0f, 0.0f, 0.0f};     // m
  float target[3] = {0.0f, 0.0f, 0.0f};  // m
  float fov_deg = 0.0f;
  float sun_elevation_deg = 0.0f, sun_azimuth_deg = 0.0f, turbidity = 0.0f;
  bool shadows = true;
  int msaa = 1;      // samples per pixel the scene pass used
  bool exr = false;  // frames also written as .exr
  // GPU seconds of the frames' parts, summed over frames (Renderer::part_seconds); empty
  // without --gpu-times.
  std::map<std::string, double> parts;
};

struct RunSummary {
  std::string scene_name;
  std::string scene_source;  // the file, or "built-in default"
  std::optional<uint64_t> seed;  // --seed; unset: the scene's own seeds
  boreas_device_info device{};
  RunSettings run;
  long long steps = 0;
  double sim_time = 0.0;  // s
  // boreas_world_get_state_hash after the last step: equal runs (scene, seed, device,
  // steps) have equal hashes, so a dataset can check one machine's item against another's.
  uint64_t state_hash = 0;
  std::vector<FrameStats> frames;
  std::vector<TreeStats> trees;  // empty: no trees, and no max_sway in the frame stats
  std::vector<MeshTreeStats> mesh_trees;
  std::vector<MeadowStats> meadows;  // empty: no meadows, and no max_bend in the frame stats
  int top_stride = 1;                // from above, every top_stride-th component is drawn
  std::vector<ColliderStats> colliders;
  int emitters = 0;
  std::string contact_sheet;  // relative to the output folder
  std::string animation;      // relative to the output folder; empty: none written
  std::string trails;         // the trails view's picture, relative to the output folder
  int branch_trails = 0;      // the trails view: branch tips and blade tips followed
  int blade_trails = 0;
  std::vector<SensorStats> sensors;  // the scene's sensors, in its order
  RenderStats render;         // the 3D view only (run.view "scene")
  StageTimes times;
};

nlohmann::ordered_json summary_json(const RunSummary& summary);

// Writes summary_json() to path; throws CliError (exit 3) when it cannot.
void write_summary(const std::string& path, const RunSummary& summary);

}  // namespace boreas::render
