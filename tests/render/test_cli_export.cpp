// render tests: `boreas export-mesh` end to end: each format written and read back, with as
// many vertices as boreas_tree_get_mesh reports for the same tree (plus four per leaf), and
// the ways it fails: a bad species (the library's message), a bad extension, no half files.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "boreas/boreas.hpp"
#include "command_runner.h"
#include "test_scenes.h"

namespace boreas::render::testing {
namespace {

namespace fs = std::filesystem;

struct LibraryCounts {
  size_t vertices = 0;
  size_t triangles = 0;
  size_t leaves = 0;
};

// What the library reports for the tree export-mesh grows (the topology does not change as
// the tree bends, so a fresh, unstepped tree has the same counts).
LibraryCounts library_counts(const std::string& species, uint64_t seed) {
  boreas::World world;
  boreas_tree_def def = boreas_default_tree_def();
  def.species = species.c_str();
  def.seed = seed;
  boreas_tree_id tree = world.add_tree(def);
  int vertices = 0;
  int indices = 0;
  boreas::check(
      boreas_tree_get_mesh(world.handle(), tree, nullptr, 0, &vertices, nullptr, 0, &indices));
  int leaves = 0;
  boreas::check(boreas_tree_get_leaves(world.handle(), tree, nullptr, 0, &leaves));
  return {size_t(vertices), size_t(indices) / 3, size_t(leaves)};
}

size_t count_lines(const std::string& text, const std::string& prefix) {
  size_t n = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) n += line.rfind(prefix, 0) == 0;
  return n;
}

TEST(CliExport, EachFormatReadsBackWithTheLibrarysCounts) {
  LibraryCounts expected = library_counts("quaking_aspen", 7);
  ASSERT_GT(expected.vertices, 0u);
  ASSERT_GT(expected.leaves, 0u);
  size_t vertices = expected.vertices + 4 * expected.leaves;
  size_t triangles = expected.triangles + 2 * expected.leaves;

  TempDir dir;
  for (const char* name : {"tree.obj", "tree.ply", "tree.glb"}) {
    SCOPED_TRACE(name);
    CommandResult r = run_boreas(
        std::string("export-mesh --species quaking_aspen --seed 7 --time 0.25 --out out/") + name,
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("wrote out/" + std::string(name)), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("15 steps, 0.250 s simulated"), std::string::npos) << r.err;
    fs::path file = dir.path() / "out" / name;
    ASSERT_TRUE(fs::is_regular_file(file));

    if (file.extension() == ".obj") {
      std::string obj = read_text(file);
      EXPECT_EQ(count_lines(obj, "v "), vertices);
      EXPECT_EQ(count_lines(obj, "vn "), vertices);
      EXPECT_EQ(count_lines(obj, "vt "), vertices);
      EXPECT_EQ(count_lines(obj, "f "), triangles);
      EXPECT_EQ(count_lines(obj, "g branches"), 1u);
      EXPECT_EQ(count_lines(obj, "g leaves"), 1u);
      // The last face names the last vertex of all.
      size_t last_face = obj.rfind("\nf ");
      std::string tail = obj.substr(last_face);
      EXPECT_NE(tail.find(" " + std::to_string(vertices) + "/"), std::string::npos) << tail;
    } else if (file.extension() == ".ply") {
      std::string ply = read_text(file);
      std::string header = ply.substr(0, ply.find("end_header\n"));
      EXPECT_NE(header.find("element vertex " + std::to_string(vertices) + "\n"),
                std::string::npos)
          << header;
      EXPECT_NE(header.find("element face " + std::to_string(triangles) + "\n"),
                std::string::npos)
          << header;
      size_t body = ply.size() - header.size() - std::string("end_header\n").size();
      EXPECT_EQ(body, vertices * 32 + triangles * 13);
    } else {
      tinygltf::TinyGLTF loader;
      tinygltf::Model model;
      std::string error;
      std::string warning;
      ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, file.string())) << error;
      ASSERT_EQ(model.meshes.size(), 2u);
      const tinygltf::Primitive& branches = model.meshes[0].primitives.at(0);
      const tinygltf::Primitive& leaves = model.meshes[1].primitives.at(0);
      for (const char* attribute : {"POSITION", "NORMAL", "TEXCOORD_0"}) {
        EXPECT_EQ(model.accessors[size_t(branches.attributes.at(attribute))].count,
                  expected.vertices)
            << attribute;
        EXPECT_EQ(model.accessors[size_t(leaves.attributes.at(attribute))].count,
                  4 * expected.leaves)
            << attribute;
      }
      EXPECT_EQ(model.accessors[size_t(branches.indices)].count, 3 * expected.triangles);
      EXPECT_EQ(model.accessors[size_t(leaves.indices)].count, 6 * expected.leaves);
      const tinygltf::Accessor& position =
          model.accessors[size_t(branches.attributes.at("POSITION"))];
      ASSERT_EQ(position.minValues.size(), 3u);
      ASSERT_EQ(position.maxValues.size(), 3u);
      // The default scene's grid covers the origin: the tree stands there, on the ground,
      // and is taller than it is wide.
      EXPECT_LT(position.minValues[1], 0.5);
      EXPECT_GT(position.maxValues[1], 5.0);
      EXPECT_LT(position.minValues[0], 0.0);
      EXPECT_GT(position.maxValues[0], 0.0);
    }
  }
  // Written through temporary files renamed into place: nothing else is left.
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir.path() / "out")) {
    files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"tree.glb", "tree.obj", "tree.ply"}));
}

TEST(CliExport, BadSpeciesGivesTheLibrarysMessage) {
  TempDir dir;
  CommandResult r = run_boreas("export-mesh --species baobab --out tree.obj", dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err.rfind("boreas: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("unknown species 'baobab'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("quaking_aspen"), std::string::npos) << "lists the built-in ones";
  EXPECT_FALSE(fs::exists(dir.path() / "tree.obj"));
}

TEST(CliExport, BadSpeciesFileNamesFileAndLine) {
  TempDir dir;
  dir.write("bad.json", bad_species_json());
  CommandResult r = run_boreas("export-mesh --species bad.json --out tree.ply", dir);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("bad.json:5: parameter 'Levels'"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "tree.ply"));
}

TEST(CliExport, BadOptionsFailBeforeAnyWork) {
  TempDir dir;
  struct Case {
    const char* args;
    const char* expected;
  };
  for (const Case& c :
       {Case{"export-mesh --out tree.stl",
             "--out: tree.stl: unknown mesh format '.stl' (expected .obj, .ply or .glb)"},
        Case{"export-mesh --out t.obj --time -1", "--time: must be in [0, 100000] s (got -1)"},
        Case{"export-mesh --out t.obj --seed -3", "--seed: must be a whole number"}}) {
    CommandResult r = run_boreas(c.args, dir);
    EXPECT_EQ(r.exit_code, 1) << c.args;
    EXPECT_EQ(r.err.rfind("boreas: error: ", 0), 0u) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << ": " << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir.path() / ".stdout"));
}

}  // namespace
}  // namespace boreas::render::testing
