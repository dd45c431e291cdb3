// boreas: a tree model from a Wavefront OBJ file, through tinyobjloader: each shape's faces
// of one material are a run of triangles, its part chosen by the shape's and the material's
// names. The text is checked and cleaned first where tinyobjloader would read it wrong.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

// tinyobjloader is header-only here: boreas_objects compiles it with hidden visibility, so
// its symbols stay private to the library (the Debian package's libtinyobjloader.so would
// add a run-time dependency for the same code).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#include "errors.h"
#include "mesh_trees/model_import_internal.h"
#include "mesh_trees/part_builder.h"
#include "mesh_trees/part_selection.h"

namespace boreas::impl::model_import {

namespace {

// tinyobj drops the name of a material its .mtl does not define, and boreas needs only the
// names. So the reader gets a material library made from the file's own `usemtl` names
// instead of the .mtl: a missing or broken .mtl (common once a model has been passed
// around) costs nothing. The names are cut as tinyobj cuts them: the first word after
// `usemtl`.
std::vector<std::string> usemtl_names(const std::string& text) {
  std::vector<std::string> names;
  std::unordered_set<std::string> seen;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find_first_of("\r\n", pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    size_t start = line.find_first_not_of(" \t");
    if (start == std::string_view::npos || line.substr(start, 6) != "usemtl") continue;
    std::string_view rest = line.substr(start + 6);
    size_t word = rest.find_first_not_of(" \t");
    if (word == std::string_view::npos) continue;
    rest = rest.substr(word);
    std::string name(rest.substr(0, rest.find_first_of(std::string_view(" \t\r\0", 4))));
    if (!name.empty() && seen.insert(name).second) names.push_back(name);
  }
  return names;
}

// tinyobj reads the material library only at an `mtllib` line, so one goes in front of the
// file; its messages then count one line too many, which this takes back.
const char kMaterialLibraryLine[] = "mtllib boreas-usemtl-names.mtl\n";

std::string without_added_line(const std::string& message) {
  std::string out;
  size_t pos = 0;
  while (true) {
    size_t at = message.find("line", pos);
    if (at == std::string::npos) break;
    size_t digits = at + 4;
    if (digits < message.size() && message[digits] == ':') ++digits;
    if (digits < message.size() && message[digits] == ' ') ++digits;
    size_t end = digits;
    while (end < message.size() && std::isdigit(static_cast<unsigned char>(message[end]))) ++end;
    out.append(message, pos, digits - pos);
    if (end > digits && end - digits < 10) {
      out += std::to_string(std::stol(message.substr(digits, end - digits)) - 1);
    } else {
      out.append(message, digits, end - digits);
    }
    pos = end;
  }
  out.append(message, pos, std::string::npos);
  return out;
}

std::string shape_label(const tinyobj::shape_t& shape) {
  return shape.name.empty() ? "an unnamed object" : "'" + shape.name + "'";
}

// tinyobj resolves relative indices but checks few of them: every corner is checked here.
void check_obj_indices(const std::string& path, const tinyobj::ObjReader& reader) {
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const long positions = long(attrib.vertices.size() / 3);
  const long normals = long(attrib.normals.size() / 3);
  const long uvs = long(attrib.texcoords.size() / 2);
  auto check = [&](const tinyobj::shape_t& shape, int index, long count, const char* what,
                   const char* line) {
    if (index >= 0 && index < count) return;
    fail_argument(about(path) + "a face of " + shape_label(shape) + " uses " + what + " " +
                  std::to_string(long(index) + 1) + ", which is out of range: the file has " +
                  std::to_string(count) + " (`" + line + "` lines)");
  };
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    for (const tinyobj::index_t& i : shape.mesh.indices) {
      check(shape, i.vertex_index, positions, "vertex", "v");
      // -1 is tinyobj's "none"; anything else must exist.
      if (i.normal_index != -1) check(shape, i.normal_index, normals, "normal", "vn");
      if (i.texcoord_index != -1) check(shape, i.texcoord_index, uvs, "texture coordinate", "vt");
    }
  }
  // tinyobj drops a polygon with an index out of range when it triangulates, and only warns.
  const std::string& warning = reader.Warning();
  if (warning.find("invalid vertex index") != std::string::npos ||
      warning.find("out of bounds") != std::string::npos) {
    fail_argument(about(path) + "a face uses an index that is out of range (tinyobjloader: " +
                  trim(without_added_line(warning)) + ")");
  }
}

// The lines of an OBJ text as tinyobjloader splits them, at "\n", "\r\n" or a lone "\r"
// (a fuzzed file hid a `vw` line behind a "\r"): f(line number, first, end) each.
template <typename F>
void for_each_obj_line(std::string_view text, F&& f) {
  size_t line = 0;
  for (size_t at = 0; at < text.size();) {
    size_t end = text.find_first_of("\r\n", at);
    if (end == std::string_view::npos) end = text.size();
    f(++line, at, end);
    if (end == text.size()) break;
    at = end + (text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n' ? 2 : 1);
  }
}

// tinyobjloader reads `nan`, `inf` and a word that is no number as 0, which would move a
// vertex without a word said: every number on a `v`, `vn` or `vt` line must be a finite one,
// checked on the text (with the file's line numbers) before tinyobj reads it. Refused even
// where no face uses the vertex: the file is not what it would be read as.
void check_obj_numbers(const std::string& path, std::string_view text) {
  for_each_obj_line(text, [&](size_t line, size_t at, size_t end) {
    const std::string_view row = text.substr(at, end - at);
    auto token_at = [&](size_t from, size_t* next) {
      while (from < row.size() && std::isspace(static_cast<unsigned char>(row[from]))) ++from;
      size_t to = from;
      while (to < row.size() && !std::isspace(static_cast<unsigned char>(row[to]))) ++to;
      *next = to;
      return row.substr(from, to - from);
    };
    size_t next = 0;
    const std::string_view keyword = token_at(0, &next);
    if (keyword != "v" && keyword != "vn" && keyword != "vt") return;
    for (std::string_view token = token_at(next, &next); !token.empty() && token[0] != '#';
         token = token_at(next, &next)) {
      const std::string_view digits = token[0] == '+' ? token.substr(1) : token;
      double value = 0.0;
      const auto [stop, error] =
          std::from_chars(digits.data(), digits.data() + digits.size(), value);
      if (error == std::errc() && stop == digits.data() + digits.size() && std::isfinite(value))
        continue;
      fail_argument(about(path) + "line " + std::to_string(line) + ": the `" +
                    std::string(keyword) + "` line has '" + std::string(token) +
                    "', which is not a finite number (tinyobjloader would read it as 0)");
    }
  });
}

// Skin weights (`vw` lines) are not boreas's concern, and tinyobjloader converts their joint
// ids to int unchecked (a number past int's range is undefined behaviour; found by
// fuzz_obj): each such line is blanked before tinyobj reads the text, keeping the file's line
// numbers.
void blank_skin_weights(std::string& text) {
  for_each_obj_line(text, [&](size_t, size_t at, size_t end) {
    // tinyobj's test: "vw" after spaces and tabs, then a space or a tab.
    const size_t first = text.find_first_not_of(" \t", at);
    if (first < end && end - first > 2 && text.compare(first, 2, "vw") == 0 &&
        (text[first + 2] == ' ' || text[first + 2] == '\t'))
      std::fill(text.begin() + ptrdiff_t(at), text.begin() + ptrdiff_t(end), ' ');
  });
}

// The text parsed into reader: checked, cleaned, and given a material library of its own
// `usemtl` names. Throws Error (INVALID_ARGUMENT) when tinyobjloader cannot read it, it
// has no vertices, or an index is out of range.
void parse_obj(const std::string& path, std::string text, tinyobj::ObjReader* reader) {
  // A UTF-8 byte order mark (some Windows tools write one) would hide the first line's
  // keyword from tinyobj.
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  check_obj_numbers(path, text);
  blank_skin_weights(text);
  std::string material_library;
  for (const std::string& name : usemtl_names(text)) material_library += "newmtl " + name + "\n";

  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  if (!reader->ParseFromString(kMaterialLibraryLine + text, material_library, config)) {
    fail_argument(about(path) + "malformed OBJ file (tinyobjloader: " +
                  trim(without_added_line(reader->Error())) + ")");
  }
  const tinyobj::attrib_t& attrib = reader->GetAttrib();
  if (attrib.vertices.empty()) {
    fail_argument(about(path) + "not a Wavefront OBJ file, or an empty one: it has no vertices " +
                  "(`v` lines)");
  }
  check_obj_indices(path, *reader);
}

SourcePools obj_pools(const tinyobj::attrib_t& attrib) {
  SourcePools pools;
  for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3) {
    pools.positions.push_back({attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]});
  }
  for (size_t i = 0; i + 2 < attrib.normals.size(); i += 3) {
    pools.normals.push_back({attrib.normals[i], attrib.normals[i + 1], attrib.normals[i + 2]});
  }
  for (size_t i = 0; i + 1 < attrib.texcoords.size(); i += 2) {
    pools.uvs.push_back({attrib.texcoords[i], attrib.texcoords[i + 1]});
  }
  return pools;
}

// A shape's triangles to the builders of their parts. A shape's faces can change
// material; each (shape, material) run is classified once, its material's name noted.
void add_shape(const std::string& path, const tinyobj::shape_t& shape,
               const std::vector<tinyobj::material_t>& materials, const PartSelector& selector,
               const SourcePools& pools, NameList* material_names, TrunkSearch* search,
               PartBuilders* builders) {
  const tinyobj::mesh_t& mesh = shape.mesh;
  std::unordered_map<int, Part> part_of_material;
  size_t offset = 0;
  for (size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
    const size_t corners = mesh.num_face_vertices[f];
    const size_t first = offset;
    offset += corners;
    if (corners != 3 || offset > mesh.indices.size()) continue;  // triangulated: always 3
    int material = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
    const std::string& material_name = material >= 0 && size_t(material) < materials.size()
                                           ? materials[size_t(material)].name
                                           : std::string();
    auto known = part_of_material.find(material);
    if (known == part_of_material.end()) {
      material_names->add(material_name);
      Part part = selector.classify({shape.name, material_name});
      if (part == Part::kTrunk) ++search->matched_runs;
      known = part_of_material.emplace(material, part).first;
    }
    if (known->second == Part::kNone) continue;

    Corner c[3];
    for (size_t k = 0; k < 3; ++k) {
      const tinyobj::index_t& i = mesh.indices[first + k];
      c[k] = {i.vertex_index, i.normal_index, i.texcoord_index};
      const Vec3& p = pools.positions[size_t(i.vertex_index)];
      if (!finite(p)) {
        fail_argument(about(path) + "vertex " + std::to_string(i.vertex_index + 1) +
                      " (the file's `v` line number " + std::to_string(i.vertex_index + 1) +
                      "), used by " + shape_label(shape) + " in the " + part_name(known->second) +
                      " part, has a non-finite position " + vec_text(p));
      }
    }
    (*builders)[known->second].add_triangle(c[0], c[1], c[2]);
  }
}

}  // namespace

MeshModel load_obj(const std::string& path, std::string text, const PartSelector& selector) {
  tinyobj::ObjReader reader;
  parse_obj(path, std::move(text), &reader);
  const SourcePools pools = obj_pools(reader.GetAttrib());
  NameList shape_names("objects/groups");
  NameList material_names("materials");
  TrunkSearch search{"object/group or material", 0, "", {&shape_names, &material_names}};
  PartBuilders builders(pools);
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    shape_names.add(shape.name);
    add_shape(path, shape, reader.GetMaterials(), selector, pools, &material_names, &search,
              &builders);
  }
  return finish(path, selector, builders, search);
}

}  // namespace boreas::impl::model_import
