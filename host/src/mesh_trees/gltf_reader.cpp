// boreas: a tree model from a glTF 2.0 file (.gltf or .glb), through tinygltf: the nodes of
// the default scene with their world transforms, each primitive under a node a run of
// triangles whose part its node's, mesh's and material's names choose.
#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "errors.h"
#include "mesh_trees/model_files.h"
#include "mesh_trees/model_import_internal.h"
#include "mesh_trees/part_builder.h"
#include "mesh_trees/part_selection.h"

namespace boreas::impl::model_import {

namespace {

using Mat4 = std::array<double, 16>;  // row-major

std::string labelled(const char* kind, size_t index, const std::string& name) {
  std::string s = std::string(kind) + " " + std::to_string(index);
  return name.empty() ? s : s + " '" + name + "'";
}

Mat4 identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 m{};
  for (size_t r = 0; r < 4; ++r) {
    for (size_t c = 0; c < 4; ++c) {
      for (size_t k = 0; k < 4; ++k) m[r * 4 + c] += a[r * 4 + k] * b[k * 4 + c];
    }
  }
  return m;
}

// A node's transform relative to its parent: its matrix (column-major in the file), else
// translation * rotation * scale.
Mat4 local_transform(const tinygltf::Node& node) {
  Mat4 m = identity();
  if (node.matrix.size() == 16) {
    for (size_t r = 0; r < 4; ++r) {
      for (size_t c = 0; c < 4; ++c) m[r * 4 + c] = node.matrix[c * 4 + r];
    }
    return m;
  }
  Vec3 t{0, 0, 0}, s{1, 1, 1};
  if (node.translation.size() == 3)
    t = {node.translation[0], node.translation[1], node.translation[2]};
  if (node.scale.size() == 3) s = {node.scale[0], node.scale[1], node.scale[2]};
  double x = 0, y = 0, z = 0, w = 1;
  if (node.rotation.size() == 4) {
    // The spec asks for a unit quaternion; exporters round, so it is normalised here.
    double len =
        std::sqrt(node.rotation[0] * node.rotation[0] + node.rotation[1] * node.rotation[1] +
                  node.rotation[2] * node.rotation[2] + node.rotation[3] * node.rotation[3]);
    if (len > 0.0 && std::isfinite(len)) {
      x = node.rotation[0] / len;
      y = node.rotation[1] / len;
      z = node.rotation[2] / len;
      w = node.rotation[3] / len;
    }
  }
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
                       2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                       2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
  for (size_t row = 0; row < 3; ++row) {
    for (size_t c = 0; c < 3; ++c) m[row * 4 + c] = r[row * 3 + c] * s[c];
    m[row * 4 + 3] = t[row];
  }
  return m;
}

Vec3 transform_point(const Mat4& m, const Vec3& p) {
  return {m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3],
          m[4] * p[0] + m[5] * p[1] + m[6] * p[2] + m[7],
          m[8] * p[0] + m[9] * p[1] + m[10] * p[2] + m[11]};
}

// Normals go through the inverse transpose of the upper 3x3 block A. With a0..a2 A's columns,
// cofactor(A) has columns a1 x a2, a2 x a0, a0 x a1 and equals det(A) inverse(A)^T; only the
// sign of det matters, since normals are normalised later.
struct NormalTransform {
  Vec3 columns[3];
  double det;

  explicit NormalTransform(const Mat4& m) {
    Vec3 a0{m[0], m[4], m[8]}, a1{m[1], m[5], m[9]}, a2{m[2], m[6], m[10]};
    det = dot(a0, cross(a1, a2));
    double sign = det < 0.0 ? -1.0 : 1.0;
    columns[0] = scale(cross(a1, a2), sign);
    columns[1] = scale(cross(a2, a0), sign);
    columns[2] = scale(cross(a0, a1), sign);
  }
  Vec3 apply(const Vec3& n) const {
    return add(add(scale(columns[0], n[0]), scale(columns[1], n[1])), scale(columns[2], n[2]));
  }
};

// Geometry compression needs decoders that boreas does not carry: say so, rather than
// failing later on accessors without data.
void check_required_extensions(const std::string& path, const tinygltf::Model& model) {
  for (const std::string& ext : model.extensionsRequired) {
    if (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression" ||
        ext == "KHR_mesh_quantization") {
      fail_argument(about(path) + "the file needs the glTF extension " + ext +
                    ", which boreas does not read: export it without mesh compression");
    }
  }
}

class GltfReader {
 public:
  GltfReader(const std::string& path, const tinygltf::Model& model, const PartSelector& selector)
      : path_(path), model_(model), selector_(selector), builders_(pools_) {}

  MeshModel read() {
    walk(root_nodes());
    search_.name_kinds = "node, mesh or material";
    search_.lists = {&node_names_, &mesh_names_, &material_names_};
    if (skipped_trunk_primitives_ > 0) {
      search_.skipped_note = std::to_string(skipped_trunk_primitives_) +
                             " primitive(s) were skipped because their mode is not TRIANGLES "
                             "(boreas reads triangle lists only; export triangulated meshes)";
    }
    return finish(path_, selector_, builders_, search_);
  }

 private:
  // The nodes the default scene starts from; all root nodes when there is no scene.
  std::vector<int> root_nodes() const {
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      // Without a default scene the spec leaves the choice to the reader: the first one.
      size_t scene = model_.defaultScene >= 0 && size_t(model_.defaultScene) < model_.scenes.size()
                         ? size_t(model_.defaultScene)
                         : 0;
      roots = model_.scenes[scene].nodes;
    } else {
      std::vector<char> is_child(model_.nodes.size(), 0);
      for (const tinygltf::Node& node : model_.nodes) {
        for (int child : node.children) {
          if (child >= 0 && size_t(child) < is_child.size()) is_child[size_t(child)] = 1;
        }
      }
      for (size_t i = 0; i < model_.nodes.size(); ++i) {
        if (!is_child[i]) roots.push_back(int(i));
      }
    }
    return roots;
  }

  // Every node under the roots with its world transform, its mesh read where it has one.
  // Depth-first with an explicit stack: a deep (or malicious) hierarchy cannot overflow the
  // call stack.
  void walk(const std::vector<int>& roots) {
    struct Pending {
      int node;
      Mat4 parent;
    };
    std::vector<Pending> stack;
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) stack.push_back({*r, identity()});
    std::vector<char> reached(model_.nodes.size(), 0);
    while (!stack.empty()) {
      Pending p = stack.back();
      stack.pop_back();
      if (p.node < 0 || size_t(p.node) >= model_.nodes.size()) {
        fail_argument(about(path_) + "refers to node " + std::to_string(p.node) +
                      ", but the file has " + std::to_string(model_.nodes.size()) + " nodes");
      }
      const tinygltf::Node& node = model_.nodes[size_t(p.node)];
      if (reached[size_t(p.node)]) {
        fail_argument(about(path_) + labelled("node", size_t(p.node), node.name) +
                      " is reached twice: a glTF node hierarchy must be a tree");
      }
      reached[size_t(p.node)] = 1;
      Mat4 world = multiply(p.parent, local_transform(node));
      if (node.mesh >= 0) read_mesh_instance(size_t(p.node), world);
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) {
        stack.push_back({*c, world});
      }
    }
  }

  void read_mesh_instance(size_t node_index, const Mat4& world) {
    const tinygltf::Node& node = model_.nodes[node_index];
    if (size_t(node.mesh) >= model_.meshes.size()) {
      fail_argument(about(path_) + labelled("node", node_index, node.name) + " refers to mesh " +
                    std::to_string(node.mesh) + ", but the file has " +
                    std::to_string(model_.meshes.size()) + " meshes");
    }
    const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
    node_names_.add(node.name);
    mesh_names_.add(mesh.name);
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = mesh.primitives[p];
      std::string material;
      if (primitive.material >= 0 && size_t(primitive.material) < model_.materials.size()) {
        material = model_.materials[size_t(primitive.material)].name;
      }
      material_names_.add(material);
      Part part = selector_.classify({node.name, mesh.name, material});
      if (part == Part::kNone) continue;
      if (part == Part::kTrunk) ++search_.matched_runs;
      // Points, lines, strips and fans are skipped: tree exports are triangle lists, and a
      // trunk made only of other modes is reported by the no-trunk error.
      if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
        if (part == Part::kTrunk) ++skipped_trunk_primitives_;
        continue;
      }
      std::string where = labelled("mesh", size_t(node.mesh), mesh.name) + " primitive " +
                          std::to_string(p) + " (" + labelled("node", node_index, node.name) + ")";
      read_primitive(primitive, world, part, where);
    }
  }

  // A primitive's vertex data as the file has it (normals and uvs empty when absent), and
  // its triangles' indices.
  struct PrimitiveData {
    std::vector<double> positions, normals, uvs;
    std::vector<uint32_t> indices;
    size_t count = 0;  // vertices
  };
  // Where a primitive's vertices start in each pool.
  struct PoolBases {
    int64_t position = 0, normal = 0, uv = 0;
  };

  void read_primitive(const tinygltf::Primitive& primitive, const Mat4& world, Part part,
                      const std::string& where) {
    const PrimitiveData data = primitive_data(primitive, where);
    const NormalTransform normal_transform(world);
    const PoolBases bases = append_to_pools(data, world, normal_transform);
    // A mirroring transform turns the faces inside out; swapping two corners keeps them
    // counter-clockwise seen from the front, as the spec asks renderers to do.
    add_triangles(data, bases, normal_transform.det < 0.0, part, where);
  }

  PrimitiveData primitive_data(const tinygltf::Primitive& primitive,
                               const std::string& where) const {
    GltfAccessors reader(model_, about(path_) + where + ", ");
    auto attribute = [&](const char* name) {
      auto found = primitive.attributes.find(name);
      return found == primitive.attributes.end() ? -1 : found->second;
    };
    PrimitiveData d;
    const int position_accessor = attribute("POSITION");
    if (position_accessor < 0) fail_argument(about(path_) + where + " has no POSITION attribute");
    d.positions = reader.floats(position_accessor, "POSITION", TINYGLTF_TYPE_VEC3);
    const size_t count = d.positions.size() / 3;
    d.count = count;
    if (attribute("NORMAL") >= 0) {
      d.normals = reader.floats(attribute("NORMAL"), "NORMAL", TINYGLTF_TYPE_VEC3);
    }
    if (attribute("TEXCOORD_0") >= 0) {
      d.uvs = reader.floats(attribute("TEXCOORD_0"), "TEXCOORD_0", TINYGLTF_TYPE_VEC2);
    }
    if ((!d.normals.empty() && d.normals.size() / 3 != count) ||
        (!d.uvs.empty() && d.uvs.size() / 2 != count)) {
      fail_argument(about(path_) + where +
                    ": NORMAL or TEXCOORD_0 has a different count than POSITION (" +
                    std::to_string(count) + ")");
    }

    if (primitive.indices >= 0) {
      d.indices = reader.indices(primitive.indices, "indices");
    } else {
      d.indices.resize(count);
      for (size_t i = 0; i < count; ++i) d.indices[i] = uint32_t(i);
    }
    if (d.indices.size() % 3 != 0) {
      fail_argument(about(path_) + where + ": " + std::to_string(d.indices.size()) +
                    " indices do not make whole triangles (not a multiple of 3)");
    }
    return d;
  }

  // The primitive's vertices in model space, appended to the pools.
  PoolBases append_to_pools(const PrimitiveData& d, const Mat4& world,
                            const NormalTransform& normal_transform) {
    const PoolBases bases{int64_t(pools_.positions.size()), int64_t(pools_.normals.size()),
                          int64_t(pools_.uvs.size())};
    for (size_t i = 0; i < d.count; ++i) {
      pools_.positions.push_back(transform_point(
          world, {d.positions[3 * i], d.positions[3 * i + 1], d.positions[3 * i + 2]}));
      if (!d.normals.empty()) {
        pools_.normals.push_back(
            normal_transform.apply({d.normals[3 * i], d.normals[3 * i + 1], d.normals[3 * i + 2]}));
      }
      if (!d.uvs.empty()) pools_.uvs.push_back({d.uvs[2 * i], d.uvs[2 * i + 1]});
    }
    return bases;
  }

  // The primitive's triangles to its part's builder, each index checked.
  void add_triangles(const PrimitiveData& d, const PoolBases& bases, bool mirrored, Part part,
                     const std::string& where) {
    for (size_t t = 0; t < d.indices.size(); t += 3) {
      Corner c[3];
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t i = d.indices[t + k];
        if (i >= d.count) {
          fail_argument(about(path_) + where + ": index " + std::to_string(i) + " (at " +
                        std::to_string(t + k) + ") is out of range: the primitive has " +
                        std::to_string(d.count) + " vertices");
        }
        const Vec3& p = pools_.positions[size_t(bases.position + i)];
        if (!finite(p)) {
          fail_argument(about(path_) + "vertex " + std::to_string(i) + " of " + where +
                        ", in the " + part_name(part) + " part, has a non-finite position " +
                        vec_text(p) + " (after the node transforms)");
        }
        c[k].position = bases.position + i;
        c[k].normal = d.normals.empty() ? -1 : bases.normal + i;
        c[k].uv = d.uvs.empty() ? -1 : bases.uv + i;
      }
      if (mirrored) std::swap(c[1], c[2]);
      builders_[part].add_triangle(c[0], c[1], c[2]);
    }
  }

  const std::string& path_;
  const tinygltf::Model& model_;
  const PartSelector& selector_;
  SourcePools pools_;
  PartBuilders builders_;
  NameList node_names_{"nodes"};
  NameList mesh_names_{"meshes"};
  NameList material_names_{"materials"};
  TrunkSearch search_;
  size_t skipped_trunk_primitives_ = 0;
};

}  // namespace

MeshModel load_gltf(const std::string& path, const std::string& bytes,
                    const PartSelector& selector) {
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) {
    fail_argument(about(path) + "larger than 4 GiB, more than tinygltf reads");
  }
  tinygltf::Model model;
  std::string error;
  const bool ok = parse_gltf(bytes, path, &model, &error);
  if (!ok) {
    fail_argument(about(path) + "malformed glTF file (tinygltf: " +
                  (error.empty() ? std::string("no reason given") : trim(error)) + ")");
  }
  check_required_extensions(path, model);
  return GltfReader(path, model, selector).read();
}

}  // namespace boreas::impl::model_import
