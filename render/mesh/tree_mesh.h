// boreas meshes: a tree as two triangle meshes, its branches (boreas_tree_get_mesh) and its
// leaves (one quad per leaf), written as OBJ, PLY or binary glTF by `boreas export-mesh`.
// Files are written to a temporary name next to the target and renamed into place, so a
// failure never leaves half a file behind.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "boreas/boreas.h"

namespace boreas::render {

// One mesh: per vertex a position (m), a unit normal and a texture coordinate; three
// indices per triangle, counter-clockwise seen from the side the normals face.
struct MeshPart {
  std::string name;
  std::vector<float> positions;  // 3 per vertex
  std::vector<float> normals;    // 3 per vertex
  std::vector<float> uvs;        // 2 per vertex
  std::vector<uint32_t> indices;

  size_t vertex_count() const { return positions.size() / 3; }
  size_t triangle_count() const { return indices.size() / 3; }
};

struct TreeMesh {
  MeshPart branches;
  MeshPart leaves;
  std::string description;  // one line for the file's header: species, seed, time
};

// The branch mesh as boreas_tree_get_mesh returns it.
MeshPart branch_mesh(const std::vector<boreas_vertex>& vertices,
                     const std::vector<uint32_t>& indices);

// Each leaf as a quad: from its position along its axis for its length, its width across
// (centred on the axis), facing its normal: 4 vertices (u across, v along the blade) and 2
// triangles.
MeshPart leaf_mesh(const std::vector<boreas_leaf>& leaves);

enum class MeshFormat { kObj, kPly, kGlb };

// The format a file name asks for by its extension (any case), or none.
std::optional<MeshFormat> mesh_format_for(const std::string& path);

// A file that could not be written; the message names it and says why.
class MeshWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes mesh to path in format; throws MeshWriteError, leaving no file (and no temporary
// one) behind.
void write_tree_mesh(const std::string& path, MeshFormat format, const TreeMesh& mesh);

// The bytes of each format (what write_tree_mesh writes).
std::string obj_text(const TreeMesh& mesh);
std::string ply_bytes(const TreeMesh& mesh);
std::string glb_bytes(const TreeMesh& mesh);  // gltf_writer.cpp, through tinygltf

// Writes bytes to path through a temporary file in the same folder and a rename; throws
// MeshWriteError.
void write_file_atomically(const std::string& path, const std::string& bytes);

}  // namespace boreas::render
