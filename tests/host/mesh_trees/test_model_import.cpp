// boreas tests: tree model import — OBJ groups and materials, custom part names, glTF node
// transforms against hand-computed values, shared vertices and face normals, and errors that
// name the file and say what to change; truncated and corrupted files fail cleanly.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "errors.h"
#include "mesh_trees/model_import.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace boreas::test {
namespace {

namespace fs = std::filesystem;
using impl::MeshModel;
using impl::MeshPart;
using impl::ModelPartSelection;
using Vec3 = std::array<double, 3>;

constexpr double kTolerance = 1e-5;

std::string write_file(const TempDir& dir, const std::string& name, const std::string& content) {
  fs::path path = dir.path() / name;
  std::ofstream out(path, std::ios::binary);
  out << content;
  return path.string();
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

MeshModel load(const std::string& path, const ModelPartSelection& selection = {}) {
  return impl::load_tree_model(path, selection);
}

Vec3 position(const MeshPart& part, size_t v) {
  return {part.positions[3 * v], part.positions[3 * v + 1], part.positions[3 * v + 2]};
}
Vec3 normal(const MeshPart& part, size_t v) {
  return {part.normals[3 * v], part.normals[3 * v + 1], part.normals[3 * v + 2]};
}

void expect_near(const Vec3& actual, const Vec3& expected, const std::string& what) {
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_NEAR(actual[k], expected[k], kTolerance)
        << what << " component " << k << ": (" << actual[0] << ", " << actual[1] << ", "
        << actual[2] << ") vs (" << expected[0] << ", " << expected[1] << ", " << expected[2]
        << ")";
  }
}

// Every array sized for the part's vertices and every index addressing one.
void expect_consistent(const MeshPart& part) {
  EXPECT_EQ(part.positions.size() % 3, 0u);
  EXPECT_EQ(part.normals.size(), part.positions.size());
  EXPECT_EQ(part.uvs.size() / 2, part.vertex_count());
  EXPECT_EQ(part.indices.size() % 3, 0u);
  for (uint32_t i : part.indices) EXPECT_LT(i, part.vertex_count());
  for (size_t v = 0; v < part.vertex_count(); ++v) {
    Vec3 n = normal(part, v);
    EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, kTolerance);
  }
}

double total_area(const MeshPart& part) {
  double area = 0.0;
  for (size_t t = 0; t < part.triangle_count(); ++t) {
    Vec3 a = position(part, part.indices[3 * t]);
    Vec3 b = position(part, part.indices[3 * t + 1]);
    Vec3 c = position(part, part.indices[3 * t + 2]);
    Vec3 e{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    Vec3 f{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    Vec3 n{e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2], e[0] * f[1] - e[1] * f[0]};
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return area;
}

std::set<std::array<float, 3>> position_set(const MeshPart& part) {
  std::set<std::array<float, 3>> s;
  for (size_t v = 0; v < part.vertex_count(); ++v) {
    s.insert({part.positions[3 * v], part.positions[3 * v + 1], part.positions[3 * v + 2]});
  }
  return s;
}

// A trunk of a unit quad (v1..v4, z = 0) and a triangle on its top edge (v3, v4, v5), and
// a leaf triangle (v6..v8); counter-clockwise seen from +z.
const char kTwoGroups[] =
    "# two groups\n"
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n"
    "v 0.5 2 0\n"
    "v 3 3 3\n"
    "v 4 3 3\n"
    "v 3 4 3\n"
    "g trunk\n"
    "f 1 2 3 4\n"
    "f 4 3 5\n"
    "g leaves\n"
    "f 6 7 8\n";

TEST(ModelImport, ObjGroupsMakeTrunkAndLeaves) {
  TempDir dir;
  MeshModel model = load(write_file(dir, "tree.obj", kTwoGroups));
  expect_consistent(model.trunk);
  expect_consistent(model.leaves);
  EXPECT_EQ(model.trunk.triangle_count(), 3u);
  EXPECT_EQ(model.trunk.vertex_count(), 5u);
  EXPECT_EQ(
      position_set(model.trunk),
      (std::set<std::array<float, 3>>{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 2, 0}}));
  // Quad (1) plus triangle (1 x 1 / 2): nothing dropped, nothing doubled.
  EXPECT_NEAR(total_area(model.trunk), 1.5, kTolerance);

  ASSERT_EQ(model.leaves.triangle_count(), 1u);
  ASSERT_EQ(model.leaves.vertex_count(), 3u);
  // Vertices come in the order the face uses them.
  expect_near(position(model.leaves, model.leaves.indices[0]), {3, 3, 3}, "leaf corner 0");
  expect_near(position(model.leaves, model.leaves.indices[1]), {4, 3, 3}, "leaf corner 1");
  expect_near(position(model.leaves, model.leaves.indices[2]), {3, 4, 3}, "leaf corner 2");
  // No vn or vt lines: face normals (+z) and zero uvs.
  for (size_t v = 0; v < model.trunk.vertex_count(); ++v) {
    expect_near(normal(model.trunk, v), {0, 0, 1}, "trunk normal");
  }
  for (float uv : model.trunk.uvs) EXPECT_EQ(uv, 0.0f);
}

TEST(ModelImport, ObjQuadBecomesTwoTrianglesOnItsFourCorners) {
  TempDir dir;
  MeshModel model =
      load(write_file(dir, "quad.obj", "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\ng trunk\nf 1 2 3 4\n"));
  ASSERT_EQ(model.trunk.triangle_count(), 2u);
  EXPECT_EQ(model.trunk.vertex_count(), 4u);
  EXPECT_NEAR(total_area(model.trunk), 2.0, kTolerance);
  // Both halves keep the quad's counter-clockwise winding (+z face normals).
  for (size_t v = 0; v < 4; ++v) expect_near(normal(model.trunk, v), {0, 0, 1}, "quad normal");
}

TEST(ModelImport, SharedVerticesStayShared) {
  TempDir dir;
  // A fan of four triangles around v1: the file shares v1 and each spoke.
  MeshModel model = load(write_file(dir, "fan.obj",
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\n"
                                    "o Trunk\nf 1 2 3\nf 1 3 4\nf 1 4 5\nf 1 5 2\n"));
  EXPECT_EQ(model.trunk.triangle_count(), 4u);
  EXPECT_EQ(model.trunk.vertex_count(), 5u);
  EXPECT_LT(model.trunk.vertex_count(), 3 * model.trunk.triangle_count());
  // The centre is one index used by every triangle.
  uint32_t centre = model.trunk.indices[0];
  for (size_t t = 0; t < 4; ++t) EXPECT_EQ(model.trunk.indices[3 * t], centre);
}

TEST(ModelImport, ObjNormalsAndUvsComeFromTheFileAndSplitVertices) {
  TempDir dir;
  // Two triangles on the edge v2-v3. The first face's corners all use vn 1 (given at twice
  // unit length); the second uses vn 1 on v2 and vn 2 on v3, so v3 becomes two vertices
  // and v2 stays one.
  MeshModel model = load(write_file(dir, "normals.obj",
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                    "vn 0 0 2\nvn 1 0 0\n"
                                    "vt 0.25 0.5\nvt 0.75 1\n"
                                    "g bark\n"
                                    "f 1/1/1 2/2/1 3/1/1\n"
                                    "f 2/2/1 4/1/1 3/1/2\n"));
  expect_consistent(model.trunk);
  EXPECT_EQ(model.trunk.vertex_count(), 5u);
  const std::vector<uint32_t>& i = model.trunk.indices;
  EXPECT_EQ(i[3], i[1]);  // v2 with vt 2 and vn 1 in both faces
  EXPECT_NE(i[5], i[2]);  // v3 with vn 1, then with vn 2
  expect_near(normal(model.trunk, i[0]), {0, 0, 1}, "normalised file normal");
  expect_near(normal(model.trunk, i[5]), {1, 0, 0}, "second file normal");
  EXPECT_FLOAT_EQ(model.trunk.uvs[2 * i[0]], 0.25f);
  EXPECT_FLOAT_EQ(model.trunk.uvs[2 * i[0] + 1], 0.5f);
  EXPECT_FLOAT_EQ(model.trunk.uvs[2 * i[1]], 0.75f);
  EXPECT_FLOAT_EQ(model.trunk.uvs[2 * i[1] + 1], 1.0f);
}

TEST(ModelImport, MissingNormalsAreAreaWeightedFaceNormals) {
  TempDir dir;
  // Two triangles share the origin: one of area 2 facing +z, one of area 0.5 facing +x.
  // Weighted by area the origin's normal is (0.5, 0, 2) normalised; unweighted it would be
  // (1, 0, 1) normalised.
  MeshModel model = load(write_file(dir, "weights.obj",
                                    "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 1 0\nv 0 0 1\n"
                                    "g stem\nf 1 2 3\nf 1 4 5\n"));
  ASSERT_EQ(model.trunk.triangle_count(), 2u);
  uint32_t origin = model.trunk.indices[0];
  ASSERT_EQ(model.trunk.indices[3], origin);
  double len = std::sqrt(0.5 * 0.5 + 2.0 * 2.0);
  expect_near(normal(model.trunk, origin), {0.5 / len, 0, 2.0 / len}, "shared normal");
  expect_near(normal(model.trunk, model.trunk.indices[1]), {0, 0, 1}, "first face only");
  expect_near(normal(model.trunk, model.trunk.indices[4]), {1, 0, 0}, "second face only");
}

TEST(ModelImport, ObjSelectsByMaterialWithoutItsMtlFile) {
  TempDir dir;
  const std::string body =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
      "usemtl Bark\nf 1 2 3\nf 1 3 4\n"
      "usemtl Leaf\nf 2 3 4\n";
  // mtllib naming a file that is not there (tinyobj only warns), and no mtllib at all.
  for (const std::string& header : {std::string("mtllib missing.mtl\n"), std::string()}) {
    SCOPED_TRACE(header.empty() ? "no mtllib" : "missing mtllib");
    MeshModel model = load(write_file(dir, "materials.obj", header + body));
    EXPECT_EQ(model.trunk.triangle_count(), 2u);
    EXPECT_EQ(model.trunk.vertex_count(), 4u);
    EXPECT_EQ(model.leaves.triangle_count(), 1u);
  }
}

TEST(ModelImport, CustomSelectorsPickNamedParts) {
  TempDir dir;
  std::string path = write_file(dir, "custom.obj",
                                "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                "g Stem1\nf 1 2 3\n"
                                "g Twig_03\nf 1 3 4\nf 1 2 4\n"
                                "g Needles\nf 2 3 4\n"
                                "g Rock\nf 1 2 3\n");
  ModelPartSelection selection;
  selection.trunk = " stem1 ,TWIG,, ";  // spaces, case and empty items do not matter
  selection.leaves = "needle";
  MeshModel model = load(path, selection);
  EXPECT_EQ(model.trunk.triangle_count(), 3u);   // Stem1 and Twig_03; Rock is neither
  EXPECT_EQ(model.leaves.triangle_count(), 1u);  // Needles

  selection.leaves = "";  // no leaves at all is fine
  model = load(path, selection);
  EXPECT_EQ(model.trunk.triangle_count(), 3u);
  EXPECT_EQ(model.leaves.triangle_count(), 0u);
  EXPECT_EQ(model.leaves.vertex_count(), 0u);

  // The default names match parts of names: "stem" finds Stem1, "needle" Needles.
  model = load(path);
  EXPECT_EQ(model.trunk.triangle_count(), 1u);
  EXPECT_EQ(model.leaves.triangle_count(), 1u);
}

TEST(ModelImport, GroupNameDecidesBeforeMaterialAndLeavesWinATie) {
  TempDir dir;
  MeshModel model = load(write_file(dir, "order.obj",
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                    "g trunk\nusemtl Leaf\nf 1 2 3\n"  // group: trunk
                                    "g Tree\nusemtl Leaf\nf 1 3 4\n"   // material: leaves
                                    "g branch_leaves\nf 2 3 4\n"));    // both: leaves
  EXPECT_EQ(model.trunk.triangle_count(), 1u);
  EXPECT_EQ(model.leaves.triangle_count(), 2u);
}

// Builds small glTF models: one buffer, a view and accessor per array.
class GltfBuilder {
 public:
  GltfBuilder() {
    model_.asset.version = "2.0";
    model_.buffers.emplace_back();
  }

  template <typename T>
  int accessor(const std::vector<T>& data, int component_type, int type, size_t count) {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    while (buffer.size() % 4) buffer.push_back(0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = data.size() * sizeof(T);
    buffer.resize(buffer.size() + view.byteLength);
    std::memcpy(buffer.data() + view.byteOffset, data.data(), view.byteLength);
    model_.bufferViews.push_back(view);
    tinygltf::Accessor a;
    a.bufferView = int(model_.bufferViews.size()) - 1;
    a.componentType = component_type;
    a.type = type;
    a.count = count;
    model_.accessors.push_back(a);
    return int(model_.accessors.size()) - 1;
  }
  int vec3(const std::vector<float>& xyz) {
    return accessor(xyz, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, xyz.size() / 3);
  }
  int vec2(const std::vector<float>& uv) {
    return accessor(uv, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, uv.size() / 2);
  }
  template <typename T>
  int indices(const std::vector<T>& i, int component_type) {
    return accessor(i, component_type, TINYGLTF_TYPE_SCALAR, i.size());
  }

  static tinygltf::Primitive primitive(int positions, int indices = -1, int normals = -1,
                                       int uvs = -1, int material = -1,
                                       int mode = TINYGLTF_MODE_TRIANGLES) {
    tinygltf::Primitive p;
    p.attributes["POSITION"] = positions;
    if (normals >= 0) p.attributes["NORMAL"] = normals;
    if (uvs >= 0) p.attributes["TEXCOORD_0"] = uvs;
    p.indices = indices;
    p.material = material;
    p.mode = mode;
    return p;
  }
  int mesh(const std::string& name, const std::vector<tinygltf::Primitive>& primitives) {
    tinygltf::Mesh m;
    m.name = name;
    m.primitives = primitives;
    model_.meshes.push_back(m);
    return int(model_.meshes.size()) - 1;
  }
  int material(const std::string& name) {
    tinygltf::Material m;
    m.name = name;
    model_.materials.push_back(m);
    return int(model_.materials.size()) - 1;
  }
  tinygltf::Node& node(const std::string& name, int mesh = -1) {
    tinygltf::Node n;
    n.name = name;
    n.mesh = mesh;
    model_.nodes.push_back(n);
    return model_.nodes.back();
  }
  int last_node() const { return int(model_.nodes.size()) - 1; }
  void scene(const std::vector<int>& roots) {
    tinygltf::Scene s;
    s.nodes = roots;
    model_.scenes.push_back(s);
    model_.defaultScene = 0;
  }
  tinygltf::Model& model() { return model_; }

  std::string write(const std::string& path, bool binary, bool embed_buffers = true) {
    tinygltf::TinyGLTF writer;
    EXPECT_TRUE(writer.WriteGltfSceneToFile(&model_, path, true, embed_buffers, false, binary))
        << path;
    return path;
  }

 private:
  tinygltf::Model model_;
};

// A root "tree" (translation (1, 2, 3)) over "trunk" (90 degrees about Y, scale (2, 1, 1); a
// unit quad with normals (1, 1, 0)/sqrt 2 and uvs, unsigned short indices), "leaf_card" (a
// matrix: scale 0.5, then up 5; a non-indexed triangle with no normals, the same triangle
// again reversed with unsigned byte indices and material "Leaf", and a POINTS primitive) and
// "rock" (matched by neither part).
GltfBuilder hierarchy_model() {
  GltfBuilder b;
  const float s = float(std::sqrt(0.5));
  int quad = b.vec3({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  int quad_normals = b.vec3({s, s, 0, s, s, 0, s, s, 0, s, s, 0});
  int quad_uvs = b.vec2({0, 0, 1, 0, 1, 1, 0, 1});
  int quad_indices =
      b.indices(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  int trunk_mesh =
      b.mesh("bole", {GltfBuilder::primitive(quad, quad_indices, quad_normals, quad_uvs)});

  int leaf = b.vec3({0, 0, 0, 2, 0, 0, 0, 2, 0});
  int reversed = b.indices(std::vector<uint8_t>{0, 2, 1}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
  int leaf_material = b.material("Leaf");
  int leaf_mesh = b.mesh(
      "card",
      {GltfBuilder::primitive(leaf), GltfBuilder::primitive(leaf, reversed, -1, -1, leaf_material),
       GltfBuilder::primitive(leaf, -1, -1, -1, leaf_material, TINYGLTF_MODE_POINTS)});
  int rock_mesh = b.mesh("stone", {GltfBuilder::primitive(leaf)});

  b.node("tree").translation = {1, 2, 3};
  int tree = b.last_node();
  tinygltf::Node& trunk = b.node("trunk", trunk_mesh);
  trunk.rotation = {0, std::sqrt(0.5), 0, std::sqrt(0.5)};
  trunk.scale = {2, 1, 1};
  int trunk_node = b.last_node();
  b.node("leaf_card", leaf_mesh).matrix = {0.5, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0.5, 0, 0, 5, 0, 1};
  int leaf_node = b.last_node();
  b.node("rock", rock_mesh);
  int rock_node = b.last_node();
  b.model().nodes[size_t(tree)].children = {trunk_node, leaf_node, rock_node};
  b.scene({tree});
  return b;
}

void expect_hierarchy_model(const MeshModel& model) {
  expect_consistent(model.trunk);
  expect_consistent(model.leaves);
  // trunk: world = T(1, 2, 3) R_y(90) S(2, 1, 1), and R_y(90) takes (x, y, z) to (z, y, -x).
  ASSERT_EQ(model.trunk.vertex_count(), 4u);
  ASSERT_EQ(model.trunk.triangle_count(), 2u);
  const Vec3 corners[4] = {{1, 2, 3}, {1, 2, 1}, {1, 3, 1}, {1, 3, 3}};
  const float uvs[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  // Normals take (R S)^-T = R S^-1: (1, 1, 0) -> (0.5, 1, 0) -> (0, 1, -0.5), i.e.
  // (0, 2, -1)/sqrt 5. Transformed like positions, they would come out (0, 1, -2)/sqrt 5.
  const double r5 = std::sqrt(5.0);
  for (size_t v = 0; v < 4; ++v) {
    expect_near(position(model.trunk, v), corners[v], "trunk vertex " + std::to_string(v));
    expect_near(normal(model.trunk, v), {0, 2 / r5, -1 / r5}, "trunk normal");
    EXPECT_FLOAT_EQ(model.trunk.uvs[2 * v], uvs[v][0]);
    EXPECT_FLOAT_EQ(model.trunk.uvs[2 * v + 1], uvs[v][1]);
  }
  EXPECT_EQ(model.trunk.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));

  // leaves: world = T(1, 2, 3) (up 5) (scale 0.5); two triangles of their own vertices (one
  // per primitive), the POINTS primitive skipped, the rock ignored.
  ASSERT_EQ(model.leaves.triangle_count(), 2u);
  ASSERT_EQ(model.leaves.vertex_count(), 6u);
  expect_near(position(model.leaves, 0), {1, 7, 3}, "leaf vertex 0");
  expect_near(position(model.leaves, 1), {2, 7, 3}, "leaf vertex 1");
  expect_near(position(model.leaves, 2), {1, 8, 3}, "leaf vertex 2");
  expect_near(normal(model.leaves, model.leaves.indices[0]), {0, 0, 1}, "leaf face normal");
  expect_near(normal(model.leaves, model.leaves.indices[3]), {0, 0, -1}, "reversed face normal");
  for (float uv : model.leaves.uvs) EXPECT_EQ(uv, 0.0f);
}

TEST(ModelImport, GlbAppliesTheNodeHierarchyToPositionsAndNormals) {
  TempDir dir;
  std::string path = hierarchy_model().write((dir.path() / "tree.glb").string(), true);
  ASSERT_EQ(read_file(path).compare(0, 4, "glTF"), 0) << "not written as binary glTF";
  expect_hierarchy_model(load(path));
}

TEST(ModelImport, GltfAsciiWithEmbeddedOrExternalBuffers) {
  TempDir dir;
  std::string embedded = hierarchy_model().write((dir.path() / "tree.gltf").string(), false);
  ASSERT_EQ(read_file(embedded).front(), '{');
  expect_hierarchy_model(load(embedded));

  fs::create_directories(dir.path() / "sub");
  std::string external =
      hierarchy_model().write((dir.path() / "sub" / "split.gltf").string(), false, false);
  size_t bins = 0;
  for (const auto& e : fs::directory_iterator(dir.path() / "sub")) {
    bins += e.path().extension() == ".bin";
  }
  ASSERT_EQ(bins, 1u) << "tinygltf did not write an external buffer";
  expect_hierarchy_model(load(external));
}

TEST(ModelImport, GltfWithoutSceneReadsEveryRootNode) {
  TempDir dir;
  GltfBuilder b;
  int tri = b.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});
  int idx = b.indices(std::vector<uint32_t>{0, 1, 2}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  int bark = b.mesh("Bark", {GltfBuilder::primitive(tri, idx)});
  b.node("a", bark).translation = {10, 0, 0};
  b.node("b", bark).translation = {0, 10, 0};
  int child = b.last_node();
  b.node("c", bark).children = {child};  // b is c's child: translated twice
  b.model().nodes.back().translation = {0, 0, 10};
  MeshModel model = load(b.write((dir.path() / "noscene.glb").string(), true));
  ASSERT_EQ(model.trunk.triangle_count(), 3u);
  expect_near(position(model.trunk, 0), {10, 0, 0}, "root a");
  expect_near(position(model.trunk, 3), {0, 0, 10}, "root c");
  expect_near(position(model.trunk, 6), {0, 10, 10}, "b under c");
}

TEST(ModelImport, MirroringNodeKeepsFacesCounterClockwise) {
  TempDir dir;
  GltfBuilder b;
  int tri = b.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});  // faces +z
  b.node("trunk", b.mesh("m", {GltfBuilder::primitive(tri)})).scale = {-1, 1, 1};
  b.scene({0});
  MeshModel model = load(b.write((dir.path() / "mirror.glb").string(), true));
  ASSERT_EQ(model.trunk.triangle_count(), 1u);
  // Mirrored in x the triangle still faces +z; its corners, read in file order, would wind
  // clockwise and give -z.
  expect_near(normal(model.trunk, 0), {0, 0, 1}, "face normal");
}

TEST(ModelImport, GlbWithAnEmbeddedImageLoads) {
  TempDir dir;
  GltfBuilder b = hierarchy_model();
  int view_of_bytes =
      b.indices(std::vector<uint8_t>{0x89, 'P', 'N', 'G'}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
  tinygltf::Image image;
  image.name = "bark_color";
  image.mimeType = "image/png";
  image.bufferView = b.model().accessors[size_t(view_of_bytes)].bufferView;
  b.model().images.push_back(image);
  MeshModel model = load(b.write((dir.path() / "textured.glb").string(), true));
  EXPECT_EQ(model.trunk.triangle_count(), 2u);
}

TEST(ModelImport, NonTriangleModesAreSkippedAndNamedWhenTheTrunkHasNothingElse) {
  TempDir dir;
  GltfBuilder b;
  int line = b.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});
  b.node("trunk",
         b.mesh("m", {GltfBuilder::primitive(line, -1, -1, -1, -1, TINYGLTF_MODE_LINE_STRIP)}));
  b.scene({0});
  std::string path = b.write((dir.path() / "lines.glb").string(), true);
  expect_error([&] { load(path); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {path, "no trunk triangles", "1 primitive(s) were skipped", "TRIANGLES"});
}

TEST(ModelImport, NoTrunkListsTheNamesTheFileHas) {
  TempDir dir;
  std::string obj = write_file(dir, "blender.obj",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                               "o Cylinder.001\nusemtl Material.002\nf 1 2 3\n"
                               "o Plane\nusemtl Foliage_mat\nf 1 3 2\n");
  expect_error([&] { load(obj); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {obj, "no trunk triangles", "\"trunk,bark,branch,stem,wood\"", "\"Cylinder.001\"",
                "\"Plane\"", "\"Material.002\"", "\"Foliage_mat\"", "Set the trunk part",
                "e.g. \"Cylinder.001\""});

  GltfBuilder b;
  int tri = b.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});
  int mat = b.material("Bole_Mat");
  b.node("Tree_LOD0", b.mesh("Mesh_0", {GltfBuilder::primitive(tri, -1, -1, -1, mat)}));
  b.scene({0});
  std::string glb = b.write((dir.path() / "speedtree.glb").string(), true);
  ModelPartSelection selection;
  selection.trunk = "Stem1";
  expect_error([&] { load(glb, selection); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {glb, "\"Stem1\"", "node, mesh or material", "\"Tree_LOD0\"", "\"Mesh_0\"",
                "\"Bole_Mat\"", "Set the trunk part"});
}

TEST(ModelImport, MissingFileIsAnIoErrorNamingThePath) {
  TempDir dir;
  for (const char* name : {"absent.obj", "absent.glb", "absent.gltf"}) {
    std::string path = (dir.path() / name).string();
    expect_error([&] { load(path); }, BOREAS_ERROR_IO, {path, "no such file"});
  }
  fs::create_directories(dir.path() / "folder.obj");
  expect_error([&] { load((dir.path() / "folder.obj").string()); }, BOREAS_ERROR_IO,
               {"folder.obj", "not a regular file"});
}

TEST(ModelImport, GarbageIsInvalidArgumentNamingTheFile) {
  TempDir dir;
  const char raw[] = "\x7f\x01\xfe garbage \x00\x02 {]\n\x80\x81";
  const std::string garbage(raw, sizeof raw - 1);
  for (const char* name : {"garbage.obj", "garbage.gltf", "garbage.glb"}) {
    std::string path = write_file(dir, name, garbage);
    expect_error([&] { load(path); }, BOREAS_ERROR_INVALID_ARGUMENT, {path});
  }
  std::string glb = write_file(dir, "magic.glb", "glTF" + garbage);
  expect_error([&] { load(glb); }, BOREAS_ERROR_INVALID_ARGUMENT, {glb, "malformed glTF"});
  std::string gltf = write_file(dir, "json.gltf", "{\"asset\": {\"version\": \"2.0\"}, ");
  expect_error([&] { load(gltf); }, BOREAS_ERROR_INVALID_ARGUMENT, {gltf, "malformed glTF"});
}

TEST(ModelImport, ObjParseErrorsCountTheFilesOwnLines) {
  TempDir dir;
  // Index 0 does not exist in OBJ: tinyobj refuses line 4.
  std::string path = write_file(dir, "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
  expect_error([&] { load(path); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {path, "malformed OBJ", "line 4."});
}

TEST(ModelImport, NonFinitePositionNamesTheVertexAndThePart) {
  TempDir dir;
  // 1e39 overflows a float.
  std::string obj = write_file(dir, "inf.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\ng trunk\nf 1 2 3\n");
  expect_error([&] { load(obj); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {obj, "vertex 2", "trunk part", "non-finite", "inf"});
  // Unused, it does no harm.
  EXPECT_NO_THROW(load(
      write_file(dir, "unused.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nv 1 0 0\ng trunk\nf 1 4 3\n")));

  GltfBuilder b;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  int trunk = b.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});
  int leaf = b.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, nan, 0});
  int idx = b.indices(std::vector<uint16_t>{0, 1, 3}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
  b.node("trunk", b.mesh("t", {GltfBuilder::primitive(trunk)}));
  b.node("leaves", b.mesh("l", {GltfBuilder::primitive(leaf, idx)}));
  b.scene({0, 1});
  std::string glb = b.write((dir.path() / "nan.glb").string(), true);
  expect_error([&] { load(glb); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {glb, "vertex 3 of mesh 1 'l'", "leaves part", "nan"});
}

TEST(ModelImport, ObjNumbersThatAreNotFiniteAreRefusedWithTheirLine) {
  TempDir dir;
  const std::string faces = "g trunk\nf 1 2 3\n";
  // tinyobjloader alone reads each of these as 0: the vertex would move without a word.
  const struct {
    const char* name;
    const char* text;
    const char* line;
    const char* token;
  } cases[] = {
      {"nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\n", "line 2", "'nan'"},
      {"inf.obj", "v 0 0 0\nv 1 0 0\nv 0 -inf 0\n", "line 3", "'-inf'"},
      {"word.obj", "v 0 0 0\nv 1 zero 0\nv 0 1 0\n", "line 2", "'zero'"},
      {"huge.obj", "v 1e400 0 0\nv 1 0 0\nv 0 1 0\n", "line 1", "'1e400'"},
      {"normal.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 NaN 1\n", "line 4", "'NaN'"},
      {"uv.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n# uv\nvt inf 0\n", "line 5", "'inf'"},
      // Unused by any face, still refused: the file is not what it would be read as.
      {"unused.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan nan nan\n", "line 4", "'nan'"},
  };
  for (const auto& c : cases) {
    const std::string path = write_file(dir, c.name, std::string(c.text) + faces);
    SCOPED_TRACE(c.name);
    expect_error([&] { load(path); }, BOREAS_ERROR_INVALID_ARGUMENT,
                 {path, c.line, c.token, "not a finite number"});
  }
  // Signs, exponents, tabs, carriage returns and trailing comments are numbers as usual.
  const std::string fine =
      write_file(dir, "fine.obj",
                 "v +0 -0.0 0 # origin\r\nv\t1e0 0 0\r\nv 0 1.5E-0 +2e-3\nvt .5 1.\n" + faces);
  const MeshModel m = load(fine);
  ASSERT_EQ(m.trunk.vertex_count(), 3u);
  bool third = false;
  for (size_t v = 0; v < 3; ++v)
    third |= m.trunk.positions[3 * v] == 0.0f && m.trunk.positions[3 * v + 1] == 1.5f &&
             m.trunk.positions[3 * v + 2] == 2e-3f;
  EXPECT_TRUE(third) << "v 0 1.5E-0 +2e-3 read as (0, 1.5, 0.002)";
}

// Found by fuzz_obj: tinyobjloader turns a skin weight's joint id into an int unchecked (UB
// for 1e39). boreas does not read skin weights; the lines are passed over.
TEST(ModelImport, ObjSkinWeightsArePassedOver) {
  TempDir dir;
  const std::string path =
      write_file(dir, "weights.obj",
                 "v 0 0 0\nv 1 0 0\nv 0 1 0\nvw 1 1e39 0.5\n  vw 2 -7 2\ng trunk\nf 1 2 3\n");
  const MeshModel m = load(path);
  EXPECT_EQ(m.trunk.vertex_count(), 3u);
  // A lone carriage return ends a line for tinyobj too.
  EXPECT_EQ(
      load(write_file(dir, "cr.obj", "v 0 0 0\rv 1 0 0\rv 0 1 0\rvw 1 1e39 1\rg trunk\rf 1 2 3\r"))
          .trunk.vertex_count(),
      3u);
  const std::string cr_nan = write_file(dir, "cr_nan.obj", "v 0 0 0\r\nv 1 0 0\rv nan 0 0\n");
  expect_error([&] { load(cr_nan); }, BOREAS_ERROR_INVALID_ARGUMENT, {cr_nan, "line 3", "'nan'"});
  // Line numbers stay the file's own.
  const std::string bad = write_file(dir, "after.obj", "vw 1 1 1\nv 0 0 0\nv nan 0 0\n");
  expect_error([&] { load(bad); }, BOREAS_ERROR_INVALID_ARGUMENT, {bad, "line 3", "'nan'"});
}

TEST(ModelImport, IndicesOutOfRangeAreRejected) {
  TempDir dir;
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\ng trunk\n";
  std::string triangle = write_file(dir, "tri.obj", vertices + "f 1 2 99\n");
  expect_error([&] { load(triangle); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {triangle, "vertex 99", "out of range", "the file has 4"});
  // tinyobj drops a quad with a bad index, with only a warning.
  std::string quad = write_file(dir, "quad.obj", vertices + "f 1 2 3 40\n");
  expect_error([&] { load(quad); }, BOREAS_ERROR_INVALID_ARGUMENT, {quad, "out of range"});
  std::string relative = write_file(dir, "relative.obj", vertices + "f -1 -2 -9\n");
  expect_error([&] { load(relative); }, BOREAS_ERROR_INVALID_ARGUMENT, {relative, "out of range"});
  std::string normals = write_file(dir, "vn.obj", vertices + "f 1//3 2//3 3//3\n");
  expect_error([&] { load(normals); }, BOREAS_ERROR_INVALID_ARGUMENT, {normals, "normal 3"});

  GltfBuilder b;
  int tri = b.vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});
  int idx = b.indices(std::vector<uint8_t>{0, 1, 7}, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE);
  b.node("trunk", b.mesh("m", {GltfBuilder::primitive(tri, idx)}));
  b.scene({0});
  std::string glb = b.write((dir.path() / "index.glb").string(), true);
  expect_error([&] { load(glb); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {glb, "index 7", "out of range", "3 vertices"});

  // An accessor that claims more elements than its buffer view holds.
  b.model().accessors[size_t(tri)].count = 1000;
  b.model().accessors[size_t(idx)].count = 3;
  std::string overrun = b.write((dir.path() / "overrun.glb").string(), true);
  expect_error([&] { load(overrun); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {overrun, "POSITION", "do not fit"});
}

TEST(ModelImport, UnknownExtensionIsRejected) {
  TempDir dir;
  std::string path = write_file(dir, "tree.fbx", kTwoGroups);
  expect_error([&] { load(path); }, BOREAS_ERROR_INVALID_ARGUMENT,
               {path, "'.fbx'", ".obj", ".gltf", ".glb"});
  // Extensions are case-insensitive.
  EXPECT_EQ(load(write_file(dir, "TREE.OBJ", kTwoGroups)).trunk.triangle_count(), 3u);
}

// Every prefix of a file, and the file with each byte inverted in turn, either loads or
// throws impl::Error: nothing else escapes, and (under the sanitizers) nothing reads out of
// bounds.
TEST(ModelImport, TruncatedAndCorruptedFilesFailCleanly) {
  TempDir dir;
  std::string glb = read_file(hierarchy_model().write((dir.path() / "whole.glb").string(), true));
  const std::string obj = std::string(kTwoGroups) + "vn 0 0 1\nvt 0 0\nf 6/1/1 7/1/1 8/1/1\n";
  struct Case {
    const char* name;
    const std::string* bytes;
  };
  for (const Case& c : {Case{"cut.glb", &glb}, Case{"cut.obj", &obj}}) {
    size_t loaded = 0;
    auto attempt = [&](const std::string& bytes, const std::string& what) {
      std::string path = write_file(dir, c.name, bytes);
      try {
        load(path);
        ++loaded;
      } catch (const impl::Error&) {
      } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": " << e.what();
      }
    };
    for (size_t n = 0; n < c.bytes->size(); ++n) {
      attempt(c.bytes->substr(0, n), std::string(c.name) + " cut at " + std::to_string(n));
    }
    for (size_t i = 0; i < c.bytes->size(); ++i) {
      std::string bytes = *c.bytes;
      bytes[i] = char(~bytes[i]);
      attempt(bytes, std::string(c.name) + " byte " + std::to_string(i) + " inverted");
    }
    EXPECT_GT(loaded, 0u) << c.name << ": nothing loaded, the cases test nothing";
  }
}

}  // namespace
}  // namespace boreas::test
