// boreas tests: the preprocessed-tree glb — an exact round trip, what an engine sees with
// plain tinygltf, malformed files, and preprocess_tree's use of the cache beside a model.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <tiny_gltf.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "host/mesh_trees/tube_trees.h"
#include "mesh_trees/model_import.h"
#include "mesh_trees/obj_writer.h"
#include "mesh_trees/wind_cache.h"
#include "mesh_trees/wind_weights.h"
#include "support/test_support.h"

namespace boreas::test {
namespace {

using impl::PreprocessedTree;

constexpr uint64_t kSeed = 7;
constexpr uint64_t kKey = 0x0123456789abcdefull;

PreprocessedTree tube_tree_data() {
  PreprocessedTree tree;
  tree.model = make_tube_tree().model;
  tree.data = impl::compute_mesh_tree(tree.model, kSeed);
  return tree;
}

void expect_same_part(const impl::MeshPart& a, const impl::MeshPart& b) {
  EXPECT_EQ(a.positions, b.positions);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.uvs, b.uvs);
  EXPECT_EQ(a.indices, b.indices);
}

void expect_same(const PreprocessedTree& a, const PreprocessedTree& b) {
  expect_same_part(a.model.trunk, b.model.trunk);
  expect_same_part(a.model.leaves, b.model.leaves);
  const impl::MeshTreeData& x = a.data;
  const impl::MeshTreeData& y = b.data;
  ASSERT_EQ(x.branches.size(), y.branches.size());
  for (size_t i = 0; i < x.branches.size(); ++i) {
    const impl::MeshTreeBranch& p = x.branches[i];
    const impl::MeshTreeBranch& q = y.branches[i];
    SCOPED_TRACE("branch " + std::to_string(i));
    EXPECT_EQ(p.parent, q.parent);
    EXPECT_EQ(p.level, q.level);
    EXPECT_EQ(p.animated_by, q.animated_by);
    EXPECT_EQ(p.phase, q.phase);
    EXPECT_EQ(p.axis, q.axis);
    EXPECT_EQ(p.up, q.up);
    EXPECT_EQ(p.right, q.right);
    EXPECT_EQ(p.center, q.center);
    EXPECT_EQ(p.base, q.base);
    EXPECT_EQ(p.tip, q.tip);
    EXPECT_EQ(p.length, q.length);
    EXPECT_EQ(p.radius, q.radius);
    EXPECT_EQ(p.orphan, q.orphan);
  }
  EXPECT_EQ(x.longest, y.longest);
  EXPECT_EQ(x.levels, y.levels);
  EXPECT_EQ(x.orphans, y.orphans);
  EXPECT_EQ(x.trunk_weights, y.trunk_weights);
  EXPECT_EQ(x.trunk_branch, y.trunk_branch);
  EXPECT_EQ(x.leaf_weights, y.leaf_weights);
  EXPECT_EQ(x.leaf_branch, y.leaf_branch);
  EXPECT_EQ(x.leaf_petiole, y.leaf_petiole);
  EXPECT_EQ(x.leaf_axis, y.leaf_axis);
  EXPECT_EQ(x.leaf_length, y.leaf_length);
  EXPECT_EQ(x.leaf_of_vertex, y.leaf_of_vertex);
}

// ---- plain tinygltf, as an engine would read the file ----

tinygltf::Model load_glb(const std::string& path) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, path)) << error;
  return model;
}

void save_glb(tinygltf::Model& model, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  tinygltf::TinyGLTF writer;
  ASSERT_TRUE(writer.WriteGltfSceneToStream(&model, out, false, true));
}

const tinygltf::Mesh& mesh_named(const tinygltf::Model& model, const std::string& name) {
  for (const tinygltf::Mesh& mesh : model.meshes)
    if (mesh.name == name) return mesh;
  ADD_FAILURE() << "no mesh " << name;
  return model.meshes.at(0);
}

tinygltf::Mesh& mesh_named(tinygltf::Model& model, const std::string& name) {
  return const_cast<tinygltf::Mesh&>(mesh_named(std::as_const(model), name));
}

// The first float of the attribute's data (the files boreas writes are tightly packed).
float* attribute_data(tinygltf::Model& model, const std::string& mesh, const std::string& name) {
  const tinygltf::Accessor& a =
      model.accessors[size_t(mesh_named(model, mesh).primitives[0].attributes.at(name))];
  const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
  return reinterpret_cast<float*>(model.buffers[0].data.data() + view.byteOffset + a.byteOffset);
}

tinygltf::Value::Object& wind_extras(tinygltf::Model& model) {
  return mesh_named(model, "trunk")
      .extras.Get<tinygltf::Value::Object>()
      .at("boreas_wind")
      .Get<tinygltf::Value::Object>();
}

tinygltf::Value::Array& branch_row(tinygltf::Model& model, size_t i) {
  return wind_extras(model)
      .at("branches")
      .Get<tinygltf::Value::Array>()
      .at(i)
      .Get<tinygltf::Value::Array>();
}

// Writes the tube tree, changes it with `edit` through plain tinygltf, saves it as `name`.
std::string edited_glb(const TempDir& dir, const std::string& name,
                       const std::function<void(tinygltf::Model&)>& edit) {
  const std::string good = (dir.path() / "good.glb").string();
  impl::write_preprocessed_glb(good, tube_tree_data(), kKey);
  tinygltf::Model model = load_glb(good);
  edit(model);
  const std::string path = (dir.path() / name).string();
  save_glb(model, path);
  return path;
}

void expect_malformed(const std::string& path, std::initializer_list<std::string> pieces) {
  std::vector<std::string> all{path};
  all.insert(all.end(), pieces.begin(), pieces.end());
  try {
    PreprocessedTree tree;
    uint64_t key = 0;
    impl::read_preprocessed_glb(path, &tree, &key);
    ADD_FAILURE() << "no error thrown for " << path;
  } catch (const impl::Error& e) {
    const std::string what = e.what();
    EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT) << what;
    for (const std::string& p : all) {
      EXPECT_NE(what.find(p), std::string::npos) << "'" << p << "' not in: " << what;
    }
  }
}

// ---- OBJ input for preprocess_tree ----

// The tube tree as OBJ (positions and faces only), with `comment` on a line of its own.
std::string write_obj(const std::filesystem::path& folder, const std::string& comment = "") {
  const impl::MeshModel model = make_tube_tree().model;
  const std::string path = (folder / "model.obj").string();
  std::ofstream out(path);
  out << "# " << comment << "\n";
  impl::write_obj(out, model);
  return path;
}

PreprocessedTree computed(const std::string& path) {
  PreprocessedTree tree;
  tree.model = impl::load_tree_model(path, {});
  tree.data = impl::compute_mesh_tree(tree.model, kSeed);
  return tree;
}

// ---- the file ----

TEST(WindCache, RoundTripKeepsEveryField) {
  TempDir dir;
  const std::string path = (dir.path() / "tree.glb").string();
  const PreprocessedTree tree = tube_tree_data();
  ASSERT_FALSE(tree.model.leaves.indices.empty());
  ASSERT_GT(tree.data.levels, impl::kMeshTreeLevels);  // the level-4 twig: a row beyond 3
  impl::write_preprocessed_glb(path, tree, kKey);

  PreprocessedTree back;
  uint64_t key = 0;
  ASSERT_TRUE(impl::read_preprocessed_glb(path, &back, &key));
  EXPECT_EQ(key, kKey);
  expect_same(tree, back);
}

TEST(WindCache, RoundTripWithoutLeaves) {
  TempDir dir;
  const std::string path = (dir.path() / "bare.glb").string();
  PreprocessedTree tree;
  tree.model = make_tube_tree().model;
  tree.model.leaves = {};
  tree.data = impl::compute_mesh_tree(tree.model, kSeed);
  impl::write_preprocessed_glb(path, tree, ~0ull);

  EXPECT_EQ(load_glb(path).meshes.size(), 1u);
  PreprocessedTree back;
  uint64_t key = 0;
  ASSERT_TRUE(impl::read_preprocessed_glb(path, &back, &key));
  EXPECT_EQ(key, ~0ull);
  expect_same(tree, back);
}

TEST(WindCache, EnginesSeeNamedAttributes) {
  TempDir dir;
  const std::string path = (dir.path() / "tree.glb").string();
  const PreprocessedTree tree = tube_tree_data();
  impl::write_preprocessed_glb(path, tree, kKey);
  const tinygltf::Model model = load_glb(path);

  ASSERT_EQ(model.nodes.size(), 2u);
  EXPECT_EQ(model.nodes[0].name, "trunk");
  EXPECT_EQ(model.nodes[1].name, "leaves");
  ASSERT_EQ(model.materials.size(), 2u);
  EXPECT_EQ(model.materials[0].name, "bark");
  EXPECT_EQ(model.materials[1].name, "leaf");
  EXPECT_TRUE(model.materials[1].doubleSided);

  struct Expected {
    const char* name;
    int type;
  };
  auto check = [&](const char* mesh_name, const impl::MeshPart& part,
                   std::initializer_list<Expected> attributes) {
    SCOPED_TRACE(mesh_name);
    const tinygltf::Primitive& p = mesh_named(model, mesh_name).primitives.at(0);
    for (const Expected& e : attributes) {
      ASSERT_EQ(p.attributes.count(e.name), 1u) << e.name;
      const tinygltf::Accessor& a = model.accessors[size_t(p.attributes.at(e.name))];
      EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT) << e.name;
      EXPECT_EQ(a.type, e.type) << e.name;
      EXPECT_EQ(a.count, part.vertex_count()) << e.name;
    }
    const tinygltf::Accessor& position = model.accessors[size_t(p.attributes.at("POSITION"))];
    EXPECT_EQ(position.minValues.size(), 3u);
    EXPECT_EQ(position.maxValues.size(), 3u);
    const tinygltf::Accessor& indices = model.accessors[size_t(p.indices)];
    EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    EXPECT_EQ(indices.count, part.indices.size());
  };
  check("trunk", tree.model.trunk,
        {{"POSITION", TINYGLTF_TYPE_VEC3},
         {"NORMAL", TINYGLTF_TYPE_VEC3},
         {"TEXCOORD_0", TINYGLTF_TYPE_VEC2},
         {"_BOREAS_WEIGHTS", TINYGLTF_TYPE_VEC4},
         {"_BOREAS_BRANCH", TINYGLTF_TYPE_SCALAR}});
  check("leaves", tree.model.leaves,
        {{"POSITION", TINYGLTF_TYPE_VEC3},
         {"NORMAL", TINYGLTF_TYPE_VEC3},
         {"TEXCOORD_0", TINYGLTF_TYPE_VEC2},
         {"_BOREAS_WEIGHTS", TINYGLTF_TYPE_VEC4},
         {"_BOREAS_BRANCH", TINYGLTF_TYPE_SCALAR},
         {"_BOREAS_LEAF", TINYGLTF_TYPE_SCALAR},
         {"_BOREAS_PETIOLE", TINYGLTF_TYPE_VEC3},
         {"_BOREAS_LEAF_AXIS", TINYGLTF_TYPE_VEC4}});

  const tinygltf::Value& wind = mesh_named(model, "trunk").extras.Get("boreas_wind");
  ASSERT_TRUE(wind.IsObject());
  EXPECT_EQ(wind.Get("version").GetNumberAsInt(), impl::kWindCacheVersion);
  EXPECT_EQ(wind.Get("key").Get<std::string>(), "0123456789abcdef");
  EXPECT_EQ(wind.Get("levels").GetNumberAsInt(), tree.data.levels);
  EXPECT_EQ(wind.Get("longest").ArrayLen(), 4u);
  const tinygltf::Value& rows = wind.Get("branches");
  ASSERT_EQ(rows.ArrayLen(), tree.data.branches.size());
  for (size_t i = 0; i < rows.ArrayLen(); ++i) {
    const tinygltf::Value& row = rows.Get(int(i));
    ASSERT_EQ(row.ArrayLen(), size_t(impl::kWindCacheColumns));
    EXPECT_EQ(row.Get(0).GetNumberAsInt(), tree.data.branches[i].parent);
    EXPECT_EQ(row.Get(1).GetNumberAsInt(), tree.data.branches[i].level);
    EXPECT_EQ(float(row.Get(26).GetNumberAsDouble()), tree.data.branches[i].length);
  }
  // A leaf vertex's per-vertex copy of its leaf's data.
  tinygltf::Model editable = model;
  const float* axis = attribute_data(editable, "leaves", "_BOREAS_LEAF_AXIS");
  const int leaf = tree.data.leaf_of_vertex[0];
  EXPECT_EQ(axis[0], tree.data.leaf_axis[3 * leaf]);
  EXPECT_EQ(axis[3], tree.data.leaf_length[leaf]);
}

TEST(WindCache, PlainGlbIsNotPreprocessed) {
  TempDir dir;
  const std::string path = edited_glb(dir, "plain.glb", [](tinygltf::Model& model) {
    for (tinygltf::Mesh& mesh : model.meshes) mesh.extras = tinygltf::Value();
  });
  PreprocessedTree tree;
  uint64_t key = 1;
  EXPECT_FALSE(impl::read_preprocessed_glb(path, &tree, &key));
  EXPECT_EQ(key, 1u);
}

TEST(WindCache, WrongColumnCountIsInvalid) {
  TempDir dir;
  const std::string path = edited_glb(
      dir, "columns.glb", [](tinygltf::Model& model) { branch_row(model, 2).pop_back(); });
  expect_malformed(path, {"branch 2", "29"});
}

TEST(WindCache, BranchIndexOutOfRangeIsInvalid) {
  TempDir dir;
  const impl::MeshTreeData data = tube_tree_data().data;
  const size_t branches = data.branches.size();
  const std::string parent = edited_glb(dir, "parent.glb", [](tinygltf::Model& model) {
    branch_row(model, 3)[0] = tinygltf::Value(99);
  });
  expect_malformed(parent, {"branch 3's parent", "99", "out of range"});

  const std::string vertex = edited_glb(dir, "vertex.glb", [&](tinygltf::Model& model) {
    attribute_data(model, "trunk", "_BOREAS_BRANCH")[5] = float(branches);
  });
  expect_malformed(vertex, {"trunk vertex 5", "out of range"});

  // Every vertex of one leaf, so that they still agree.
  const int32_t changed = data.leaf_of_vertex[0];
  const std::string leaf = edited_glb(dir, "leaf.glb", [&](tinygltf::Model& model) {
    float* branch = attribute_data(model, "leaves", "_BOREAS_BRANCH");
    for (size_t v = 0; v < data.leaf_of_vertex.size(); ++v)
      if (data.leaf_of_vertex[v] == changed) branch[v] = float(branches) + 3.0f;
  });
  expect_malformed(leaf, {"leaf " + std::to_string(changed) + "'s branch", "out of range"});
}

TEST(WindCache, WrongVersionIsInvalid) {
  TempDir dir;
  const std::string path = edited_glb(dir, "version.glb", [](tinygltf::Model& model) {
    wind_extras(model)["version"] = tinygltf::Value(impl::kWindCacheVersion + 1);
  });
  expect_malformed(path, {"version " + std::to_string(impl::kWindCacheVersion + 1)});
}

TEST(WindCache, AttributeCountMismatchIsInvalid) {
  TempDir dir;
  const std::string path = edited_glb(dir, "count.glb", [](tinygltf::Model& model) {
    const int weights = mesh_named(model, "leaves").primitives[0].attributes.at("_BOREAS_PETIOLE");
    model.accessors[size_t(weights)].count -= 1;
  });
  expect_malformed(path, {"leaves _BOREAS_PETIOLE", "POSITION"});
}

TEST(WindCache, NaNIsInvalid) {
  TempDir dir;
  const std::string path = edited_glb(dir, "nan.glb", [](tinygltf::Model& model) {
    attribute_data(model, "trunk", "_BOREAS_WEIGHTS")[9] = std::numeric_limits<float>::quiet_NaN();
  });
  expect_malformed(path, {"trunk _BOREAS_WEIGHTS", "NaN"});
}

TEST(WindCache, LeafVerticesThatDisagreeAreInvalid) {
  TempDir dir;
  const std::string path = edited_glb(dir, "leaf.glb", [](tinygltf::Model& model) {
    attribute_data(model, "leaves", "_BOREAS_PETIOLE")[3 * 2 + 1] += 1.0f;  // vertex 2, y
  });
  const int32_t leaf = tube_tree_data().data.leaf_of_vertex[2];
  expect_malformed(path, {"of leaf " + std::to_string(leaf) + " have", "_BOREAS_PETIOLE"});
}

TEST(WindCache, WriteRefusesDataThatDoesNotFitTheModel) {
  TempDir dir;
  const std::string path = (dir.path() / "short.glb").string();
  PreprocessedTree tree = tube_tree_data();
  tree.data.trunk_branch.pop_back();
  expect_error([&] { impl::write_preprocessed_glb(path, tree, kKey); },
               BOREAS_ERROR_INVALID_ARGUMENT, {path, "trunk branches"});
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(WindCache, WriteToMissingFolderIsIoError) {
  TempDir dir;
  const std::string path = (dir.path() / "missing" / "tree.glb").string();
  expect_error([&] { impl::write_preprocessed_glb(path, tube_tree_data(), kKey); }, BOREAS_ERROR_IO,
               {path});
}

TEST(WindCache, NotGltfIsInvalid) {
  TempDir dir;
  const std::string path = (dir.path() / "junk.glb").string();
  std::ofstream(path) << "not a glTF file";
  expect_error([&] { impl::read_preprocessed_glb(path, nullptr, nullptr); },
               BOREAS_ERROR_INVALID_ARGUMENT, {path});
}

// ---- preprocess_tree ----

TEST(WindCache, KeyDependsOnBytesSelectionsAndSeed) {
  TempDir dir;
  const std::string path = write_obj(dir.path());
  const impl::ModelPartSelection defaults;
  const uint64_t key = impl::preprocess_key(path, defaults, kSeed);
  EXPECT_EQ(impl::preprocess_key(path, defaults, kSeed), key);
  EXPECT_NE(impl::preprocess_key(path, defaults, kSeed + 1), key);
  impl::ModelPartSelection trunk = defaults, leaves = defaults;
  trunk.trunk = "trunk";
  leaves.leaves = "leaves";
  EXPECT_NE(impl::preprocess_key(path, trunk, kSeed), key);
  EXPECT_NE(impl::preprocess_key(path, leaves, kSeed), key);
  write_obj(dir.path(), "changed");
  EXPECT_NE(impl::preprocess_key(path, defaults, kSeed), key);
  expect_error([&] { impl::preprocess_key((dir.path() / "none.obj").string(), defaults, kSeed); },
               BOREAS_ERROR_IO, {"none.obj"});
}

TEST(WindCache, PreprocessTreeWritesThenReadsCache) {
  TempDir dir;
  const std::string path = write_obj(dir.path());
  const std::string cache = path + ".boreas.glb";
  bool from_cache = true;
  std::string note = "old";
  const PreprocessedTree first = impl::preprocess_tree(path, {}, kSeed, true, &from_cache, &note);
  EXPECT_FALSE(from_cache);
  EXPECT_EQ(note, "");
  EXPECT_TRUE(std::filesystem::exists(cache));
  expect_same(first, computed(path));

  const PreprocessedTree second = impl::preprocess_tree(path, {}, kSeed, true, &from_cache, &note);
  EXPECT_TRUE(from_cache);
  EXPECT_EQ(note, "");
  expect_same(first, second);

  // Another seed is another key: recomputed, and the cache now holds that seed's data.
  impl::preprocess_tree(path, {}, kSeed + 1, true, &from_cache, &note);
  EXPECT_FALSE(from_cache);
  uint64_t key = 0;
  ASSERT_TRUE(impl::read_preprocessed_glb(cache, nullptr, &key));
  EXPECT_EQ(key, impl::preprocess_key(path, {}, kSeed + 1));
}

TEST(WindCache, ChangedModelIsRecomputed) {
  TempDir dir;
  const std::string path = write_obj(dir.path());
  bool from_cache = false;
  impl::preprocess_tree(path, {}, kSeed, true, &from_cache, nullptr);
  const uint64_t old_key = impl::preprocess_key(path, {}, kSeed);

  write_obj(dir.path(), "edited in a modeller");
  const uint64_t new_key = impl::preprocess_key(path, {}, kSeed);
  EXPECT_NE(new_key, old_key);
  std::string note;
  const PreprocessedTree tree = impl::preprocess_tree(path, {}, kSeed, true, &from_cache, &note);
  EXPECT_FALSE(from_cache);
  EXPECT_EQ(note, "");
  expect_same(tree, computed(path));
  uint64_t key = 0;
  ASSERT_TRUE(impl::read_preprocessed_glb(path + ".boreas.glb", nullptr, &key));
  EXPECT_EQ(key, new_key);
  impl::preprocess_tree(path, {}, kSeed, true, &from_cache, nullptr);
  EXPECT_TRUE(from_cache);
}

TEST(WindCache, PreprocessedGlbIsReadDirectly) {
  TempDir dir;
  const std::string path = (dir.path() / "tree.glb").string();
  const PreprocessedTree tree = tube_tree_data();
  impl::write_preprocessed_glb(path, tree, kKey);
  bool from_cache = false;
  std::string note;
  // Another seed and selection do not apply: the file's data is used as it is.
  impl::ModelPartSelection selection;
  selection.trunk = "nothing";
  const PreprocessedTree back =
      impl::preprocess_tree(path, selection, kSeed + 5, true, &from_cache, &note);
  EXPECT_TRUE(from_cache);
  EXPECT_EQ(note, "");
  expect_same(tree, back);
  EXPECT_FALSE(std::filesystem::exists(path + ".boreas.glb"));
}

TEST(WindCache, OrdinaryGlbIsImported) {
  TempDir dir;
  const std::string path = edited_glb(dir, "plain.glb", [](tinygltf::Model& model) {
    for (tinygltf::Mesh& mesh : model.meshes) mesh.extras = tinygltf::Value();
  });
  bool from_cache = true;
  const PreprocessedTree tree = impl::preprocess_tree(path, {}, kSeed, false, &from_cache, nullptr);
  EXPECT_FALSE(from_cache);
  expect_same(tree, computed(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".boreas.glb"));
}

TEST(WindCache, WithoutCacheNothingIsWritten) {
  TempDir dir;
  const std::string path = write_obj(dir.path());
  bool from_cache = true;
  std::string note;
  const PreprocessedTree tree = impl::preprocess_tree(path, {}, kSeed, false, &from_cache, &note);
  EXPECT_FALSE(from_cache);
  EXPECT_EQ(note, "");
  expect_same(tree, computed(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".boreas.glb"));
}

TEST(WindCache, CorruptCacheIsRewritten) {
  TempDir dir;
  const std::string path = write_obj(dir.path());
  const std::string cache = path + ".boreas.glb";
  impl::preprocess_tree(path, {}, kSeed, true, nullptr, nullptr);
  // Cut in half, as a crash while copying the folder would leave it.
  const auto size = std::filesystem::file_size(cache);
  std::filesystem::resize_file(cache, size / 2);

  bool from_cache = true;
  std::string note;
  const PreprocessedTree tree = impl::preprocess_tree(path, {}, kSeed, true, &from_cache, &note);
  EXPECT_FALSE(from_cache);
  EXPECT_NE(note.find("corrupt"), std::string::npos) << note;
  EXPECT_NE(note.find(cache), std::string::npos) << note;
  EXPECT_EQ(note.find('\n'), std::string::npos) << note;
  expect_same(tree, computed(path));
  EXPECT_EQ(std::filesystem::file_size(cache), size);

  impl::preprocess_tree(path, {}, kSeed, true, &from_cache, &note);
  EXPECT_TRUE(from_cache);
  EXPECT_EQ(note, "");
}

TEST(WindCache, UnwritableCacheFolderGivesNote) {
  if (geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
  TempDir dir;
  const std::filesystem::path folder = dir.path() / "read-only";
  std::filesystem::create_directories(folder);
  const std::string path = write_obj(folder);
  ASSERT_EQ(chmod(folder.c_str(), 0555), 0);

  bool from_cache = true;
  std::string note;
  PreprocessedTree tree;
  EXPECT_NO_THROW(tree = impl::preprocess_tree(path, {}, kSeed, true, &from_cache, &note));
  chmod(folder.c_str(), 0755);  // so that TempDir can remove it
  EXPECT_FALSE(from_cache);
  EXPECT_NE(note.find("not saved"), std::string::npos) << note;
  EXPECT_NE(note.find(path + ".boreas.glb"), std::string::npos) << note;
  EXPECT_EQ(note.find('\n'), std::string::npos) << note;
  expect_same(tree, computed(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".boreas.glb"));
}

}  // namespace
}  // namespace boreas::test
