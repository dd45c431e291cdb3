// boreas: reads a tree model made in another package (Wavefront OBJ through tinyobjloader,
// glTF 2.0 through tinygltf) into its trunk and leaves parts.
//
// Both readers (obj_reader.cpp, gltf_reader.cpp; this file picks one by the extension)
// reduce the file to runs of triangles (an OBJ shape's faces of one material, a glTF
// primitive under one node), pick each run's part from its names (PartSelector,
// part_selection.cpp), and give its triangles, as indices into pools of the file's
// positions, normals and uvs, to that part's PartBuilder (part_builder.cpp). The builder
// makes one vertex per distinct (position, normal, uv) triple, so vertices the file shares
// stay shared, and fills in face normals where the file has none.
#include "mesh_trees/model_import.h"

#include <filesystem>
#include <string>

#include "errors.h"
#include "mesh_trees/model_files.h"
#include "mesh_trees/model_import_internal.h"
#include "mesh_trees/part_selection.h"

namespace boreas::impl {

MeshModel load_tree_model(const std::string& path, const ModelPartSelection& selection) {
  return load_tree_model(path, read_file_bytes(path, "tree model"), selection);
}

MeshModel load_tree_model(const std::string& path, const std::string& bytes,
                          const ModelPartSelection& selection) {
  const std::string extension =
      model_import::lowercase(std::filesystem::path(path).extension().string());
  const model_import::PartSelector selector(selection);
  if (extension == ".obj") return model_import::load_obj(path, bytes, selector);
  if (extension == ".gltf" || extension == ".glb")
    return model_import::load_gltf(path, bytes, selector);
  fail_argument(model_import::about(path) + "unknown file type '" + extension +
                "': boreas reads Wavefront OBJ (.obj) and glTF 2.0 (.gltf, .glb); export the model "
                "to one of these");
}

}  // namespace boreas::impl
