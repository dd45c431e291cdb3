// boreas meshes: leaf quads, OBJ and PLY text, and atomic file output.
#include "mesh/tree_mesh.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace boreas::render {

namespace {

namespace fs = std::filesystem;

void normalize(float v[3]) {
  float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (length > 0.0f) {
    for (int a = 0; a < 3; ++a) v[a] /= length;
  }
}

void cross(const float a[3], const float b[3], float out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// Appends the shortest text that reads back as v.
void append_float(std::string& out, float v) {
  char text[32];
  auto result = std::to_chars(text, text + sizeof text, v);
  out.append(text, result.ptr);
}

void append_line(std::string& out, const char* tag, const float* v, int n) {
  out += tag;
  for (int i = 0; i < n; ++i) {
    out += ' ';
    append_float(out, v[i]);
  }
  out += '\n';
}

void append_uint(std::string& out, uint64_t v) {
  char text[24];
  auto result = std::to_chars(text, text + sizeof text, v);
  out.append(text, result.ptr);
}

template <typename T>
void append_binary(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace

MeshPart branch_mesh(const std::vector<boreas_vertex>& vertices,
                     const std::vector<uint32_t>& indices) {
  MeshPart part;
  part.name = "branches";
  part.positions.reserve(vertices.size() * 3);
  part.normals.reserve(vertices.size() * 3);
  part.uvs.reserve(vertices.size() * 2);
  for (const boreas_vertex& v : vertices) {
    part.positions.insert(part.positions.end(), v.position, v.position + 3);
    part.normals.insert(part.normals.end(), v.normal, v.normal + 3);
    part.uvs.insert(part.uvs.end(), v.uv, v.uv + 2);
  }
  part.indices = indices;
  return part;
}

MeshPart leaf_mesh(const std::vector<boreas_leaf>& leaves) {
  MeshPart part;
  part.name = "leaves";
  part.positions.reserve(leaves.size() * 12);
  part.normals.reserve(leaves.size() * 12);
  part.uvs.reserve(leaves.size() * 8);
  part.indices.reserve(leaves.size() * 6);
  for (const boreas_leaf& leaf : leaves) {
    float axis[3] = {leaf.axis[0], leaf.axis[1], leaf.axis[2]};
    float normal[3] = {leaf.normal[0], leaf.normal[1], leaf.normal[2]};
    normalize(axis);
    normalize(normal);
    // across = axis x normal, so (across, axis, normal) is right-handed and the triangles
    // below turn counter-clockwise seen from the normal's side.
    float across[3];
    cross(axis, normal, across);
    normalize(across);
    float half = 0.5f * leaf.width;
    const float corner_u[4] = {0.0f, 1.0f, 1.0f, 0.0f};
    const float corner_v[4] = {0.0f, 0.0f, 1.0f, 1.0f};
    uint32_t first = uint32_t(part.vertex_count());
    for (int c = 0; c < 4; ++c) {
      float side = (corner_u[c] * 2.0f - 1.0f) * half;
      float along = corner_v[c] * leaf.length;
      for (int a = 0; a < 3; ++a) {
        part.positions.push_back(leaf.position[a] + across[a] * side + axis[a] * along);
        part.normals.push_back(normal[a]);
      }
      part.uvs.push_back(corner_u[c]);
      part.uvs.push_back(corner_v[c]);
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) part.indices.push_back(first + i);
  }
  return part;
}

std::optional<MeshFormat> mesh_format_for(const std::string& path) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension == ".obj") return MeshFormat::kObj;
  if (extension == ".ply") return MeshFormat::kPly;
  if (extension == ".glb") return MeshFormat::kGlb;
  return std::nullopt;
}

std::string obj_text(const TreeMesh& mesh) {
  std::string out;
  out.reserve((mesh.branches.vertex_count() + mesh.leaves.vertex_count()) * 100);
  out += "# boreas export-mesh: " + mesh.description + "\n";
  out += "# branches: ";
  append_uint(out, mesh.branches.vertex_count());
  out += " vertices, ";
  append_uint(out, mesh.branches.triangle_count());
  out += " triangles; leaves: ";
  append_uint(out, mesh.leaves.vertex_count());
  out += " vertices, ";
  append_uint(out, mesh.leaves.triangle_count());
  out += " triangles\no tree\n";
  // Indices count from 1 over the whole file; each group's vertices come just before its
  // faces, so a face's position, normal and texture coordinate share one number.
  uint64_t base = 1;
  for (const MeshPart* part : {&mesh.branches, &mesh.leaves}) {
    if (part->vertex_count() == 0) continue;
    out += "g " + part->name + "\n";
    for (size_t i = 0; i < part->vertex_count(); ++i) append_line(out, "v", &part->positions[3 * i], 3);
    for (size_t i = 0; i < part->vertex_count(); ++i) append_line(out, "vn", &part->normals[3 * i], 3);
    for (size_t i = 0; i < part->vertex_count(); ++i) append_line(out, "vt", &part->uvs[2 * i], 2);
    for (size_t t = 0; t < part->triangle_count(); ++t) {
      out += 'f';
      for (int c = 0; c < 3; ++c) {
        uint64_t index = base + part->indices[3 * t + size_t(c)];
        out += ' ';
        append_uint(out, index);
        out += '/';
        append_uint(out, index);
        out += '/';
        append_uint(out, index);
      }
      out += '\n';
    }
    base += part->vertex_count();
  }
  return out;
}

std::string ply_bytes(const TreeMesh& mesh) {
#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "ply_bytes writes the host's floats as binary_little_endian"
#endif
  size_t vertices = mesh.branches.vertex_count() + mesh.leaves.vertex_count();
  size_t faces = mesh.branches.triangle_count() + mesh.leaves.triangle_count();
  std::string out =
      "ply\n"
      "format binary_little_endian 1.0\n"
      "comment boreas export-mesh: " +
      mesh.description +
      "\n"
      "comment faces 0.." +
      std::to_string(mesh.branches.triangle_count()) + " (exclusive) are the branches, the " +
      std::to_string(mesh.leaves.triangle_count()) +
      " after them the leaves\n"
      "element vertex " +
      std::to_string(vertices) +
      "\n"
      "property float x\nproperty float y\nproperty float z\n"
      "property float nx\nproperty float ny\nproperty float nz\n"
      "property float s\nproperty float t\n"
      "element face " +
      std::to_string(faces) +
      "\n"
      "property list uchar uint vertex_indices\n"
      "end_header\n";
  out.reserve(out.size() + vertices * 32 + faces * 13);
  for (const MeshPart* part : {&mesh.branches, &mesh.leaves}) {
    for (size_t i = 0; i < part->vertex_count(); ++i) {
      for (int a = 0; a < 3; ++a) append_binary(out, part->positions[3 * i + size_t(a)]);
      for (int a = 0; a < 3; ++a) append_binary(out, part->normals[3 * i + size_t(a)]);
      for (int a = 0; a < 2; ++a) append_binary(out, part->uvs[2 * i + size_t(a)]);
    }
  }
  uint32_t base = 0;
  for (const MeshPart* part : {&mesh.branches, &mesh.leaves}) {
    for (size_t t = 0; t < part->triangle_count(); ++t) {
      append_binary(out, uint8_t(3));
      for (int c = 0; c < 3; ++c) append_binary(out, base + part->indices[3 * t + size_t(c)]);
    }
    base += uint32_t(part->vertex_count());
  }
  return out;
}

void write_file_atomically(const std::string& path, const std::string& bytes) {
  fs::path target(path);
  // Same folder, so the rename never crosses file systems; the pid keeps two writers apart.
  fs::path temporary = target;
  temporary += ".tmp-" + std::to_string(::getpid());
  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw MeshWriteError(path + ": cannot write: " + why);
  };
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) fail(std::strerror(errno));
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.flush();
    if (!out) fail(std::string("write failed: ") + std::strerror(errno));
  }
  std::error_code error;
  fs::rename(temporary, target, error);
  if (error) fail(error.message());
}

void write_tree_mesh(const std::string& path, MeshFormat format, const TreeMesh& mesh) {
  switch (format) {
    case MeshFormat::kObj:
      write_file_atomically(path, obj_text(mesh));
      return;
    case MeshFormat::kPly:
      write_file_atomically(path, ply_bytes(mesh));
      return;
    case MeshFormat::kGlb:
      write_file_atomically(path, glb_bytes(mesh));
      return;
  }
}

}  // namespace boreas::render
