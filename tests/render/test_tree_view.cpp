// render tests: trees on frames (from above and in the side-view panel) and tree meshes
// (leaf quads, OBJ, PLY and glTF bytes, atomic writes), on their own, without a world.
#include "image/tree_view.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "mesh/tree_mesh.h"

namespace boreas::render {
namespace {

namespace fs = std::filesystem;

// A two-branch tree: a 10 m trunk straight up from base and one bough to the side.
TreePose small_tree(float base_x, float bend = 0.0f) {
  TreePose pose;
  TreeCurve trunk;
  for (int i = 0; i < 4; ++i) {
    float t = float(i) / 3.0f;
    trunk.points[i][0] = base_x + bend * t * t;
    trunk.points[i][1] = 10.0f * t;
    trunk.points[i][2] = 0.0f;
  }
  trunk.level = 0;
  trunk.radius = 0.3f;
  TreeCurve bough;
  for (int i = 0; i < 4; ++i) {
    float t = float(i) / 3.0f;
    bough.points[i][0] = base_x + bend * 0.5f + 3.0f * t;
    bough.points[i][1] = 6.0f + 2.0f * t;
    bough.points[i][2] = 0.0f;
  }
  bough.level = 1;
  bough.radius = 0.1f;
  pose.branches = {trunk, bough};
  pose.leaves = {{base_x + bend + 0.5f, 10.0f, 0.0f}, {base_x + bend * 0.5f + 3.0f, 8.0f, 0.0f}};
  return pose;
}

bool same_pixels(const Image& a, const Image& b) { return a.data() == b.data(); }

TEST(TreeView, BezierPassesThroughItsEnds) {
  float points[4][3] = {{0, 0, 0}, {1, 2, 0}, {2, 2, 0}, {3, 0, 1}};
  EXPECT_EQ(bezier_point(points, 0.0f), (std::array<float, 3>{0, 0, 0}));
  EXPECT_EQ(bezier_point(points, 1.0f), (std::array<float, 3>{3, 0, 1}));
  std::array<float, 3> middle = bezier_point(points, 0.5f);
  EXPECT_NEAR(middle[0], 1.5f, 1e-6f);
  EXPECT_NEAR(middle[1], 1.5f, 1e-6f);
}

TEST(TreeView, TreesFromAboveLandWhereTheyStand) {
  // 1 pixel per meter, origin (-32, -32): a tree at x = 0 stands at pixel column 32.
  TopProjection projection{-32.0f, -32.0f, 1.0f, 1.0f};
  TreePose tree = small_tree(0.0f);
  Image image(64, 64);
  draw_trees_from_above(image, projection, {&tree});
  auto lit = [&](int x, int y) {
    Rgb c = image.at(x, y);
    return c.r + c.g + c.b > 0.0f;
  };
  EXPECT_TRUE(lit(32, 32));   // the trunk, end-on
  EXPECT_TRUE(lit(34, 32));   // the bough, reaching +x
  EXPECT_FALSE(lit(32, 40));  // nothing toward +z
  EXPECT_FALSE(lit(10, 10));
}

TEST(TreeView, SidePanelColumnsShareOneScale) {
  TreePose a = small_tree(-20.0f);
  TreePose b = small_tree(20.0f);
  SidePanel panel = layout_side_panel({&a, &b}, {"A", "B"}, 200, 100);
  ASSERT_EQ(panel.columns.size(), 2u);
  EXPECT_EQ(panel.hidden, 0);
  EXPECT_EQ(panel.columns[0].left, 0);
  EXPECT_EQ(panel.columns[1].left, 100);
  EXPECT_EQ(panel.columns[0].center_x, -20.0f);
  EXPECT_EQ(panel.columns[1].center_x, 20.0f);
  EXPECT_GT(panel.pixels_per_meter, 1.0f);
  // The 10 m tree fits between the ground line and the top.
  EXPECT_LE(10.0f * panel.pixels_per_meter, float(panel.ground_row));
  EXPECT_EQ(side_panel_height(384, 384), 192);
  EXPECT_EQ(side_panel_height(64, 64), 48);

  // More trees than columns fit: the rest are counted, not squeezed.
  std::vector<const TreePose*> many(10, &a);
  SidePanel narrow = layout_side_panel(many, {}, 2 * kMinSideColumn, 60);
  EXPECT_EQ(narrow.columns.size(), 2u);
  EXPECT_EQ(narrow.hidden, 8);
}

TEST(TreeView, SidePanelShowsTheBendAndNothingElseMoves) {
  TreePose rest = small_tree(0.0f);
  TreePose bent = small_tree(0.0f, 1.5f);
  SidePanel panel = layout_side_panel({&rest}, {"OAK"}, 96, 96);
  Image still = draw_side_panel(panel, {&rest}, {&rest});
  Image again = draw_side_panel(panel, {&rest}, {&rest});
  Image moved = draw_side_panel(panel, {&rest}, {&bent});
  EXPECT_TRUE(same_pixels(still, again));
  EXPECT_FALSE(same_pixels(still, moved));
  // The ground under the tree and the sky far above it are the same in both.
  EXPECT_EQ(still.at(2, panel.height - 1).r, moved.at(2, panel.height - 1).r);
  EXPECT_EQ(still.at(2, 0).g, moved.at(2, 0).g);
}

// --- meshes -------------------------------------------------------------------------------

boreas_leaf flat_leaf() {
  boreas_leaf leaf{};
  leaf.position[0] = 1.0f;
  leaf.axis[1] = 1.0f;    // along +y
  leaf.normal[2] = 1.0f;  // facing +z
  leaf.length = 0.2f;
  leaf.width = 0.1f;
  return leaf;
}

TreeMesh small_mesh() {
  std::vector<boreas_vertex> vertices(3);
  for (int i = 0; i < 3; ++i) {
    vertices[size_t(i)].position[0] = float(i == 1);
    vertices[size_t(i)].position[1] = float(i == 2);
    vertices[size_t(i)].normal[2] = 1.0f;
    vertices[size_t(i)].uv[0] = 0.5f;
  }
  TreeMesh mesh;
  mesh.branches = branch_mesh(vertices, {0, 1, 2});
  mesh.leaves = leaf_mesh({flat_leaf(), flat_leaf()});
  mesh.description = "test";
  return mesh;
}

TEST(MeshExport, LeafQuadsFaceTheirNormalCounterClockwise) {
  MeshPart part = leaf_mesh({flat_leaf()});
  ASSERT_EQ(part.vertex_count(), 4u);
  ASSERT_EQ(part.indices, (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  const float* p = part.positions.data();
  // Corners: width across (x, centred on the axis), length along +y.
  EXPECT_NEAR(p[0], 0.95f, 1e-6f);
  EXPECT_NEAR(p[3], 1.05f, 1e-6f);
  EXPECT_NEAR(p[7], 0.2f, 1e-6f);
  for (int t = 0; t < 2; ++t) {
    const uint32_t* tri = &part.indices[size_t(3 * t)];
    float e1[3], e2[3];
    for (int a = 0; a < 3; ++a) {
      e1[a] = p[3 * tri[1] + a] - p[3 * tri[0] + a];
      e2[a] = p[3 * tri[2] + a] - p[3 * tri[0] + a];
    }
    float nz = e1[0] * e2[1] - e1[1] * e2[0];
    EXPECT_GT(nz, 0.0f) << "triangle " << t << " winds clockwise seen from +z";
  }
  for (size_t v = 0; v < 4; ++v) EXPECT_EQ(part.normals[3 * v + 2], 1.0f);
  EXPECT_EQ(part.uvs, (std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1}));
}

TEST(MeshExport, FormatsByExtension) {
  EXPECT_EQ(mesh_format_for("a/tree.obj"), MeshFormat::kObj);
  EXPECT_EQ(mesh_format_for("TREE.PLY"), MeshFormat::kPly);
  EXPECT_EQ(mesh_format_for("t.glb"), MeshFormat::kGlb);
  EXPECT_FALSE(mesh_format_for("t.gltf"));
  EXPECT_FALSE(mesh_format_for("t"));
}

TEST(MeshExport, ObjHasGroupsAndSharedIndices) {
  std::string obj = obj_text(small_mesh());
  auto count = [&](const std::string& prefix) {
    size_t n = 0;
    std::istringstream lines(obj);
    for (std::string line; std::getline(lines, line);) n += line.rfind(prefix, 0) == 0;
    return n;
  };
  EXPECT_EQ(count("v "), 3u + 8u);
  EXPECT_EQ(count("vn "), 11u);
  EXPECT_EQ(count("vt "), 11u);
  EXPECT_EQ(count("f "), 1u + 4u);
  EXPECT_NE(obj.find("g branches\n"), std::string::npos);
  EXPECT_NE(obj.find("g leaves\n"), std::string::npos);
  EXPECT_NE(obj.find("f 1/1/1 2/2/2 3/3/3\n"), std::string::npos);
  EXPECT_NE(obj.find("f 4/4/4 5/5/5 6/6/6\n"), std::string::npos);  // the first leaf
  EXPECT_NE(obj.find("\nf 8/8/8 10/10/10 11/11/11\n"), std::string::npos);  // the last
}

TEST(MeshExport, PlyHeaderCountsAndBinarySize) {
  std::string ply = ply_bytes(small_mesh());
  size_t end = ply.find("end_header\n");
  ASSERT_NE(end, std::string::npos);
  std::string header = ply.substr(0, end);
  EXPECT_NE(header.find("format binary_little_endian 1.0\n"), std::string::npos);
  EXPECT_NE(header.find("element vertex 11\n"), std::string::npos);
  EXPECT_NE(header.find("element face 5\n"), std::string::npos);
  EXPECT_NE(header.find("property float nx\n"), std::string::npos);
  size_t body = ply.size() - end - std::strlen("end_header\n");
  EXPECT_EQ(body, 11u * 8u * 4u + 5u * (1u + 3u * 4u));
}

TEST(MeshExport, GlbReadsBackWithTwoMeshes) {
  std::string glb = glb_bytes(small_mesh());
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error;
  std::string warning;
  ASSERT_TRUE(loader.LoadBinaryFromMemory(&model, &error, &warning,
                                          reinterpret_cast<const unsigned char*>(glb.data()),
                                          unsigned(glb.size())))
      << error;
  ASSERT_EQ(model.meshes.size(), 2u);
  EXPECT_EQ(model.meshes[0].name, "branches");
  EXPECT_EQ(model.meshes[1].name, "leaves");
  const tinygltf::Primitive& leaves = model.meshes[1].primitives.at(0);
  const tinygltf::Accessor& position = model.accessors[size_t(leaves.attributes.at("POSITION"))];
  EXPECT_EQ(position.count, 8u);
  ASSERT_EQ(position.minValues.size(), 3u);
  EXPECT_NEAR(position.minValues[0], 0.95, 1e-6);
  EXPECT_NEAR(position.maxValues[1], 0.2, 1e-6);
  EXPECT_EQ(model.accessors[size_t(leaves.indices)].count, 12u);
  EXPECT_EQ(model.accessors[size_t(leaves.attributes.at("TEXCOORD_0"))].type, TINYGLTF_TYPE_VEC2);
  EXPECT_TRUE(model.materials[size_t(leaves.material)].doubleSided);
}

TEST(MeshExport, FailedWritesLeaveNoFile) {
  fs::path dir = fs::temp_directory_path() / ("boreas_mesh_export_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  // A folder that does not exist.
  EXPECT_THROW(write_tree_mesh((dir / "missing" / "t.obj").string(), MeshFormat::kObj,
                               small_mesh()),
               MeshWriteError);
  // A target that is a folder: the rename fails after the temporary file was written.
  fs::create_directories(dir / "t.ply" / "inside");
  try {
    write_tree_mesh((dir / "t.ply").string(), MeshFormat::kPly, small_mesh());
    ADD_FAILURE() << "no error";
  } catch (const MeshWriteError& e) {
    EXPECT_NE(std::string(e.what()).find("t.ply: cannot write"), std::string::npos) << e.what();
  }
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename());
  EXPECT_EQ(left, std::vector<std::string>{"t.ply"});  // the folder only, no temporary
  // And a good write leaves just the file.
  write_tree_mesh((dir / "ok.glb").string(), MeshFormat::kGlb, small_mesh());
  EXPECT_TRUE(fs::is_regular_file(dir / "ok.glb"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace boreas::render
