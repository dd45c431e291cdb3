// boreas views: the 3D view's draw lists, camera, ground and settings (scene_view.h).
#include "view/scene_view.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace boreas::render {

namespace {

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

std::vector<MeadowToDraw> meadows_to_draw(const FrameMeadows& meadows) {
  std::vector<MeadowToDraw> out;
  size_t at = 0;
  for (size_t m = 0; m < meadows.ids.size(); ++m) {
    MeadowToDraw d;
    d.id = meadows.ids[m];
    d.styles.reserve(size_t(meadows.counts[m]) * 6);
    for (int i = 0; i < meadows.counts[m]; ++i, ++at) {
      // The species file's look: its sRGB color as a linear albedo, and the light that
      // passes through as that albedo times the translucency.
      const boreas_meadow_part& look = meadows.looks[meadows.look_of[at]];
      glm::vec3 albedo(srgb_to_linear(look.color[0]), srgb_to_linear(look.color[1]),
                       srgb_to_linear(look.color[2]));
      glm::vec3 transmittance = albedo * look.translucency;
      d.styles.insert(d.styles.end(), {albedo.r, albedo.g, albedo.b, transmittance.r, transmittance.g, transmittance.b});
    }
    out.push_back(std::move(d));
  }
  return out;
}

std::vector<TreeToDraw> trees_to_draw(const Scene& scene, const std::vector<boreas_tree_id>& ids,
                                      const Renderer& renderer) {
  std::vector<TreeToDraw> out;
  for (size_t i = 0; i < ids.size(); ++i) {
    TreeToDraw t;
    t.id = ids[i];
    std::copy(scene.trees[i].def.levels, scene.trees[i].def.levels + 4, t.levels);
    t.leaf_layer = renderer.leaf_layer(scene.trees[i].leaf_kind);
    t.leaf_transmittance = renderer.leaf_transmittance(scene.trees[i].leaf_kind);
    const boreas_tree_def& def = scene.trees[i].def;
    t.model = scene.trees[i].species + "#" + std::to_string(def.seed) + "#" + scene.trees[i].leaf_kind;
    t.position = glm::vec3(def.position[0], def.position[1], def.position[2]);
    t.rotation = def.rotation;
    t.scale = def.scale;
    out.push_back(t);
  }
  return out;
}

std::vector<std::string> scene_leaf_kinds(const Scene& scene) {
  std::vector<std::string> kinds;
  for (const SceneTree& tree : scene.trees) {
    if (std::find(kinds.begin(), kinds.end(), tree.leaf_kind) == kinds.end())
      kinds.push_back(tree.leaf_kind);
  }
  return kinds;
}

Camera frame_camera(const SceneView& view, const FrameGeometry& g, float aspect) {
  Camera camera;
  camera.fov_deg = view.fov_deg;
  glm::vec3 lo = g.bounds_min, hi = g.bounds_max;
  glm::vec3 center = 0.5f * (lo + hi);
  camera.target = view.target ? glm::vec3((*view.target)[0], (*view.target)[1], (*view.target)[2])
                              : glm::vec3(center.x, lo.y + 0.3f * (hi.y - lo.y), center.z);
  if (view.eye) {
    camera.eye = glm::vec3((*view.eye)[0], (*view.eye)[1], (*view.eye)[2]);
    return camera;
  }
  float radius = 0.5f * glm::length(glm::vec2(hi.x - lo.x, hi.z - lo.z));
  float half_width = std::atan(std::tan(glm::radians(view.fov_deg) * 0.5f) * aspect);
  Orbit orbit;
  orbit.target = camera.target;
  orbit.yaw_deg = view.sun_azimuth_deg + 35.0f;
  orbit.pitch_deg = 14.0f;
  orbit.distance = std::max(2.0f, 0.85f * radius / std::tan(half_width));
  // And far enough back that the top of what is drawn stays in the frame (a lone tall tree
  // is higher than it is wide): the angle from the view's axis up to the top, seen from
  // the eye, within 90 % of the half field of view.
  const float pitch = glm::radians(orbit.pitch_deg), half_height = 0.9f * glm::radians(view.fov_deg) * 0.5f;
  const float above = hi.y - camera.target.y;
  for (int i = 0; i < 100; ++i) {
    float d = orbit.distance;
    if (std::atan2(above - d * std::sin(pitch), d * std::cos(pitch)) + pitch <= half_height) break;
    orbit.distance *= 1.05f;
  }
  camera.eye = orbit.eye();
  return camera;
}

Ground scene_ground(const Scene& scene, const FrameGeometry& g) {
  Ground ground;
  ground.y = scene.grid.origin[1];
  glm::vec3 center = 0.5f * (g.bounds_min + g.bounds_max);
  float reach = 20.0f * std::max({g.bounds_max.x - g.bounds_min.x, g.bounds_max.z - g.bounds_min.z, 50.0f});
  ground.rect = glm::vec4(center.x - reach, center.z - reach, center.x + reach, center.z + reach);
  for (const SceneMeadow& m : scene.meadows) {
    const boreas_meadow_def& d = m.def;
    ground.meadow_rects.emplace_back(d.center[0] - 0.5f * d.size[0], d.center[2] - 0.5f * d.size[1],
                                     d.center[0] + 0.5f * d.size[0], d.center[2] + 0.5f * d.size[1]);
  }
  return ground;
}

RenderSettings render_settings(const Scene& scene, const RunSettings& run) {
  RenderSettings settings;
  settings.width = run.image_width;
  settings.height = run.image_height;
  settings.shadow_map_size = scene.view.shadows ? 2048 : 0;
  settings.exposure = scene.view.exposure;
  settings.msaa_samples = scene.view.msaa;
  settings.thinning = scene.view.thinning;
  settings.bloom = scene.view.bloom;
  settings.light_shafts = scene.view.light_shafts;
  settings.impostor_distance = scene.view.impostor_distance;
  return settings;
}

SkyParams sky_params(const SceneView& view) {
  SkyParams sky;
  sky.turbidity = view.turbidity;
  sky.sun_elevation_deg = view.sun_elevation_deg;
  sky.sun_azimuth_deg = view.sun_azimuth_deg;
  return sky;
}

}  // namespace boreas::render
