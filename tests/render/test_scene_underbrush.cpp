// render tests: the scene's "meadows", "colliders" and "emitters" arrays: defaults, values,
// species files and images found next to the scene, and each kind of mistake caught with
// the file and the JSON path.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "scene/scene_error.h"
#include "scene/scene_loader.h"
#include "scene_error_for.h"

namespace boreas::render {
namespace {

namespace fs = std::filesystem;

using testing::error_for;

TEST(SceneUnderbrush, AbsentKeysTakeTheLibraryDefaults) {
  Scene scene =
      load_scene_text(R"({"meadows": [{}], "colliders": [{}], "emitters": [{}]})", "s.json");
  ASSERT_EQ(scene.meadows.size(), 1u);
  const SceneMeadow& meadow = scene.meadows[0];
  boreas_meadow_def d = boreas_default_meadow_def();
  EXPECT_TRUE(meadow.species.empty()) << "the library's default mix";
  EXPECT_TRUE(meadow.terrain_image.empty());
  EXPECT_TRUE(meadow.nutrient_image.empty());
  EXPECT_EQ(meadow.def.species, nullptr);  // set from the strings when the meadow is added
  EXPECT_EQ(meadow.def.terrain.pixels, nullptr);
  EXPECT_EQ(meadow.def.nutrients.pixels, nullptr);
  EXPECT_EQ(meadow.def.size[0], d.size[0]);
  EXPECT_EQ(meadow.def.size[1], d.size[1]);
  EXPECT_EQ(meadow.def.center[1], d.center[1]);
  EXPECT_EQ(meadow.def.density, d.density);
  EXPECT_EQ(meadow.def.seed, d.seed);
  EXPECT_EQ(meadow.def.terrain_relief, d.terrain_relief);
  EXPECT_EQ(meadow.def.seed_points, d.seed_points);
  EXPECT_EQ(meadow.def.shape_angles, d.shape_angles);
  EXPECT_EQ(meadow.def.shape_norms, d.shape_norms);
  EXPECT_EQ(meadow.def.lod_distances[2], d.lod_distances[2]);

  ASSERT_EQ(scene.colliders.size(), 1u);
  boreas_collider_def c = boreas_default_collider_def();
  EXPECT_EQ(scene.colliders[0].def.radius, c.radius);
  EXPECT_EQ(scene.colliders[0].def.pose.position[1], c.pose.position[1]);
  EXPECT_EQ(scene.colliders[0].def.velocity[0], 0.0f);

  ASSERT_EQ(scene.emitters.size(), 1u);
  boreas_emitter_def e = boreas_default_emitter_def();
  EXPECT_EQ(scene.emitters[0].rate, e.rate);
  EXPECT_EQ(scene.emitters[0].impulse[1], e.impulse[1]);
  EXPECT_EQ(scene.emitters[0].event_radius, e.event_radius);
  EXPECT_EQ(scene.emitters[0].seed, e.seed);

  Scene empty = load_scene_text("{}", "s.json");
  EXPECT_TRUE(empty.meadows.empty());
  EXPECT_TRUE(empty.colliders.empty());
  EXPECT_TRUE(empty.emitters.empty());
}

TEST(SceneUnderbrush, ValuesAreRead) {
  Scene scene = load_scene_text(R"({
    "meadows": [{"species": [{"species": "meadow_grass", "weight": 3}, {"species": "fern"}],
                 "center": [1, 2, 3], "size": [4, 5], "density": 50, "seed": 9,
                 "terrain_image": "ground.png", "terrain_relief": 0.5, "nutrient_image": null,
                 "seed_points": 64, "shape_angles": 7, "shape_norms": 8,
                 "lod_distances": [1, 2, 2]}],
    "colliders": [{"center": [0, 0.3, -2], "radius": 0.3, "velocity": [2, 0, 0.5]},
                  {"shape": "capsule", "center": [1, 0.9, 0], "radius": 0.25,
                   "half_height": 0.65, "orientation": [0, 0.6, 0, 0.8],
                   "angular_velocity": [0, 0.5, 0]},
                  {"shape": "box", "half_extents": [2.25, 0.75, 0.9], "velocity": [5, 0, 0]}],
    "emitters": [{"center": [1, 1, 1], "area_radius": 2, "event_radius": 0.1,
                  "impulse": [0, -0.001, 0], "rate": 10, "lifetime": 3, "seed": 4}]})",
                                "s.json");
  const SceneMeadow& m = scene.meadows[0];
  ASSERT_EQ(m.species.size(), 2u);
  EXPECT_EQ(m.species[0].species, "meadow_grass");
  EXPECT_EQ(m.species[0].weight, 3.0f);
  EXPECT_EQ(m.species[1].species, "fern");
  EXPECT_EQ(m.species[1].weight, 1.0f);
  EXPECT_EQ(m.def.center[2], 3.0f);
  EXPECT_EQ(m.def.size[1], 5.0f);
  EXPECT_EQ(m.def.density, 50.0f);
  EXPECT_EQ(m.def.seed, 9u);
  EXPECT_EQ(m.terrain_image, "ground.png");
  EXPECT_EQ(m.def.terrain_relief, 0.5f);
  EXPECT_TRUE(m.nutrient_image.empty());
  EXPECT_EQ(m.def.seed_points, 64);
  EXPECT_EQ(m.def.shape_angles, 7);
  EXPECT_EQ(m.def.shape_norms, 8);
  EXPECT_EQ(m.def.lod_distances[1], 2.0f);

  const SceneCollider& c = scene.colliders[0];
  EXPECT_EQ(c.def.pose.position[2], -2.0f);
  EXPECT_EQ(c.def.radius, 0.3f);
  EXPECT_EQ(c.def.velocity[0], 2.0f);
  EXPECT_EQ(c.def.velocity[2], 0.5f);
  EXPECT_EQ(c.def.shape, BOREAS_COLLIDER_SPHERE);
  const boreas_collider_def& capsule = scene.colliders[1].def;
  EXPECT_EQ(capsule.shape, BOREAS_COLLIDER_CAPSULE);
  EXPECT_EQ(capsule.half_height, 0.65f);
  EXPECT_EQ(capsule.pose.orientation[1], 0.6f);
  EXPECT_EQ(capsule.pose.orientation[3], 0.8f);
  EXPECT_EQ(capsule.angular_velocity[1], 0.5f);
  const boreas_collider_def& box = scene.colliders[2].def;
  EXPECT_EQ(box.shape, BOREAS_COLLIDER_BOX);
  EXPECT_EQ(box.half_extents[0], 2.25f);
  EXPECT_EQ(box.half_extents[2], 0.9f);
  EXPECT_EQ(box.velocity[0], 5.0f);
  EXPECT_EQ(box.pose.orientation[3], 1.0f) << "the default orientation";

  const boreas_emitter_def& e = scene.emitters[0];
  EXPECT_EQ(e.area_radius, 2.0f);
  EXPECT_EQ(e.event_radius, 0.1f);
  EXPECT_EQ(e.impulse[1], -0.001f);
  EXPECT_EQ(e.rate, 10.0f);
  EXPECT_EQ(e.lifetime, 3.0f);
  EXPECT_EQ(e.seed, 4u);
}

TEST(SceneUnderbrush, FilesAreFoundNextToTheScene) {
  Scene scene = load_scene_text(
      R"({"meadows": [{"species": [{"species": "my/moss.json"}, {"species": "clover"}],
                       "terrain_image": "../maps/hills.png", "nutrient_image": "/abs/soil.exr"}]})",
      "s.json", "/data/scenes");
  const SceneMeadow& m = scene.meadows[0];
  EXPECT_EQ(m.species[0].species, "/data/scenes/my/moss.json");
  EXPECT_EQ(m.species[1].species, "clover") << "built-in names stay names";
  EXPECT_EQ(m.terrain_image, "/data/maps/hills.png");
  EXPECT_EQ(m.nutrient_image, "/abs/soil.exr");
  // Without a folder (text, the built-in scene) paths stay relative to the working folder.
  EXPECT_EQ(load_scene_text(R"({"meadows": [{"terrain_image": "h.png"}]})", "s.json")
                .meadows[0]
                .terrain_image,
            "h.png");
  // A file on disk: its folder.
  fs::path dir = fs::temp_directory_path() / ("boreas_scene_meadows_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream(dir / "scene.json")
        << R"({"meadows": [{"species": [{"species": "sp/moss.json"}], "terrain_image": "h.png"}]})";
  }
  Scene from_file = load_scene_file((dir / "scene.json").string());
  EXPECT_EQ(from_file.meadows[0].species[0].species, (dir / "sp" / "moss.json").string());
  EXPECT_EQ(from_file.meadows[0].terrain_image, (dir / "h.png").string());
  fs::remove_all(dir);
}

TEST(SceneUnderbrush, DefaultSceneHasMeadowsWithFlowersARollingBallAndRain) {
  Scene scene = load_default_scene();
  ASSERT_GE(scene.meadows.size(), 1u);
  ASSERT_GE(scene.colliders.size(), 1u);
  EXPECT_GE(scene.emitters.size(), 1u);
  const boreas_grid_def& g = scene.grid;
  for (const SceneMeadow& m : scene.meadows) {
    for (int a : {0, 2}) {
      int s = a == 0 ? 0 : 1;
      EXPECT_GE(m.def.center[a] - 0.5f * m.def.size[s], g.origin[a]) << "inside the grid";
      EXPECT_LE(m.def.center[a] + 0.5f * m.def.size[s],
                g.origin[a] + g.cell_size * float(g.resolution[a]));
    }
    EXPECT_EQ(m.def.center[1], g.origin[1]) << "on the ground";
    // Not inside a building.
    for (const SolidBox& box : scene.obstacles) {
      bool overlaps = m.def.center[0] + 0.5f * m.def.size[0] > box.min[0] &&
                      m.def.center[0] - 0.5f * m.def.size[0] < box.max[0] &&
                      m.def.center[2] + 0.5f * m.def.size[1] > box.min[2] &&
                      m.def.center[2] - 0.5f * m.def.size[1] < box.max[2];
      EXPECT_FALSE(overlaps);
    }
  }
  // The ball rolls along the ground, starting in the first meadow, and stays in it for the run.
  const SceneCollider& ball = scene.colliders[0];
  const boreas_meadow_def& first = scene.meadows[0].def;
  EXPECT_GT(std::hypot(ball.def.velocity[0], ball.def.velocity[2]), 0.5f);
  EXPECT_EQ(ball.def.velocity[1], 0.0f);
  EXPECT_EQ(ball.def.pose.position[1], ball.def.radius) << "resting on flat ground";
  double duration = double(scene.run.frames) * scene.run.steps_per_frame * scene.run.dt;
  for (double t : {0.0, duration}) {
    EXPECT_LE(std::fabs(ball.def.pose.position[0] + ball.def.velocity[0] * t - first.center[0]),
              0.5 * first.size[0])
        << t;
    EXPECT_LE(std::fabs(ball.def.pose.position[2] + ball.def.velocity[2] * t - first.center[2]),
              0.5 * first.size[1])
        << t;
  }
  // At least 100k components asked for (the issue's floor; render/SCENES.md gives the count
  // planted: fewer, where the ground and the spacing allow), and not so many that the demo
  // leaves its minute (the dense patch in front of the camera asks for 84,000).
  double components = 0.0;
  for (const SceneMeadow& m : scene.meadows) {
    components += double(m.def.size[0]) * m.def.size[1] * m.def.density;
  }
  EXPECT_GE(components, 100000.0);
  EXPECT_LE(components, 200000.0);
  // Grass, clover, flowers and ferns all grow somewhere.
  std::set<std::string> species;
  for (const SceneMeadow& m : scene.meadows) {
    if (m.species.empty()) species.insert(default_meadow_mix().begin(), default_meadow_mix().end());
    for (const SceneMeadowSpecies& s : m.species) species.insert(s.species);
  }
  for (const char* name : {"meadow_grass", "clover", "daisy", "fern"}) {
    EXPECT_EQ(species.count(name), 1u) << name;
  }
}

struct Mistake {
  const char* label;
  const char* members;
  const char* where;
  const char* detail;  // the start of the message after the place
};

TEST(SceneUnderbrush, MistakesAreReportedWithTheirPath) {
  const Mistake cases[] = {
      {"MeadowsNotAnArray", R"("meadows": {})", "/meadows",
       "expected an array of objects, got an object"},
      {"MeadowNotAnObject", R"("meadows": [3])", "/meadows/0",
       "expected an object, got a number (3)"},
      {"UnknownMeadowKey", R"("meadows": [{"densty": 3}])", "/meadows/0/densty",
       "unknown key; did you mean \"density\"?"},
      {"SpeciesNotAnArray", R"("meadows": [{"species": "clover"}])", "/meadows/0/species",
       "expected an array of objects, got a string (\"clover\")"},
      {"EmptySpecies", R"("meadows": [{"species": []}])", "/meadows/0/species",
       "must list at least one species; leave it out for the default mix"},
      {"MissingSpeciesName", R"("meadows": [{"species": [{"weight": 2}]}])",
       "/meadows/0/species/0/species", "missing: a species mix entry needs a species"},
      {"SpeciesTypo", R"("meadows": [{}, {"species": [{"species": "clovr"}]}])",
       "/meadows/1/species/0/species",
       "unknown underbrush species \"clovr\"; did you mean \"clover\"?"},
      {"TreeSpeciesInAMeadow", R"("meadows": [{"species": [{"species": "quaking_aspen"}]}])",
       "/meadows/0/species/0/species",
       "unknown underbrush species \"quaking_aspen\"; the built-in species are"},
      {"ZeroWeight", R"("meadows": [{"species": [{"species": "fern", "weight": 0}]}])",
       "/meadows/0/species/0/weight", "must be > 0 (got 0)"},
      {"TooManySpecies",
       R"("meadows": [{"species": [{"species": "fern"}, {"species": "fern"}, {"species": "fern"},
           {"species": "fern"}, {"species": "fern"}, {"species": "fern"}, {"species": "fern"},
           {"species": "fern"}, {"species": "fern"}, {"species": "fern"}, {"species": "fern"},
           {"species": "fern"}, {"species": "fern"}, {"species": "fern"}, {"species": "fern"},
           {"species": "fern"}, {"species": "fern"}]}])",
       "/meadows/0/species", "at most 16 entries are allowed (got 17)"},
      {"ShortSize", R"("meadows": [{"size": [3]}])", "/meadows/0/size",
       "expected an array of 2 numbers, got an array of 1"},
      {"TinySize", R"("meadows": [{"size": [3, 0]}])", "/meadows/0/size/1",
       "must be >= 0.01 (got 0)"},
      {"NegativeDensity", R"("meadows": [{"density": -1}])", "/meadows/0/density",
       "must be >= 0 (got -1)"},
      {"TooManyComponents", R"("meadows": [{"size": [1000, 1000], "density": 100}])",
       "/meadows/0/density", "gives size[0] * size[1] * density = 1e+08 components; at most"},
      {"SeedNotAnInteger", R"("meadows": [{"seed": 1.5}])", "/meadows/0/seed",
       "must be an integer (got 1.5)"},
      {"ImageNotAString", R"("meadows": [{"terrain_image": 3}])", "/meadows/0/terrain_image",
       "expected a string or null, got a number (3)"},
      {"EmptyImage", R"("meadows": [{"nutrient_image": ""}])", "/meadows/0/nutrient_image",
       "must be a file name, or null for the procedural one"},
      {"HighRelief", R"("meadows": [{"terrain_relief": 2e4}])", "/meadows/0/terrain_relief",
       "must be <= 10000 (got 20000)"},
      {"ZeroSeedPoints", R"("meadows": [{"seed_points": 0}])", "/meadows/0/seed_points",
       "must be >= 1 (got 0)"},
      {"FewShapeAngles", R"("meadows": [{"shape_angles": 2}])", "/meadows/0/shape_angles",
       "must be >= 3 (got 2)"},
      {"ManyShapeNorms", R"("meadows": [{"shape_norms": 300}])", "/meadows/0/shape_norms",
       "must be <= 256 (got 300)"},
      {"DecreasingLod", R"("meadows": [{"lod_distances": [10, 5, 20]}])",
       "/meadows/0/lod_distances/1", "must be >= lod_distances/0 = 10 (got 5)"},
      {"CollidersNotAnArray", R"("colliders": 1)", "/colliders",
       "expected an array of objects, got a number (1)"},
      {"ZeroRadius", R"("colliders": [{"radius": 0}])", "/colliders/0/radius",
       "must be >= 0.001 (got 0)"},
      {"VelocityTooShort", R"("colliders": [{}, {"velocity": [1, 0]}])", "/colliders/1/velocity",
       "expected an array of 3 numbers, got an array of 2"},
      {"VelocityNotANumber", R"("colliders": [{"velocity": [1, "0", 0]}])",
       "/colliders/0/velocity/1", "expected a number, got a string (\"0\")"},
      {"FastBall", R"("colliders": [{"velocity": [2000, 0, 0]}])", "/colliders/0/velocity/0",
       "must be <= 1000 (got 2000)"},
      {"UnknownColliderKey", R"("colliders": [{"speed": [1, 0, 0]}])", "/colliders/0/speed",
       "unknown key; known keys: angular_velocity center half_extents half_height orientation "
       "radius shape velocity"},
      {"UnknownShape", R"("colliders": [{"shape": "cone"}])", "/colliders/0/shape",
       "must be one of sphere, capsule, box"},
      {"LongQuaternion", R"("colliders": [{"orientation": [0, 0, 0, 1.5]}])",
       "/colliders/0/orientation", "must be a unit quaternion x, y, z, w"},
      {"ShortQuaternion", R"("colliders": [{"orientation": [0, 0, 1]}])",
       "/colliders/0/orientation", "expected an array of 4 numbers, got an array of 3"},
      {"NegativeHalfExtent", R"("colliders": [{"shape": "box", "half_extents": [1, -1, 1]}])",
       "/colliders/0/half_extents/1", "must be >= 0.001 (got -1)"},
      {"NegativeHalfHeight", R"("colliders": [{"half_height": -0.5}])", "/colliders/0/half_height",
       "must be >= 0 (got -0.5)"},
      {"FastSpin", R"("colliders": [{"angular_velocity": [0, 0, 1e4]}])",
       "/colliders/0/angular_velocity/2", "must be <= 1000 (got 10000)"},
      {"ZeroEventRadius", R"("emitters": [{"event_radius": 0}])", "/emitters/0/event_radius",
       "must be >= 0.0001 (got 0)"},
      {"NegativeRate", R"("emitters": [{"rate": -5}])", "/emitters/0/rate",
       "must be >= 0 (got -5)"},
      {"NegativeLifetime", R"("emitters": [{"lifetime": -1}])", "/emitters/0/lifetime",
       "must be >= 0 (got -1)"},
      {"NegativeArea", R"("emitters": [{"area_radius": -1}])", "/emitters/0/area_radius",
       "must be >= 0 (got -1)"},
      {"UnknownEmitterKey", R"("emitters": [{"impulses": [0, 0, 0]}])", "/emitters/0/impulses",
       "unknown key; did you mean \"impulse\"?"},
      {"MisspeltArray", R"("meadow": [])", "/meadow", "unknown key; did you mean \"meadows\"?"},
  };
  for (const Mistake& m : cases) {
    SCOPED_TRACE(m.label);
    SceneError e = error_for("{" + std::string(m.members) + "}", "scenes");
    EXPECT_EQ(e.source(), "s.json");
    EXPECT_EQ(e.where(), m.where);
    EXPECT_EQ(e.detail().rfind(m.detail, 0), 0u) << e.detail();
  }
}

}  // namespace
}  // namespace boreas::render
