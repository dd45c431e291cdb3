// boreas scenes: what a scene file describes, as plain structs the loader fills in and the
// boreas command turns into a world. Units and defaults are listed in render/SCENES.md.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "boreas/boreas.h"
#include "scene/scene_sensors.h"

namespace boreas::render {

// An axis-aligned obstacle; every grid cell whose center lies inside becomes solid.
struct SolidBox {
  float min[3] = {0.0f, 0.0f, 0.0f};  // m
  float max[3] = {0.0f, 0.0f, 0.0f};  // m
};

// Limits of the run settings, shared by the scene loader and the command line (dt: the
// library's BOREAS_STEP_MAX_SECONDS).
constexpr int kMaxFrames = 100000;
constexpr int kMaxStepsPerFrame = 100000;
constexpr int kMinImageSide = 16;    // pixels
constexpr int kMaxImageSide = 4096;  // pixels; a 4096x4096 frame already takes ~600 MB

// What `boreas run` draws: the scene in 3D through the OpenGL renderer (the main job), or
// the older top view of a horizontal wind slice with trees and meadows (a wind diagnostic).
// lidar: the 3D view with the LiDARs' latest sweeps drawn over it, colored by surface.
enum class ViewMode { scene, slice, trails, lidar };

// How `boreas run` films the scene; command-line options override these.
struct RunSettings {
  int frames = 24;
  int steps_per_frame = 4;
  float dt = 1.0f / 24.0f;    // s per step
  float slice_height = 2.0f;  // m; the loader puts it 2 m above the grid floor unless given
  int image_width = 384;      // pixels
  int image_height = 384;     // pixels
  float color_max = 0.0f;     // m/s at the top of the color map; 0 picks it from the scene
  ViewMode view = ViewMode::scene;
};

// Limits of the scene's arrays. Meadows have none below what an int counts (the world
// refuses, naming the sizes, what the device cannot hold). Trees, the scene's own and its
// forests' together, stop at 2^20: a hundred times the 10,000 trees boreas is built for
// (bench/RESULTS.md), some 10 GB of world state; the loader holds about 200 bytes a tree,
// so that a forest's "count" cannot make it plant gigabytes before any world exists.
constexpr int kMaxTrees = 1048576;
constexpr int kMaxMeadows = 2147483647;

// What load_scene_text lets a scene ask for. The defaults are the limits above; the fuzzer
// passes fewer trees, so that every input loads in milliseconds under its sanitizers.
struct SceneLimits {
  int trees = kMaxTrees;  // the scene's own and its forests' together, at most kMaxTrees
};
constexpr int kMaxMeshTrees = 256;
constexpr int kMaxColliders = 1024;
constexpr int kMaxEmitters = 1024;

// A tree the world grows (the scene's "trees" array). def holds the library's defaults
// with the scene's values; def.species is left null and set from species when the tree is
// added, so a Scene can be copied freely.
struct SceneTree {
  // A built-in species name, or a species file (.xml or .json) with a relative path
  // already resolved against the scene file's folder.
  std::string species;
  // Which drawn leaf its leaves wear (render/textures/leaf_kinds.h): the scene's "leaf", or
  // the species' own kind (broadleaf for a species without one).
  std::string leaf_kind = "broadleaf";
  boreas_tree_def def = boreas_default_tree_def();
};

// A stand of trees the loader plants (the scene's "forests" array), expanded into trees:
// `count` trees over a rectangle, on a jittered lattice, of the species mix by weight,
// each species grown from `templates` seeds (trees of one species and seed share one model
// in the world), every tree turned and scaled at random (fixed by `seed`).
struct SceneForest {
  std::vector<std::pair<std::string, float>> species;  // resolved names or files, weights
  int count = 0;
  float center[3] = {0.0f, 0.0f, 0.0f};  // m
  float size[2] = {100.0f, 100.0f};      // m along x and z
  int templates = 20;
  uint64_t seed = 1;
  float scale[2] = {0.85f, 1.15f};  // the range of the trees' scales
  boreas_tree_def def = boreas_default_tree_def();  // mode, response, lod_distances
};

// An imported tree (the scene's "mesh_trees" array): a model made elsewhere, animated by
// the world's wind (Kusternig sec. 5). def holds the library's defaults with the scene's
// values; its strings are set from the members when the tree is added.
struct SceneMeshTree {
  std::string model;  // path, resolved against the scene file's folder
  std::optional<std::string> trunk_part, leaves_part;
  boreas_mesh_tree_def def = boreas_default_mesh_tree_def();
};

// One entry of a meadow's species mix.
struct SceneMeadowSpecies {
  // A built-in underbrush species name, or a species file (.json) with a relative path
  // already resolved against the scene file's folder.
  std::string species;
  float weight = 1.0f;  // > 0: its share of the plants
};

// A meadow the world plants (the scene's "meadows" array). def holds the library's defaults
// with the scene's values; its pointers (species, terrain, nutrients) are left null and set
// when the meadow is added (images are read then, scene/ground_image.h), so a Scene can be
// copied.
struct SceneMeadow {
  std::vector<SceneMeadowSpecies> species;  // empty: the library's default mix
  std::string terrain_image;                // "": procedural ground; paths resolved
  std::string nutrient_image;               // "": procedural nutrients
  boreas_meadow_def def = boreas_default_meadow_def();
};

// The built-in species of the library's default mix (species NULL), in its order
// (boreas_meadow_def: "grass, clover, daisies"), so components' species indices can be named.
inline const std::vector<std::string>& default_meadow_mix() {
  static const std::vector<std::string> names = {"meadow_grass", "clover", "daisy"};
  return names;
}

// A sphere, capsule or box that pushes plants aside (boreas_collider_def, velocities
// included): the world moves it by its velocity and angular velocity each step.
struct SceneCollider {
  boreas_collider_def def = boreas_default_collider_def();
};

// How the 3D view films the scene (the scene file's "view" object). Unset positions are
// chosen from the scene's content by the command (render/cli).
struct SceneView {
  std::optional<std::array<float, 3>> eye;     // m: the camera
  std::optional<std::array<float, 3>> target;  // m: where it looks
  // m: where the camera has walked to by the last frame (from eye, in a straight line, the
  // target moving with it); unset: it stands still.
  std::optional<std::array<float, 3>> eye_end;
  float fov_deg = 50.0f;                       // vertical field of view, [5, 150]
  float sun_elevation_deg = 40.0f;             // above the horizon, [-90, 90]
  float sun_azimuth_deg = 210.0f;              // in XZ from +X toward +Z, any finite value
  float turbidity = 3.0f;                      // Preetham's, [1.7, 10]
  float exposure = 1.0f;                       // (0, 1000]: multiplies the automatic one
  bool shadows = true;
  int msaa = 4;  // samples per pixel, 1..16 (1: none); capped at what the driver offers
  bool thinning = true;  // RenderSettings::thinning
  float bloom = 0.04f;   // RenderSettings::bloom, 0..1
  float light_shafts = 1.0f;  // RenderSettings::light_shafts, 0..100
  float impostor_distance = 80.0f;  // m, RenderSettings::impostor_distance, 0 (never)..1e5
};

struct Scene {
  std::string name = "unnamed";
  std::string source;  // the file, for errors raised once the world is built
  std::string description;
  std::optional<std::string> device;  // unset: the best device (or BOREAS_DEVICE)
  boreas_grid_def grid = boreas_default_grid_def();
  std::vector<boreas_wave> waves;
  std::vector<boreas_flow_primitive_def> primitives;
  std::vector<boreas_gust_def> gusts;
  std::vector<SolidBox> obstacles;
  std::vector<SceneTree> trees;
  std::vector<SceneMeshTree> mesh_trees;
  std::vector<SceneMeadow> meadows;
  std::vector<SceneCollider> colliders;
  std::vector<boreas_emitter_def> emitters;
  std::vector<SceneSensor> sensors;  // scene_sensors.h
  RunSettings run;
  SceneView view;
};

}  // namespace boreas::render
