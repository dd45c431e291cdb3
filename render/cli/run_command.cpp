// boreas command: `boreas run`. The 3D view is in scene_run.cpp; here is the slice view
// (wind speed in a horizontal slice, trees and meadows from above). The order matters for
// errors: the scene and the options are checked completely before a world is created or
// any file is written.
//
// Per frame: steps_per_frame world steps (each after moving the rolling colliders), one
// sampling call for the slice, the trees and meadows read back (when the scene has any),
// drawing, PNG.
#include "cli/run_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "cli/cli_error.h"
#include "cli/frame_files.h"
#include "view/meadow_frames.h"
#include "cli/progress.h"
#include "cli/run_summary.h"
#include "cli/scene_run.h"
#include "cli/scene_stats.h"
#include "cli/sensor_recorder.h"
#include "cli/slice_sampler.h"
#include "cli/tree_poses.h"
#include "image/contact_sheet.h"
#include "image/draw.h"
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
  std::vector<boreas_tree_id> ids;
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

// The side-view panel under the slice: the trees' columns on the left, the meadow's
// close-up on the right (a third of the width with trees, so that the trees' columns keep
// room for their labels; all of it without).
struct PanelLayout {
  int height = 0;        // 0: no panel
  int tree_width = 0;    // pixels
  int meadow_width = 0;  // pixels
};

PanelLayout panel_layout(const Scene& scene, const RunSettings& run) {
  PanelLayout layout;
  bool trees = !scene.trees.empty();
  bool meadows = !scene.meadows.empty();
  if (!trees && !meadows) return layout;
  layout.height = side_panel_height(run.image_width, run.image_height);
  int width = run.image_width;
  if (meadows) {
    layout.meadow_width = trees ? std::max(width / 3, std::min(kMinSideColumn, width / 2)) : width;
  }
  layout.tree_width = trees ? width - layout.meadow_width : 0;
  return layout;
}

FrameTrees grow_frame_trees(const boreas::World& world, const Scene& scene,
                            std::vector<boreas_tree_id> ids, const PanelLayout& layout,
                            std::vector<TreeStats>& stats) {
  FrameTrees trees;
  trees.ids = std::move(ids);
  trees.rest.resize(trees.ids.size());
  std::vector<std::string> labels;
  for (size_t i = 0; i < trees.ids.size(); ++i) {
    read_tree_pose(world, trees.ids[i], trees.rest[i]);
    const SceneTree& tree = scene.trees[i];
    stats.push_back(tree_stats(tree, trees.rest[i]));
    labels.push_back(species_label(tree.species));
  }
  trees.now = trees.rest;
  if (!trees.empty()) {
    trees.panel = layout_side_panel(FrameTrees::pointers(trees.rest), labels, layout.tree_width,
                                    layout.height);
  }
  return trees;
}

// The meadows as planted, and what the summary says about them.
FrameMeadows plant_meadows(const boreas::World& world, const Scene& scene,
                           std::vector<boreas_meadow_id> ids, RunSummary& summary) {
  FrameMeadows meadows = plant_frame_meadows(world, scene, std::move(ids));
  add_meadow_stats(scene, meadows, summary);
  summary.top_stride = meadows.stride;
  return meadows;
}

// The meadow's close-up, laid out from the first meadow's rest pose.
MeadowCloseUp layout_close_up(const Scene& scene, const FrameMeadows& meadows,
                              const PanelLayout& layout) {
  if (meadows.empty()) return {};
  const boreas_meadow_def& first = scene.meadows[0].def;
  double area = double(first.size[0]) * first.size[1];
  float per_m2 = float(double(meadows.counts[0]) / area);
  return layout_meadow_close_up(meadows.rest, layout.meadow_width, layout.height, per_m2);
}

TopProjection top_projection(const boreas_grid_def& grid, const SliceSampler& sampler) {
  TopProjection projection;
  projection.origin_x = grid.origin[0];
  projection.origin_z = grid.origin[2];
  projection.pixels_per_meter_x = 1.0f / sampler.meters_per_pixel_x();
  projection.pixels_per_meter_z = 1.0f / sampler.meters_per_pixel_z();
  return projection;
}

// Everything a frame draws over the slice, and the panel under it.
struct FrameContent {
  const Scene* scene = nullptr;
  const FrameTrees* trees = nullptr;
  const FrameMeadows* meadows = nullptr;
  PanelLayout layout;
  MeadowCloseUp close_up;
  TopProjection projection;
};

// The slice's field with the meadows, balls and trees from above, and the side-view panel
// under it (trees left, the meadow's close-up right) at simulated time t.
Image compose_frame(Image field, const FrameContent& content, double t, StageTimes& times) {
  const FrameTrees& trees = *content.trees;
  const FrameMeadows& meadows = *content.meadows;
  const Scene& scene = *content.scene;
  std::vector<Ball> balls = colliders_at(scene, t);
  timed(times.meadow_drawing, [&] {
    draw_meadow_from_above(field, content.projection, meadows.now, meadows.rest, meadows.palette,
                           meadows.stride);
    // Under the trees' crowns, as they would be.
    draw_balls_from_above(field, content.projection, balls);
  });
  timed(times.tree_drawing,
        [&] { draw_trees_from_above(field, content.projection, FrameTrees::pointers(trees.now)); });
  timed(times.meadow_drawing,
        [&] { draw_emitters_from_above(field, content.projection, emitter_areas(scene)); });
  if (content.layout.height == 0) return field;
  Image frame(field.width(), field.height() + content.layout.height);
  frame.paste(field, 0, 0);
  if (!trees.empty()) {
    timed(times.tree_drawing, [&] {
      frame.paste(draw_side_panel(trees.panel, FrameTrees::pointers(trees.rest),
                                  FrameTrees::pointers(trees.now)),
                  0, field.height());
    });
  }
  if (!meadows.empty()) {
    timed(times.meadow_drawing, [&] {
      float focus[3];
      close_up_focus(scene, t, focus);
      frame.paste(draw_meadow_close_up(content.close_up, focus[0], focus[1], focus[2], meadows.now,
                                       meadows.rest, meadows.palette, balls),
                  content.layout.tree_width, field.height());
      if (content.layout.tree_width > 0) {
        const Rgb separator{0.70f, 0.73f, 0.78f};
        frame.fill_rect(content.layout.tree_width, field.height(), content.layout.tree_width + 1,
                        frame.height(), separator);
      }
    });
  }
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

// What the slice view's frames share once the world, its trees and meadows, the sampler
// and the frame's content exist, under the names run_run_command's locals had.
struct SliceRun {
  SliceRun(const Scene& scene, const RunOptions& options, RunSummary& summary, boreas::World& world,
           const SceneIds& ids, FrameTrees& trees, FrameMeadows& meadows, SliceSampler& sampler,
           const FrameContent& content, const fs::path& out_dir)
      : scene(scene),
        options(options),
        summary(summary),
        run(summary.run),
        times(summary.times),
        world(world),
        ids(ids),
        trees(trees),
        meadows(meadows),
        sampler(sampler),
        content(content),
        out_dir(out_dir),
        sheet_frames(contact_sheet_frames(summary.run.frames, kSheetTiles)),
        progress(summary.run.frames, !options.quiet) {}

  const Scene& scene;
  const RunOptions& options;
  RunSummary& summary;
  const RunSettings& run;
  StageTimes& times;
  boreas::World& world;
  const SceneIds& ids;
  FrameTrees& trees;
  FrameMeadows& meadows;
  SliceSampler& sampler;
  const FrameContent& content;
  const fs::path& out_dir;
  std::vector<int> sheet_frames;
  std::vector<Image> sheet_images;
  std::unique_ptr<AnimationWriter> animation = nullptr;
  Progress progress;
  std::optional<SensorRecorder> sensors;  // made with the output folder

  void film(AnimationFormat animation_format);
  const std::vector<float>& step_frame(int frame, FrameStats& stats);
  Image draw_frame(int frame, const FrameStats& stats, const std::vector<float>& wind);
};

// Every frame stepped, drawn and written; then the animation and the contact sheet.
void SliceRun::film(AnimationFormat animation_format) {
  for (int frame = 0; frame < run.frames; ++frame) {
    FrameStats stats;
    const std::vector<float>& wind = step_frame(frame, stats);
    Image image = draw_frame(frame, stats, wind);
    timed(times.image_writing, [&] { write_png((out_dir / stats.file).string(), image); });
    if (frame == 0) {
      // Frames have their size only once the panels are drawn.
      animation = open_animation(out_dir, animation_format, image.width(), image.height(),
                                 run.frames, run.steps_per_frame * double(run.dt));
    }
    if (animation) timed(times.animation, [&] { add_frame(*animation, image.to_rgb8()); });
    summary.frames.push_back(stats);
    progress.update(frame + 1);
  }
  summary.steps = (long long)run.frames * run.steps_per_frame;
  summary.sim_time = world.get_time();
  summary.state_hash = world.get_state_hash();
  add_collider_stats(scene, summary);
  summary.sensors = sensors->stats();

  if (animation) {
    timed(times.animation, [&] { finish(*animation); });
    summary.animation = animation_file(animation_format);
  }
  timed(times.contact_sheet,
        [&] { write_contact_sheet(out_dir, scene, summary, sheet_frames, sheet_images); });
}

// The world stepped to the frame, the slice sampled (the sampler's buffer is returned) and
// measured, the trees and meadows read back.
const std::vector<float>& SliceRun::step_frame(int frame, FrameStats& stats) {
  timed(times.wind_step, [&] {
    step_scene(world, scene, run.steps_per_frame, run.dt, ids.lidars);
  });
  timed(times.sensors, [&] { sensors->record(world, frame); });
  const std::vector<float>& wind =
      timed(times.sampling, [&]() -> const std::vector<float>& { return sampler.sample(world); });
  stats.index = frame;
  stats.time = world.get_time();
  stats.file = frame_file(frame, run.frames);
  measure(wind, stats);
  timed(times.tree_readback, [&] {
    for (size_t i = 0; i < trees.ids.size(); ++i) {
      read_tree_pose(world, trees.ids[i], trees.now[i]);
      stats.max_sway = std::max(stats.max_sway, max_tip_offset(trees.rest[i], trees.now[i]));
    }
  });
  timed(times.meadow_readback, [&] {
    if (meadows.empty()) return;
    read_meadows(world, meadows);
    stats.max_bend = max_bend(meadows);
  });
  return wind;
}

// The frame's picture: the field with compose_frame's content, kept for the contact sheet
// when it is one of its frames, then the overlays.
Image SliceRun::draw_frame(int frame, const FrameStats& stats, const std::vector<float>& wind) {
  const PanelLayout& layout = content.layout;
  WindView view = frame_view(run, sampler, wind, frame_title(scene, run, frame, stats.time));
  Image field = timed(times.drawing, [&] { return draw_wind_field(view); });
  Image image = compose_frame(std::move(field), content, stats.time, times);
  timed(times.drawing, [&] {
    // The sheet labels its tiles itself; shrunk overlays would only be clutter.
    if (std::find(sheet_frames.begin(), sheet_frames.end(), frame) != sheet_frames.end()) {
      sheet_images.push_back(image);
    }
    draw_wind_overlays(image, view);
    if (std::min(view.width, view.height) >= kMinOverlaySize) {
      if (!trees.empty()) draw_side_panel_labels(image, view.height, trees.panel);
      if (!meadows.empty()) {
        draw_meadow_close_up_label(image, layout.tree_width, view.height, content.close_up);
      }
    }
  });
  return image;
}

// The slice view: the world and what the frames show made (a run that cannot start leaves
// the folder alone), then the frames filmed and the summary written.
int run_slice_view(const Scene& scene, const RunOptions& options, AnimationFormat animation_format,
                   RunSummary& summary, std::chrono::steady_clock::time_point command_start) {
  const RunSettings& run = summary.run;
  PanelLayout layout = panel_layout(scene, run);

  StageTimes& times = summary.times;
  SceneIds ids;
  boreas::World world =
      timed(times.world_create, [&] { return make_world(scene, options.device, &ids); });
  FrameTrees trees = timed(times.tree_readback, [&] {
    return grow_frame_trees(world, scene, std::move(ids.trees), layout, summary.trees);
  });
  FrameMeadows meadows = timed(times.meadow_readback, [&] {
    return plant_meadows(world, scene, std::move(ids.meadows), summary);
  });
  add_mesh_tree_stats(world, scene, ids.mesh_trees, summary);
  summary.emitters = int(scene.emitters.size());
  // Only now that the world exists: a run that cannot start leaves the folder alone.
  fs::path out_dir(options.out_dir);
  prepare_output(out_dir);
  summary.device = world.get_device();
  const boreas_grid_def grid = world.wind_get_grid();
  SliceSampler sampler(grid, run.slice_height, run.image_width, run.image_height);
  FrameContent content;
  content.scene = &scene;
  content.trees = &trees;
  content.meadows = &meadows;
  content.layout = layout;
  content.close_up = layout_close_up(scene, meadows, layout);
  content.projection = top_projection(grid, sampler);

  SliceRun r(scene, options, summary, world, ids, trees, meadows, sampler, content, out_dir);
  r.sensors.emplace(scene, ids.lidars, out_dir, run.frames);
  r.film(animation_format);
  times.total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - command_start).count();
  write_summary((out_dir / "summary.json").string(), summary);

  char done[256];
  std::snprintf(done, sizeof done, "%d frames (%lld steps, %.2f s simulated) in %.2f s -> %s",
                run.frames, summary.steps, summary.sim_time, times.total, out_dir.string().c_str());
  r.progress.finish(done);
  if (!options.quiet) {
    std::cout << "scene " << scene.name << " on " << summary.device.device_name << ": "
              << (out_dir / "summary.json").string() << "\n";
  }
  return kExitOk;
}

}  // namespace

int run_run_command(const RunOptions& options) {
  auto command_start = std::chrono::steady_clock::now();
  Scene scene = options.scene_path ? load_scene_file(*options.scene_path, options.seed)
                                   : load_default_scene(options.seed);
  RunSummary summary;
  summary.seed = options.seed;
  summary.run = resolve_run_settings(scene, options);
  const RunSettings& run = summary.run;
  summary.scene_name = scene.name;
  summary.scene_source = options.scene_path ? *options.scene_path : "built-in default";
  const AnimationFormat animation_format = resolve_animation(options, run.view);
  if (run.view != ViewMode::slice) {
    return run_scene_view(scene, options, animation_format, summary, command_start);
  }
  return run_slice_view(scene, options, animation_format, summary, command_start);
}

}  // namespace boreas::render
