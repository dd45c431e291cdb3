// boreas command: `boreas run`. The order matters for errors: the scene and the options
// are checked completely before a world is created or any file is written.
//
// Per frame: steps_per_frame world steps, one sampling call for the slice, the trees read
// back (when the scene has any), drawing, PNG.
#include "cli/run_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <regex>

#include "cli/cli_error.h"
#include "cli/progress.h"
#include "cli/run_summary.h"
#include "cli/slice_sampler.h"
#include "cli/tree_poses.h"
#include "image/contact_sheet.h"
#include "image/png_io.h"
#include "image/tree_view.h"
#include "image/wind_view.h"
#include "scene/scene_loader.h"
#include "scene/scene_world.h"

namespace boreas::render {

namespace {

namespace fs = std::filesystem;

constexpr int kSheetTiles = 8;
constexpr int kSheetColumns = 4;
constexpr int kSheetTileWidth = 256;

std::string frame_file(int index, int frame_count) {
  std::string number = std::to_string(index);
  size_t digits = std::max<size_t>(4, std::to_string(frame_count - 1).size());
  return "frame_" + std::string(digits - std::min(digits, number.size()), '0') + number + ".png";
}

// Frames of an earlier, longer run in the same folder would pass for this run's.
void remove_old_frames(const fs::path& dir) {
  static const std::regex kFrameName("frame_[0-9]+\\.png");
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), kFrameName)) {
      fs::remove(entry.path());
    }
  }
}

void prepare_output(const fs::path& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error || !fs::is_directory(dir)) {
    throw CliError(kExitFailure, dir.string() + ": cannot create the output folder" +
                                     (error ? ": " + error.message() : ""));
  }
  remove_old_frames(dir);
}

void measure(const std::vector<float>& wind, FrameStats& stats) {
  double sum = 0.0;
  float peak = 0.0f;
  size_t count = wind.size() / 3;
  for (size_t i = 0; i < count; ++i) {
    float speed = std::sqrt(wind[3 * i] * wind[3 * i] + wind[3 * i + 1] * wind[3 * i + 1] +
                            wind[3 * i + 2] * wind[3 * i + 2]);
    // A non-finite wind is a library failure, not a frame to draw (std::max would drop it).
    if (!std::isfinite(speed)) {
      throw CliError(kExitFailure, "frame " + std::to_string(stats.index) +
                                       ": the wind is not finite at sample " + std::to_string(i) +
                                       " (a boreas bug: please report the scene)");
    }
    peak = std::max(peak, speed);
    sum += speed;
  }
  stats.max_speed = peak;
  stats.mean_speed = count ? float(sum / double(count)) : 0.0f;
}

std::string frame_title(const Scene& scene, const RunSettings& run, int frame, double time) {
  char text[160];
  std::snprintf(text, sizeof text, "%s  T=%.2f S  Y=%.1f M  %d/%d", scene.name.c_str(), time,
                double(run.slice_height), frame + 1, run.frames);
  return text;
}

WindView frame_view(const RunSettings& run, const SliceSampler& sampler,
                    const std::vector<float>& wind, std::string title) {
  WindView view;
  view.width = run.image_width;
  view.height = run.image_height;
  view.wind = &wind;
  view.color_max = run.color_max;
  view.pixels_per_meter_x = 1.0f / sampler.meters_per_pixel_x();
  view.pixels_per_meter_z = 1.0f / sampler.meters_per_pixel_z();
  view.title = std::move(title);
  return view;
}

// The scene's trees as the frames show them: rest poses (as grown), the poses of the last
// step, and the side-view panel laid out from the rest poses.
struct FrameTrees {
  std::vector<boreas_id> ids;
  std::vector<TreePose> rest;
  std::vector<TreePose> now;
  SidePanel panel;

  bool empty() const { return ids.empty(); }
  static std::vector<const TreePose*> pointers(const std::vector<TreePose>& poses) {
    std::vector<const TreePose*> out;
    for (const TreePose& pose : poses) out.push_back(&pose);
    return out;
  }
};

FrameTrees grow_frame_trees(const boreas::World& world, const Scene& scene,
                            std::vector<boreas_id> ids, const RunSettings& run,
                            std::vector<TreeStats>& stats) {
  FrameTrees trees;
  trees.ids = std::move(ids);
  trees.rest.resize(trees.ids.size());
  std::vector<std::string> labels;
  for (size_t i = 0; i < trees.ids.size(); ++i) {
    read_tree_pose(world, trees.ids[i], trees.rest[i]);
    const SceneTree& tree = scene.trees[i];
    TreeStats s;
    s.species = tree.species;
    std::copy(tree.def.position, tree.def.position + 3, s.position);
    s.branches = int(trees.rest[i].branches.size());
    s.leaves = int(trees.rest[i].leaves.size());
    stats.push_back(s);
    labels.push_back(species_label(tree.species));
  }
  trees.now = trees.rest;
  if (!trees.empty()) {
    trees.panel = layout_side_panel(FrameTrees::pointers(trees.rest), labels, run.image_width,
                                    side_panel_height(run.image_width, run.image_height));
  }
  return trees;
}

// The slice's field with the trees from above, and the side-view panel under it.
Image field_with_trees(Image field, const FrameTrees& trees, const boreas_grid_def& grid,
                       const SliceSampler& sampler) {
  if (trees.empty()) return field;
  TopProjection projection;
  projection.origin_x = grid.origin[0];
  projection.origin_z = grid.origin[2];
  projection.pixels_per_meter_x = 1.0f / sampler.meters_per_pixel_x();
  projection.pixels_per_meter_z = 1.0f / sampler.meters_per_pixel_z();
  std::vector<const TreePose*> now = FrameTrees::pointers(trees.now);
  draw_trees_from_above(field, projection, now);
  Image frame(field.width(), field.height() + trees.panel.height);
  frame.paste(field, 0, 0);
  frame.paste(draw_side_panel(trees.panel, FrameTrees::pointers(trees.rest), now), 0,
              field.height());
  return frame;
}

// images[i] is the field of frame sheet_frames[i], without overlays.
void write_contact_sheet(const fs::path& out_dir, const Scene& scene, RunSummary& summary,
                         const std::vector<int>& sheet_frames, const std::vector<Image>& images) {
  std::vector<SheetTile> tiles;
  for (size_t i = 0; i < images.size(); ++i) {
    const FrameStats& f = summary.frames[size_t(sheet_frames[i])];
    char label[64];
    std::snprintf(label, sizeof label, "%d  T=%.2f S", f.index + 1, f.time);
    tiles.push_back({&images[i], label});
  }
  char title[160];
  std::snprintf(title, sizeof title, "%s  Y=%.1f M  SPEED 0 TO %s M/S (VIRIDIS)",
                scene.name.c_str(), double(summary.run.slice_height),
                speed_label(summary.run.color_max).c_str());
  summary.contact_sheet = "contact_sheet.png";
  write_png((out_dir / summary.contact_sheet).string(),
            make_contact_sheet(tiles, kSheetColumns, kSheetTileWidth, title));
}

}  // namespace

int run_run_command(const RunOptions& options) {
  auto command_start = std::chrono::steady_clock::now();
  Scene scene = options.scene_path ? load_scene_file(*options.scene_path) : load_default_scene();
  RunSummary summary;
  summary.run = resolve_run_settings(scene, options);
  const RunSettings& run = summary.run;
  summary.scene_name = scene.name;
  summary.scene_source = options.scene_path ? *options.scene_path : "built-in default";

  StageTimes& times = summary.times;
  std::vector<boreas_id> tree_ids;
  boreas::World world =
      timed(times.world_create, [&] { return make_world(scene, options.device, &tree_ids); });
  FrameTrees trees = timed(times.tree_readback, [&] {
    return grow_frame_trees(world, scene, std::move(tree_ids), run, summary.trees);
  });
  // Only now that the world exists: a run that cannot start leaves the folder alone.
  fs::path out_dir(options.out_dir);
  prepare_output(out_dir);
  summary.device = world.device();
  const boreas_grid_def grid = world.grid();
  SliceSampler sampler(grid, run.slice_height, run.image_width, run.image_height);

  std::vector<int> sheet_frames = contact_sheet_frames(run.frames, kSheetTiles);
  std::vector<Image> sheet_images;
  Progress progress(run.frames, !options.quiet);
  for (int frame = 0; frame < run.frames; ++frame) {
    timed(times.wind_step, [&] {
      for (int i = 0; i < run.steps_per_frame; ++i) world.step(run.dt);
    });
    const std::vector<float>& wind =
        timed(times.sampling, [&]() -> const std::vector<float>& { return sampler.sample(world); });
    FrameStats stats;
    stats.index = frame;
    stats.time = world.time();
    stats.file = frame_file(frame, run.frames);
    measure(wind, stats);
    timed(times.tree_readback, [&] {
      for (size_t i = 0; i < trees.ids.size(); ++i) {
        read_tree_pose(world, trees.ids[i], trees.now[i]);
        stats.max_sway = std::max(stats.max_sway, max_tip_offset(trees.rest[i], trees.now[i]));
      }
    });

    WindView view = frame_view(run, sampler, wind, frame_title(scene, run, frame, stats.time));
    Image field = timed(times.drawing, [&] { return draw_wind_field(view); });
    Image image = timed(times.tree_drawing, [&] {
      return field_with_trees(std::move(field), trees, grid, sampler);
    });
    timed(times.drawing, [&] {
      // The sheet labels its tiles itself; shrunk overlays would only be clutter.
      if (std::find(sheet_frames.begin(), sheet_frames.end(), frame) != sheet_frames.end()) {
        sheet_images.push_back(image);
      }
      draw_wind_overlays(image, view);
      if (!trees.empty() && std::min(view.width, view.height) >= kMinOverlaySize) {
        draw_side_panel_labels(image, view.height, trees.panel);
      }
    });
    timed(times.image_writing, [&] { write_png((out_dir / stats.file).string(), image); });
    summary.frames.push_back(stats);
    progress.update(frame + 1);
  }
  summary.steps = (long long)run.frames * run.steps_per_frame;
  summary.sim_time = world.time();

  timed(times.contact_sheet,
        [&] { write_contact_sheet(out_dir, scene, summary, sheet_frames, sheet_images); });
  times.total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - command_start).count();
  write_summary((out_dir / "summary.json").string(), summary);

  char done[256];
  std::snprintf(done, sizeof done, "%d frames (%lld steps, %.2f s simulated) in %.2f s -> %s",
                run.frames, summary.steps, summary.sim_time, times.total, out_dir.string().c_str());
  progress.finish(done);
  if (!options.quiet) {
    std::cout << "scene " << scene.name << " on " << summary.device.device_name << ": "
              << (out_dir / "summary.json").string() << "\n";
  }
  return kExitOk;
}

}  // namespace boreas::render
