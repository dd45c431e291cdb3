// boreas meshes: binary glTF through tinygltf, built with boreas_gltf's helpers (its
// implementation is compiled once, in host's boreas_gltf).
//
// The file: one buffer; per part (branches, leaves) a mesh with one triangle primitive
// whose POSITION (with min and max), NORMAL and TEXCOORD_0 accessors and its indices each
// have their own buffer view; a node per mesh under one scene; a bark and a (double-sided)
// leaf material.
#include "boreas_gltf/gltf_building.h"
#include "mesh/tree_mesh.h"

namespace boreas::render {

namespace {

void add_part(tinygltf::Model& model, const MeshPart& part, int material) {
  // glTF has no empty accessors: a part without vertices (a leafless tree) is left out.
  if (part.vertex_count() == 0 || part.indices.empty()) return;
  gltf::add_triangle_mesh(model, part.positions, part.normals, part.uvs, part.indices, part.name,
                          material);
}

}  // namespace

std::string glb_bytes(const TreeMesh& mesh) {
  int bark = 0, leaf = 0;
  tinygltf::Model model = gltf::new_tree_model("boreas export-mesh", &bark, &leaf);
  model.asset.extras =
      tinygltf::Value(tinygltf::Value::Object{{"description", tinygltf::Value(mesh.description)}});
  add_part(model, mesh.branches, bark);
  add_part(model, mesh.leaves, leaf);

  std::string bytes;
  if (!gltf::glb_bytes(model, &bytes))
    throw MeshWriteError("glTF: tinygltf could not serialize the model");
  return bytes;
}

}  // namespace boreas::render
