// render tests: `boreas blobtree` end to end — each format written with the library's
// counts for the same tree and def, progress on stderr, and its refusals (bad cut or scar
// text, a branch the tree does not have, an unknown junction kind), which write nothing.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <fstream>
#include <sstream>

#include "boreas/boreas.hpp"
#include "command_runner.h"

namespace boreas::render::testing {
namespace {

namespace fs = std::filesystem;

size_t count_lines(const std::string& text, const std::string& prefix) {
  size_t n = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) n += line.rfind(prefix, 0) == 0;
  return n;
}

TEST(CliBlobTree, EachFormatHoldsTheLibrarysMesh) {
  boreas::World world;
  boreas_tree_def tree_def = boreas_default_tree_def();
  tree_def.seed = 4;
  boreas_tree_id tree = world.add_tree(tree_def);
  boreas_blobtree_def def = boreas_default_blobtree_def();
  def.resolution = 64;
  boreas_blobtree_cut cut{0, 0.5f};
  def.cuts = &cut;
  def.cut_count = 1;
  boreas_blobtree_info info = world.blobtree_get_info(world.add_blobtree(tree, def));
  ASSERT_GT(info.triangles, 0);

  TempDir dir;
  for (const char* name : {"tree.ply", "tree.obj", "tree.glb"}) {
    SCOPED_TRACE(name);
    CommandResult r = run_boreas(
        std::string(
            "blobtree --species quaking_aspen --seed 4 --resolution 64 --cut 0:0.5 --out out/") +
            name,
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("wrote out/" + std::string(name)), std::string::npos) << r.out;
    EXPECT_NE(r.err.find("polygonized " + std::to_string(info.primitives) + " primitives"),
              std::string::npos)
        << r.err;
    fs::path file = dir.path() / "out" / name;
    std::ifstream in(file, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (file.extension() == ".ply") {
      EXPECT_NE(text.find("element vertex " + std::to_string(info.vertices) + "\n"),
                std::string::npos);
      EXPECT_NE(text.find("element face " + std::to_string(info.triangles) + "\n"),
                std::string::npos);
    } else if (file.extension() == ".obj") {
      EXPECT_EQ(count_lines(text, "v "), size_t(info.vertices));
      EXPECT_EQ(count_lines(text, "vn "), size_t(info.vertices));
      EXPECT_EQ(count_lines(text, "f "), size_t(info.triangles));
    } else {
      tinygltf::TinyGLTF loader;
      tinygltf::Model model;
      std::string error, warning;
      ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, file.string())) << error;
      ASSERT_GE(model.meshes.size(), 1u);
      const tinygltf::Primitive& bark = model.meshes[0].primitives.at(0);
      EXPECT_EQ(model.accessors[size_t(bark.attributes.at("POSITION"))].count,
                size_t(info.vertices));
      EXPECT_EQ(model.accessors[size_t(bark.indices)].count, size_t(3 * info.triangles));
    }
  }
}

TEST(CliBlobTree, BadOptionsFailCleanlyAndWriteNothing) {
  TempDir dir;
  struct Case {
    const char* args;
    int exit_code;
    const char* message;
  };
  for (const Case& c : {
           Case{"--cut 3", 1, "--cut: '3' is not BRANCH:AT"},
           Case{"--cut x:0.5", 1, "--cut: 'x:0.5' is not BRANCH:AT"},
           Case{"--cut 1.5:0.5", 1, "the branch must be a whole number"},
           Case{"--scar 2:0.1:0.5:9", 1, "--scar: '2:0.1:0.5:9' is not"},
           Case{"--cut 99999:0.5", 1, "cuts[0].branch: 99999 is not a branch of this tree"},
           Case{"--scar 0:0.1", 1, "the trunk cannot be lost"},
           Case{"--junctions smooth", 1, "--junctions: must be pcm or blend"},
           Case{"--resolution 8", 1, "resolution must be 16..1024"},
           Case{"--ridge 0.9", 1, "ridge must be 0..0.45"},
       }) {
    SCOPED_TRACE(c.args);
    CommandResult r = run_boreas(std::string("blobtree --out tree.ply ") + c.args, dir);
    EXPECT_EQ(r.exit_code, c.exit_code) << r.err;
    EXPECT_EQ(r.err.rfind("boreas: error: ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "tree.ply"));
  }
  CommandResult r = run_boreas("blobtree --out tree.stl", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("unknown mesh format '.stl'"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace boreas::render::testing
