// boreas command: the 3D view of `boreas run`. The order matters for errors: the OpenGL
// context and the world are made (and the interop strategy settled) before any file is
// written, so a run that cannot start leaves the output folder alone.
//
// Per frame: steps_per_frame world steps (each after moving the rolling colliders); the
// kernels write the branch records, leaf records and underbrush strips into the interop
// buffers; the renderer draws the shadow map, the scene, the sky and the tone-mapped
// frame; the frame is read back and written (PNG, and EXR with --exr). With --window the
// frame is shown instead, until the window closes.
#include "cli/scene_run.h"

// epoxy before GLFW: GLFW would otherwise pull in the system's GL header first.
#include <epoxy/gl.h>

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <iostream>
#include <optional>

#include "boreas/boreas.hpp"
#include "cli/cli_error.h"
#include "cli/frame_files.h"
#include "cli/progress.h"
#include "cli/scene_stats.h"
#include "cli/sensor_recorder.h"
#include "cli/tree_poses.h"
#include "gl/renderer.h"
#include "gl/world_buffers.h"
#include "image/contact_sheet.h"
#include "image/exr_io.h"
#include "image/png_io.h"
#include "interop/gl_context.h"
#include "interop/strategy.h"
#include "scene/scene_world.h"
#include "textures/texture_files.h"
#include "view/lidar_overlay.h"
#include "view/meadow_frames.h"
#include "view/motion_trails.h"
#include "view/scene_view.h"
#include "view/window_input.h"

namespace boreas::render {

namespace {

namespace fs = std::filesystem;

constexpr int kSheetTiles = 8;
constexpr int kSheetColumns = 4;
constexpr int kSheetTileWidth = 320;

// Whether the device the run will pick offers cl_khr_gl_sharing (false when none matches:
// make_world reports that).
bool picked_device_shares_gl(const Scene& scene, const RunOptions& options) {
  const std::optional<std::string>& request = options.device ? options.device : scene.device;
  int index = -1;
  if (boreas_choose_device(request ? request->c_str() : nullptr, &index) != BOREAS_OK) return false;
  std::vector<boreas_device_info> devices = boreas::list_devices();
  return index >= 0 && size_t(index) < devices.size() && devices[size_t(index)].has_gl_sharing != 0;
}

// The world's focus from its first add: the scene's eye, where it gives one (the camera
// step_frame makes the focus; framed from what is drawn, it is known only after the add).
const float* scene_focus(const Scene& scene) {
  return scene.view.eye ? scene.view.eye->data() : nullptr;
}

// The world, made to share the GL context's buffers when the strategy asks for it (or may
// use it: auto, on a device that offers sharing). Sets *shares to whether it does.
boreas::World make_shared_world(const Scene& scene, const RunOptions& options,
                                const interop::GlContext& gl, SceneIds* ids, bool* shares) {
  *shares = false;
  const float* focus = scene_focus(scene);
  // auto asks the device first: a context the driver refuses costs a second world.
  if (options.interop == "gl_sharing" ||
      (options.interop == "auto" && picked_device_shares_gl(scene, options))) {
    std::vector<intptr_t> properties = gl.cl_sharing_properties();
    if (properties.empty()) {
      if (options.interop == "gl_sharing") {
        throw CliError(kExitNoDevice,
                       "--interop gl_sharing: the OpenGL context gives no native handles to share");
      }
    } else {
      try {
        boreas::World world = make_world(scene, options.device, ids, properties.data(), focus);
        *shares = true;
        return world;
      } catch (const boreas::Error& e) {
        // auto: a driver that offers sharing but refuses this context takes the next strategy.
        if (options.interop == "gl_sharing") {
          throw CliError(kExitNoDevice, std::string("--interop gl_sharing: ") + e.what());
        }
        *ids = SceneIds{};
      }
    }
  }
  return make_world(scene, options.device, ids, nullptr, focus);
}

std::string stage_line(const StageTimes& t) {
  char text[320];
  std::snprintf(text, sizeof text,
                "stages: wind %.2f s, trees %.2f s, underbrush %.2f s (device), interop %.2f s, "
                "render %.2f s, readback %.2f s, images %.2f s, animation %.2f s",
                t.wind, t.trees, t.underbrush, t.interop, t.render, t.readback, t.image_writing,
                t.animation);
  return text;
}

Image to_image(const std::vector<uint8_t>& rgb, int width, int height) {
  Image image(width, height);
  std::vector<float>& data = image.data();
  for (size_t i = 0; i < data.size(); ++i) data[i] = float(rgb[i]) / 255.0f;
  return image;
}

// --window: GLFW's callbacks feed the accumulator (window_input.h) between frames, so a
// tap or a drag during a slow frame still counts; the window's user pointer is it.
std::optional<WindowKey> window_key(int key) {
  switch (key) {
    case GLFW_KEY_LEFT: return WindowKey::left;
    case GLFW_KEY_RIGHT: return WindowKey::right;
    case GLFW_KEY_UP: return WindowKey::up;
    case GLFW_KEY_DOWN: return WindowKey::down;
    case GLFW_KEY_EQUAL: case GLFW_KEY_KP_ADD: return WindowKey::zoom_in;
    case GLFW_KEY_MINUS: case GLFW_KEY_KP_SUBTRACT: return WindowKey::zoom_out;
    case GLFW_KEY_W: return WindowKey::wind_up;
    case GLFW_KEY_S: return WindowKey::wind_down;
    case GLFW_KEY_A: return WindowKey::wind_left;
    case GLFW_KEY_D: return WindowKey::wind_right;
    default: return std::nullopt;
  }
}

// Null once the run is over (the window outlives it).
InputAccumulator* accumulator_of(GLFWwindow* window) {
  return static_cast<InputAccumulator*>(glfwGetWindowUserPointer(window));
}

void listen_to_window(GLFWwindow* window, InputAccumulator* input) {
  glfwSetWindowUserPointer(window, input);
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
    InputAccumulator* input = accumulator_of(w);
    if (std::optional<WindowKey> k = window_key(key); input && k && action != GLFW_REPEAT)
      input->key(*k, action == GLFW_PRESS, glfwGetTime());
  });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int) {
    InputAccumulator* input = accumulator_of(w);
    if (button != GLFW_MOUSE_BUTTON_LEFT || !input) return;
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(w, &x, &y);
    input->mouse_button(action == GLFW_PRESS, x, y);
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    if (InputAccumulator* input = accumulator_of(w)) input->cursor(x, y);
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    if (InputAccumulator* input = accumulator_of(w)) input->scroll(dy);
  });
}

// The scene's waves, scaled and turned as the window's keys say (blended over 0.5 s).
void apply_wind_controls(boreas::World& world, const Scene& scene, const WindowControls& c) {
  std::vector<boreas_wave> waves = scene.waves;
  float a = glm::radians(c.wind_turn_deg);
  for (boreas_wave& w : waves) {
    w.amplitude *= c.wind_scale;
    float x = w.direction[0], z = w.direction[1];
    w.direction[0] = x * std::cos(a) - z * std::sin(a);
    w.direction[1] = x * std::sin(a) + z * std::cos(a);
  }
  boreas::check(boreas_wind_set_waves(world.handle(), waves.empty() ? nullptr : waves.data(),
                                      int(waves.size()), 0.5f));
}

// What the 3D view's steps share once the OpenGL context and the world exist, under the
// names run_scene_view's locals had. Declared in the order they are made, so they go in
// the reverse order: the interop buffers and the renderer before the world (which
// run_scene_view holds, with the context).
struct SceneRun {
  SceneRun(const Scene& scene, const RunOptions& options, RunSummary& summary,
           interop::GlContext& gl, boreas::World& world, const SceneIds& ids)
      : scene(scene),
        options(options),
        summary(summary),
        run(summary.run),
        times(summary.times),
        stats(summary.render),
        gl(gl),
        world(world),
        ids(ids) {}

  const Scene& scene;
  const RunOptions& options;
  RunSummary& summary;
  const RunSettings& run;
  StageTimes& times;
  RenderStats& stats;
  interop::GlContext& gl;
  boreas::World& world;
  const SceneIds& ids;

  std::vector<TreePose> rest;  // per tree, read for those in swaying alone
  FrameMeadows meadows;
  std::optional<Renderer> renderer;
  std::optional<WorldBuffers> buffers;
  float aspect = 1.0f;
  Camera camera;
  std::vector<size_t> swaying;
  std::vector<TreePose> now;
  glm::vec3 walk_start{0.0f}, look{0.0f}, walk_end{0.0f};
  Ground ground;
  fs::path out_dir;
  std::optional<Progress> progress;
  std::optional<SensorRecorder> sensors;  // made with the output folder

  void describe_plants();
  void make_renderer(interop::Strategy strategy);
  void place_camera();
  void bake_impostors();
  void record_view_stats();
  float distance2(size_t i) const;
  void walk(int frame);
  void step_frame(FrameStats& frame);
  void draw_frame();
  void run_window();
  void run_trails();
  void run_files(AnimationFormat animation_format);
  void write_contact_sheet(const std::vector<int>& sheet_frames,
                           const std::vector<Image>& sheet_images);
  void print_gl_messages();
  int report(std::chrono::steady_clock::time_point command_start);
};

void SceneRun::describe_plants() {
  // What the summary says about the trees and meadows; the meadows' palette. Counts
  // only: the rest poses are read for the trees whose sway is followed (place_camera).
  for (size_t i = 0; i < ids.trees.size(); ++i) {
    int branches = 0, leaves = 0;
    boreas::check(boreas_tree_get_branches(world.handle(), ids.trees[i], nullptr, 0, &branches));
    boreas::check(boreas_tree_get_leaves(world.handle(), ids.trees[i], nullptr, 0, &leaves));
    summary.trees.push_back(tree_stats(scene.trees[i], branches, leaves));
  }
  meadows = plant_frame_meadows(world, scene, ids.meadows);
  add_meadow_stats(scene, meadows, summary);
  add_mesh_tree_stats(world, scene, ids.mesh_trees, summary);
  summary.emitters = int(scene.emitters.size());
}

void SceneRun::make_renderer(interop::Strategy strategy) {
  timed(times.textures, [&] {
    TextureSet textures;
    try {
      if (options.textures) {
        textures = load_texture_set(*options.textures);  // its one leaf for every kind
      } else {
        textures = generate_texture_set();
        add_leaf_kinds(textures, scene_leaf_kinds(scene));
      }
    } catch (const std::exception& e) {
      throw CliError(kExitBadInput, std::string("--textures: ") + e.what());
    }
    RenderSettings settings = render_settings(scene, run);
    // --gpu-times: written frames say where their time went (summary.json, render.parts_s).
    settings.time_parts = options.gpu_times && !options.window;
    renderer.emplace(settings, textures, sky_params(scene.view));
  });
  buffers.emplace(world.handle(), strategy, trees_to_draw(scene, ids.trees, *renderer),
                  meadows_to_draw(meadows), ids.mesh_trees);
  stats.in_place = buffers->maps_in_place();
}

void SceneRun::place_camera() {
  aspect = float(run.image_width) / float(run.image_height);
  camera = frame_camera(scene.view, buffers->geometry(), aspect);
  // The sway is followed for the trees nearest the camera (kSwayTrees of them).
  swaying.resize(ids.trees.size());
  for (size_t i = 0; i < swaying.size(); ++i) swaying[i] = i;
  if (swaying.size() > kSwayTrees) {
    std::nth_element(swaying.begin(), swaying.begin() + kSwayTrees, swaying.end(),
                     [&](size_t a, size_t b) { return distance2(a) < distance2(b); });
    swaying.resize(kSwayTrees);
  }
  // Their rest poses (before the first step), and no other tree's: a forest's every branch
  // would be 60 B x 3.7 million, 0.22 GB for forest.json (issue 39).
  rest.resize(ids.trees.size());
  for (size_t i : swaying) read_tree_pose(world, ids.trees[i], rest[i], false);
  now.resize(ids.trees.size());
  // The walk: from the view's eye to eye_end over the frames, the target moving alike.
  walk_start = camera.eye;
  look = camera.target - camera.eye;
  walk_end = scene.view.eye_end ? glm::vec3((*scene.view.eye_end)[0], (*scene.view.eye_end)[1],
                                            (*scene.view.eye_end)[2])
                                : walk_start;
  ground = scene_ground(scene, buffers->geometry());
}

void SceneRun::bake_impostors() {
  // From the trees as they stand before the first step; those the walk sees from far
  // enough, or every one in a window (its camera goes anywhere).
  std::vector<glm::vec3> eyes;
  if (!options.window) eyes = {walk_start, walk_end};
  if (renderer->settings().impostor_distance <= 0.0f) return;  // nothing to bake
  timed(times.impostors, [&] {
    buffers->update_at_rest();
    renderer->bake_impostors(buffers->rest_geometry(), eyes);
    glFinish();
    buffers->end_draw();
  });
}

void SceneRun::record_view_stats() {
  std::copy(&camera.eye.x, &camera.eye.x + 3, stats.eye);
  std::copy(&camera.target.x, &camera.target.x + 3, stats.target);
  stats.fov_deg = camera.fov_deg;
  stats.sun_elevation_deg = scene.view.sun_elevation_deg;
  stats.sun_azimuth_deg = scene.view.sun_azimuth_deg;
  stats.turbidity = scene.view.turbidity;
  stats.shadows = scene.view.shadows;
  stats.msaa = renderer->settings().msaa_samples;
  stats.exr = options.exr;
}

float SceneRun::distance2(size_t i) const {
  const float* p = scene.trees[i].def.position;
  return glm::dot(glm::vec3(p[0], p[1], p[2]) - camera.eye,
                  glm::vec3(p[0], p[1], p[2]) - camera.eye);
}

void SceneRun::walk(int frame) {
  if (!scene.view.eye_end) return;
  const float t = run.frames > 1 ? float(frame) / float(run.frames - 1) : 0.0f;
  camera.eye = walk_start + t * (walk_end - walk_start);
  camera.target = camera.eye + look;
}

void SceneRun::step_frame(FrameStats& frame) {
  // The camera is the world's focus: trees and underbrush take their levels of detail
  // from their distance to it.
  const float focus[3] = {camera.eye.x, camera.eye.y, camera.eye.z};
  boreas::check(boreas_world_set_focus(world.handle(), focus, 1));
  boreas_step_stats s = timed(times.wind_step, [&] {
    return step_scene(world, scene, run.steps_per_frame, run.dt, ids.lidars);
  });
  times.wind += s.wind;
  times.trees += s.trees;
  times.underbrush += s.underbrush;
  frame.time = world.get_time();
  frame.wind = s.wind;
  frame.trees = s.trees;
  frame.underbrush = s.underbrush;
  const boreas_step_stats last = world.get_step_stats();
  std::copy(last.trees_by_lod, last.trees_by_lod + 4, frame.trees_by_lod);
  std::copy(last.components_by_rate, last.components_by_rate + 4, frame.components_by_rate);
  frame.branches_stepped = last.branches_stepped;
  frame.branches_carried = last.branches_carried;
  frame.branches_broken = s.branches_broken;
  frame.has_lod = true;
  for (size_t i : swaying) {
    read_tree_pose(world, ids.trees[i], now[i], false);
    frame.max_sway = std::max(frame.max_sway, max_tip_offset(rest[i], now[i]));
  }
  if (!meadows.empty()) {
    read_meadows(world, meadows);
    frame.max_bend = max_bend(meadows);
  }
}

void SceneRun::draw_frame() {
  timed(times.interop, [&] { buffers->update(camera.eye, renderer->tree_view(camera, buffers->geometry())); });
  timed(times.render, [&] {
    cpu_timed(times.render_cpu, [&] {
      std::vector<glm::vec4> balls;
      for (const Ball& b : colliders_at(scene, world.get_time()))
        for (const glm::vec4& sphere : ball_spheres(b)) balls.push_back(sphere);
      buffers->set_balls(std::move(balls));
      renderer->draw(camera, buffers->geometry(), ground);
      glFinish();
    });
  });
}

void SceneRun::run_window() {
  WindowControls controls;
  controls.orbit = Orbit::around(camera);
  GLFWwindow* window = gl.window();
  InputAccumulator input;
  listen_to_window(window, &input);
  glfwShowWindow(window);
  int frame_index = 0;
  while (!glfwWindowShouldClose(window) && (!options.frames || frame_index < run.frames)) {
    glfwPollEvents();
    apply_input(input.take(glfwGetTime()), WindowRates{}, controls);
    if (controls.wind_changed) {
      apply_wind_controls(world, scene, controls);
      controls.wind_changed = false;
    }
    camera.eye = controls.orbit.eye();
    camera.target = controls.orbit.target;
    FrameStats frame;
    frame.index = frame_index++;
    step_frame(frame);
    glfwPollEvents();  // what came during the step is timed more closely
    draw_frame();
    int w = 0, h = 0;
    glfwGetFramebufferSize(window, &w, &h);
    renderer->present(w, h);
    glfwSwapBuffers(window);
    buffers->end_draw();
    summary.frames.push_back(frame);
  }
  glfwSetWindowUserPointer(window, nullptr);
}

void SceneRun::run_trails() {
  // One picture: the first frame, with the paths of a few branch and blade tips over the
  // whole run drawn on it through the first frame's camera (motion_trails.h). Later
  // frames are stepped, not drawn.
  const glm::mat4 view_proj = camera.view_projection(aspect);
  // The six nearest trees' tips: farther ones move by less than a pixel.
  std::vector<size_t> nearest = swaying;
  std::sort(nearest.begin(), nearest.end(),
            [&](size_t a, size_t b) { return distance2(a) < distance2(b); });
  if (nearest.size() > 6) nearest.resize(6);
  std::vector<MotionTrail> trails = choose_trails(rest, nearest, meadows, camera.eye, view_proj,
                                                  run.image_width, run.image_height);
  record_trails(trails, rest, meadows);  // at rest: where the paths start
  progress.emplace(run.frames, !options.quiet);
  std::optional<Image> picture;
  for (int index = 0; index < run.frames; ++index) {
    FrameStats frame;
    frame.index = index;
    step_frame(frame);
    if (index == 0) {
      draw_frame();
      std::vector<uint8_t> rgb = timed(times.readback, [&] { return renderer->read_rgb8(); });
      buffers->end_draw();
      picture = to_image(rgb, run.image_width, run.image_height);
    }
    record_trails(trails, now, meadows);
    summary.frames.push_back(frame);
    progress->update(index + 1);
  }
  timed(times.image_writing, [&] {
    draw_trails(*picture, trails, view_proj, world.get_time(), break_points(now));
    summary.trails = "trails.png";
    write_png((out_dir / summary.trails).string(), *picture);
  });
  for (const MotionTrail& t : trails) {
    (t.kind == MotionTrail::Kind::branch ? summary.branch_trails : summary.blade_trails) += 1;
  }
  print_gl_messages();
}

void SceneRun::run_files(AnimationFormat animation_format) {
  std::vector<int> sheet_frames = contact_sheet_frames(run.frames, kSheetTiles);
  std::vector<Image> sheet_images;
  std::unique_ptr<AnimationWriter> animation =
      open_animation(out_dir, animation_format, run.image_width, run.image_height, run.frames,
                     run.steps_per_frame * double(run.dt));
  progress.emplace(run.frames, !options.quiet);
  for (int index = 0; index < run.frames; ++index) {
    FrameStats frame;
    frame.index = index;
    frame.file = frame_file(index, run.frames);
    walk(index);
    step_frame(frame);
    timed(times.sensors, [&] { sensors->record(world, index); });
    draw_frame();
    std::vector<uint8_t> rgb = timed(times.readback, [&] { return renderer->read_rgb8(); });
    std::vector<float> hdr;
    if (options.exr) hdr = timed(times.readback, [&] { return renderer->read_hdr_rgb(); });
    buffers->end_draw();
    timed(times.image_writing, [&] {
      Image image = to_image(rgb, run.image_width, run.image_height);
      if (run.view == ViewMode::lidar) {
        draw_lidar_points(image, sensors->latest_points(), camera.view_projection(aspect));
        draw_lidar_legend(image);
        rgb = image.to_rgb8();
      }
      write_png((out_dir / frame.file).string(), image);
      if (options.exr) {
        write_exr((out_dir / frame_file(index, run.frames, ".exr")).string(), run.image_width,
                  run.image_height, hdr);
      }
      if (std::find(sheet_frames.begin(), sheet_frames.end(), index) != sheet_frames.end()) {
        sheet_images.push_back(std::move(image));
      }
    });
    if (animation) timed(times.animation, [&] { add_frame(*animation, rgb); });
    summary.frames.push_back(frame);
    progress->update(index + 1);
  }
  write_contact_sheet(sheet_frames, sheet_images);
  if (animation) {
    timed(times.animation, [&] { finish(*animation); });
    summary.animation = animation_file(animation_format);
  }
  print_gl_messages();
}

void SceneRun::write_contact_sheet(const std::vector<int>& sheet_frames,
                                   const std::vector<Image>& sheet_images) {
  timed(times.contact_sheet, [&] {
    std::vector<SheetTile> tiles;
    std::vector<std::string> labels;
    for (size_t i = 0; i < sheet_images.size(); ++i) {
      const FrameStats& f = summary.frames[size_t(sheet_frames[i])];
      char label[64];
      std::snprintf(label, sizeof label, "%d  T=%.2f S", f.index + 1, f.time);
      labels.push_back(label);
    }
    for (size_t i = 0; i < sheet_images.size(); ++i) tiles.push_back({&sheet_images[i], labels[i]});
    summary.contact_sheet = "contact_sheet.png";
    write_png((out_dir / summary.contact_sheet).string(),
              make_contact_sheet(tiles, kSheetColumns, kSheetTileWidth, scene.name));
  });
}

void SceneRun::print_gl_messages() {
  std::vector<std::string> messages = gl.take_messages();
  for (const std::string& m : messages) std::cerr << "boreas: OpenGL: " << m << "\n";
}

int SceneRun::report(std::chrono::steady_clock::time_point command_start) {
  summary.steps = (long long)summary.frames.size() * run.steps_per_frame;
  summary.sim_time = world.get_time();
  summary.state_hash = world.get_state_hash();
  stats.parts = renderer->part_seconds();
  // After the frames: the tree records' buffers are as large as the views needed.
  stats.interop_mb_per_frame = double(buffers->bytes_per_frame()) / 1e6;
  const uint32_t* counts = buffers->tree_counts();
  stats.tree_ranges = counts[BOREAS_TREE_INDIRECT_RANGES_WRITTEN];
  stats.tree_branches = counts[BOREAS_TREE_INDIRECT_BRANCH_COMMAND + 1];
  stats.tree_leaves = counts[BOREAS_TREE_INDIRECT_LEAF_COMMAND + 1];
  stats.tree_impostors = counts[BOREAS_TREE_INDIRECT_IMPOSTOR_COMMAND + 1];
  add_collider_stats(scene, summary);
  if (sensors) summary.sensors = sensors->stats();
  times.total =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - command_start).count();
  if (!options.window) write_summary((out_dir / "summary.json").string(), summary);
  char done[256];
  std::snprintf(done, sizeof done, "%d frames (%lld steps, %.2f s simulated) in %.2f s%s%s",
                int(summary.frames.size()), summary.steps, summary.sim_time, times.total,
                options.window ? "" : " -> ", options.window ? "" : out_dir.string().c_str());
  if (progress) {
    progress->finish(done);
  } else if (!options.quiet) {
    std::fprintf(stderr, "boreas: %s\n", done);
  }
  if (!options.quiet) {
    std::cout << "scene " << scene.name << " on " << summary.device.device_name << ", interop "
              << stats.interop << (stats.in_place ? " (in place)" : "") << "\n"
              << stage_line(times) << "\n";
  }
  return kExitOk;
}

}  // namespace

int run_scene_view(const Scene& scene, const RunOptions& options, AnimationFormat animation_format,
                   RunSummary& summary, std::chrono::steady_clock::time_point command_start) {
  const RunSettings& run = summary.run;
  StageTimes& times = summary.times;
  RenderStats& stats = summary.render;

  std::optional<interop::GlContext> gl;
  try {
    gl.emplace(
        interop::GlContextDef{run.image_width, run.image_height, options.window, "boreas", false});
  } catch (const interop::GlError& e) {
    throw CliError(kExitNoDevice, std::string("the 3D view needs OpenGL 4.5: ") + e.what() +
                                      " (or use --view slice, which needs none)");
  }
  stats.gl = gl->description();

  SceneIds ids;
  bool shares = false;
  boreas::World world = timed(
      times.world_create, [&] { return make_shared_world(scene, options, *gl, &ids, &shares); });
  summary.device = world.get_device();
  interop::Strategy strategy = options.interop == "auto"
                                   ? interop::choose_strategy({!summary.device.is_gpu, shares})
                                   : *interop::parse_strategy(options.interop);
  stats.interop = interop::strategy_name(strategy);
  stats.interop_choice = options.interop == "auto" ? "auto" : "requested";

  SceneRun r(scene, options, summary, *gl, world, ids);
  r.describe_plants();
  r.make_renderer(strategy);
  r.place_camera();
  r.bake_impostors();
  r.record_view_stats();
  // Only now that everything exists: a run that cannot start leaves the folder alone.
  r.out_dir = fs::path(options.out_dir);
  if (!options.window) {
    prepare_output(r.out_dir);
    r.sensors.emplace(scene, ids.lidars, r.out_dir, run.frames);
  }
  if (options.window) {
    r.run_window();
  } else if (run.view == ViewMode::trails) {
    r.run_trails();
  } else {
    r.run_files(animation_format);
  }
  return r.report(command_start);
}

}  // namespace boreas::render
