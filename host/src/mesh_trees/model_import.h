// boreas: reads a tree model (Wavefront OBJ or glTF 2.0, .gltf or .glb) into its trunk
// and leaves parts.
#pragma once

#include <string>

#include "mesh_trees/tree_model.h"

namespace boreas::impl {

// Reads the model at `path` (type from the extension, case-insensitive) in its own units
// (m assumed, Y up; nothing is scaled).
//
// Parts: a run of triangles goes to the part whose names (ModelPartSelection) match the
// first of its names that either part matches — OBJ: the object/group name, then the face's
// material (`usemtl`; the .mtl file is not needed); glTF: the node name, then the mesh name,
// then the primitive's material name. A name that matches both parts goes to the leaves.
// The trunk must get triangles; the leaves may stay empty.
//
// Vertices: one per distinct (position, normal, uv) of the file within a part, so that
// vertices the file shares stay shared. Normals from the file (normalised), else the
// area-weighted normals of the part's faces around the same file position; uvs from the
// file, else zeros. OBJ polygons are triangulated by tinyobjloader.
//
// glTF: the nodes of the default scene (the first scene when none is named default; all
// root nodes when there is no scene) with their world transforms (matrix or TRS) applied to
// positions and, inverse-transposed, to normals; a mirroring transform flips the winding
// back to counter-clockwise. Attributes POSITION, NORMAL, TEXCOORD_0 (FLOAT, or normalised
// unsigned byte/short uvs), unsigned byte/short/int or no indices. Only mode TRIANGLES is
// read: primitives of other modes are skipped, and if that leaves the trunk empty the error
// says so. Images are not decoded; skins and morph targets are ignored (rest pose).
//
// Throws boreas::impl::Error naming the file and what is wrong: BOREAS_ERROR_IO when the
// file is missing or cannot be read; BOREAS_ERROR_INVALID_ARGUMENT for an unknown extension,
// a malformed file (with tinyobjloader's or tinygltf's message), no trunk triangles (listing
// the names the file does have), NaN or infinite positions (naming the vertex and the part),
// indices out of range.
MeshModel load_tree_model(const std::string& path, const ModelPartSelection& selection);
// The same for the file's bytes, already read (path names it, and external glTF buffers
// are found beside it).
MeshModel load_tree_model(const std::string& path, const std::string& bytes,
                          const ModelPartSelection& selection);

}  // namespace boreas::impl
