// boreas: reads a tree model made in another package (Wavefront OBJ through tinyobjloader,
// glTF 2.0 through tinygltf) into its trunk and leaves parts.
//
// Both readers reduce the file to runs of triangles (an OBJ shape's faces of one material, a
// glTF primitive under one node), pick each run's part from its names (PartSelector), and give
// its triangles, as indices into pools of the file's positions, normals and uvs, to that
// part's PartBuilder. The builder makes one vertex per distinct (position, normal, uv) triple,
// so vertices the file shares stay shared, and fills in face normals where the file has none.
#include "mesh_trees/model_import.h"

#include <tiny_gltf.h>

// tinyobjloader is header-only here: boreas_objects compiles it with hidden visibility, so
// its symbols stay private to the library (the Debian package's libtinyobjloader.so would
// add a run-time dependency for the same code).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "errors.h"
#include "mesh_trees/model_files.h"

namespace boreas::impl {

namespace {

namespace fs = std::filesystem;

using Vec3 = std::array<double, 3>;
using Vec2 = std::array<double, 2>;
using Mat4 = std::array<double, 16>;  // row-major

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
bool finite(const Vec3& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

std::string lowercase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string trim(std::string_view s) {
  const char* space = " \t\r\n";
  size_t begin = s.find_first_not_of(space);
  if (begin == std::string_view::npos) return {};
  size_t end = s.find_last_not_of(space);
  return std::string(s.substr(begin, end - begin + 1));
}

std::string vec_text(const Vec3& v) {
  std::ostringstream out;
  out << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
  return out.str();
}

std::string quoted(const std::string& s) { return "\"" + s + "\""; }

// Every message starts with the file, so that a scene with many models says which one failed.
std::string about(const std::string& path) { return "tree model '" + path + "': "; }

// ---- part selection ----

enum class Part { kNone, kTrunk, kLeaves };

const char* part_name(Part part) { return part == Part::kTrunk ? "trunk" : "leaves"; }

// One part's comma-separated names, matched case-insensitively as substrings.
class NameSelector {
 public:
  explicit NameSelector(const std::string& list) : text_(list) {
    std::istringstream in(list);
    std::string item;
    while (std::getline(in, item, ',')) {
      std::string name = lowercase(trim(item));
      if (!name.empty()) names_.push_back(name);
    }
  }
  bool matches(std::string_view name) const {
    if (name.empty()) return false;
    std::string lower = lowercase(name);
    return std::any_of(names_.begin(), names_.end(),
                       [&](const std::string& n) { return lower.find(n) != std::string::npos; });
  }
  bool empty() const { return names_.empty(); }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
  std::vector<std::string> names_;
};

class PartSelector {
 public:
  explicit PartSelector(const ModelPartSelection& selection)
      : trunk_(selection.trunk), leaves_(selection.leaves) {}

  // names: a run's names, most specific first; the first one that either part matches
  // decides. A name that matches both goes to the leaves: exporters name leaf cards after
  // what they hang on ("branch_leaves", "twig_leaf"), while trunk geometry rarely carries a
  // leaf word.
  Part classify(std::initializer_list<std::string_view> names) const {
    for (std::string_view name : names) {
      if (leaves_.matches(name)) return Part::kLeaves;
      if (trunk_.matches(name)) return Part::kTrunk;
    }
    return Part::kNone;
  }
  const NameSelector& trunk() const { return trunk_; }
  const NameSelector& leaves() const { return leaves_; }

 private:
  NameSelector trunk_;
  NameSelector leaves_;
};

// The distinct names of one kind in a file, in order of first appearance, for the error that
// asks the user to pick the trunk by name.
struct NameList {
  std::string kind;  // plural, as the message says it: "objects/groups", "materials"
  std::vector<std::string> names;
  std::unordered_set<std::string> seen;

  explicit NameList(std::string k) : kind(std::move(k)) {}
  void add(const std::string& name) {
    if (!name.empty() && seen.insert(name).second) names.push_back(name);
  }
};

// Why the trunk came out empty, as the readers saw it.
struct TrunkSearch {
  std::string name_kinds;    // what the names are matched against: "object/group or material"
  size_t matched_runs = 0;   // runs whose names chose the trunk
  std::string skipped_note;  // why matched runs gave no triangles, if the reader knows
  std::vector<const NameList*> lists;
};

[[noreturn]] void fail_no_trunk(const std::string& path, const PartSelector& selector,
                                const TrunkSearch& search) {
  // Enough names to recognise the model's parts; a SpeedTree export can have thousands.
  constexpr size_t kMaxListed = 12;
  std::ostringstream m;
  m << about(path) << "no trunk triangles: ";
  if (selector.trunk().empty()) {
    m << "the trunk part's names are empty.";
  } else if (search.matched_runs == 0) {
    m << "no " << search.name_kinds << " name contains any of the trunk part's names "
      << quoted(selector.trunk().text()) << " (comma-separated, case-insensitive).";
  } else {
    m << "the " << search.matched_runs << " part(s) named by the trunk part's names "
      << quoted(selector.trunk().text()) << " have no triangles"
      << (search.skipped_note.empty() ? "." : ": " + search.skipped_note);
  }

  std::string example;
  bool any = false;
  for (const NameList* list : search.lists) {
    if (list->names.empty()) continue;
    m << (any ? "; " : " The file has ") << list->kind << " ";
    for (size_t i = 0; i < list->names.size() && i < kMaxListed; ++i) {
      m << (i ? ", " : "") << quoted(list->names[i]);
    }
    if (list->names.size() > kMaxListed) {
      m << " and " << list->names.size() - kMaxListed << " more";
    }
    any = true;
    for (const std::string& name : list->names) {
      if (example.empty() && !selector.leaves().matches(name)) example = name;
    }
  }
  if (any) {
    m << ". Set the trunk part to a comma-separated list of these names (or parts of them)";
    if (!example.empty()) m << ", e.g. " << quoted(example);
    m << ".";
  } else {
    m << " The file names no " << search.name_kinds
      << ": name the trunk in the modelling package and set the trunk part to that name.";
  }
  fail_argument(m.str());
}

// ---- building a part ----

// The file's vertex data that triangles refer to. glTF positions and normals are already in
// model space (the node transforms applied); normals are not yet unit.
struct SourcePools {
  std::vector<Vec3> positions;  // m
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;
};

// Where a triangle corner's data is in the pools; -1: the file gives none.
struct Corner {
  int64_t position = -1;
  int64_t normal = -1;
  int64_t uv = -1;
  bool operator==(const Corner& o) const {
    return position == o.position && normal == o.normal && uv == o.uv;
  }
};

struct CornerHash {
  size_t operator()(const Corner& c) const {
    uint64_t h = uint64_t(c.position) * 0x9E3779B97F4A7C15ull;
    h ^= uint64_t(c.normal) + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2);
    h ^= uint64_t(c.uv) + 0x94D049BB133111EBull + (h << 6) + (h >> 2);
    return size_t(h);
  }
};

class PartBuilder {
 public:
  explicit PartBuilder(const SourcePools& pools) : pools_(pools) {}

  void add_triangle(const Corner& a, const Corner& b, const Corner& c) {
    indices_.push_back(vertex_for(a));
    indices_.push_back(vertex_for(b));
    indices_.push_back(vertex_for(c));
  }

  MeshPart finish() const {
    std::unordered_map<int64_t, FaceNormals> face_normals = accumulate_face_normals();
    MeshPart part;
    part.positions.reserve(3 * vertices_.size());
    part.normals.reserve(3 * vertices_.size());
    part.uvs.reserve(2 * vertices_.size());
    for (const Corner& v : vertices_) {
      const Vec3& p = pools_.positions[size_t(v.position)];
      Vec3 n{};
      bool has_normal = v.normal >= 0 && unit(pools_.normals[size_t(v.normal)], &n);
      if (!has_normal) n = face_normals.at(v.position).unit();
      Vec2 uv = v.uv >= 0 ? pools_.uvs[size_t(v.uv)] : Vec2{0.0, 0.0};
      for (int k = 0; k < 3; ++k) part.positions.push_back(float(p[size_t(k)]));
      for (int k = 0; k < 3; ++k) part.normals.push_back(float(n[size_t(k)]));
      part.uvs.push_back(float(uv[0]));
      part.uvs.push_back(float(uv[1]));
    }
    part.indices = indices_;
    return part;
  }

 private:
  // The area-weighted sum of the normals of the faces around one position.
  struct FaceNormals {
    Vec3 sum{};
    double magnitude = 0.0;  // sum of the faces' |cross|, to tell cancellation from zero
    Vec3 first{};            // the first non-degenerate face's, for when the sum cancels
    bool has_first = false;

    Vec3 unit() const {
      Vec3 n{};
      // Faces that cancel (a double-sided leaf card modelled as two opposite faces on the
      // same vertices) leave rounding noise, not a direction: then the first face decides.
      if (length(sum) > 1e-6 * magnitude && PartBuilder::unit(sum, &n)) return n;
      if (has_first && PartBuilder::unit(first, &n)) return n;
      // Only degenerate faces touch this position: any unit vector keeps later stages
      // finite, and up (Y) is the least surprising.
      return {0.0, 1.0, 0.0};
    }
  };

  static bool unit(const Vec3& v, Vec3* out) {
    double len = length(v);
    if (!(len > 0.0) || !std::isfinite(len)) return false;
    *out = scale(v, 1.0 / len);
    return true;
  }

  uint32_t vertex_for(const Corner& c) {
    auto found = vertex_of_.find(c);
    if (found != vertex_of_.end()) return found->second;
    if (vertices_.size() >= std::numeric_limits<uint32_t>::max()) {
      fail_argument("tree model part has more vertices than 32-bit indices can address");
    }
    uint32_t index = uint32_t(vertices_.size());
    vertices_.push_back(c);
    vertex_of_.emplace(c, index);
    return index;
  }

  std::unordered_map<int64_t, FaceNormals> accumulate_face_normals() const {
    std::unordered_map<int64_t, FaceNormals> sums;
    for (size_t t = 0; t + 2 < indices_.size(); t += 3) {
      const Corner* c[3] = {&vertices_[indices_[t]], &vertices_[indices_[t + 1]],
                            &vertices_[indices_[t + 2]]};
      const Vec3& a = pools_.positions[size_t(c[0]->position)];
      const Vec3& b = pools_.positions[size_t(c[1]->position)];
      const Vec3& d = pools_.positions[size_t(c[2]->position)];
      // |cross| is twice the triangle's area: the sum weights each face by its area.
      Vec3 n = cross(sub(b, a), sub(d, a));
      double len = length(n);
      for (const Corner* corner : c) {
        FaceNormals& s = sums[corner->position];
        s.sum = add(s.sum, n);
        s.magnitude += len;
        if (!s.has_first && len > 0.0) {
          s.first = n;
          s.has_first = true;
        }
      }
    }
    return sums;
  }

  const SourcePools& pools_;
  std::unordered_map<Corner, uint32_t, CornerHash> vertex_of_;
  std::vector<Corner> vertices_;
  std::vector<uint32_t> indices_;
};

struct PartBuilders {
  explicit PartBuilders(const SourcePools& pools) : trunk(pools), leaves(pools) {}
  PartBuilder& operator[](Part part) { return part == Part::kTrunk ? trunk : leaves; }
  PartBuilder trunk;
  PartBuilder leaves;
};

MeshModel finish(const std::string& path, const PartSelector& selector,
                 const PartBuilders& builders, const TrunkSearch& search) {
  MeshModel model;
  model.trunk = builders.trunk.finish();
  if (model.trunk.indices.empty()) fail_no_trunk(path, selector, search);
  model.leaves = builders.leaves.finish();
  return model;
}

// ---- reading the file ----

// ---- Wavefront OBJ ----

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

MeshModel load_obj(const std::string& path, std::string text, const PartSelector& selector) {
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
  tinyobj::ObjReader reader;
  if (!reader.ParseFromString(kMaterialLibraryLine + text, material_library, config)) {
    fail_argument(about(path) + "malformed OBJ file (tinyobjloader: " +
                  trim(without_added_line(reader.Error())) + ")");
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  if (attrib.vertices.empty()) {
    fail_argument(about(path) + "not a Wavefront OBJ file, or an empty one: it has no vertices " +
                  "(`v` lines)");
  }
  check_obj_indices(path, reader);

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

  const std::vector<tinyobj::material_t>& materials = reader.GetMaterials();
  NameList shape_names("objects/groups");
  NameList material_names("materials");
  TrunkSearch search{"object/group or material", 0, "", {&shape_names, &material_names}};
  PartBuilders builders(pools);
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    shape_names.add(shape.name);
    const tinyobj::mesh_t& mesh = shape.mesh;
    // A shape's faces can change material; each (shape, material) run is classified once.
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
        material_names.add(material_name);
        Part part = selector.classify({shape.name, material_name});
        if (part == Part::kTrunk) ++search.matched_runs;
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
      builders[known->second].add_triangle(c[0], c[1], c[2]);
    }
  }
  return finish(path, selector, builders, search);
}

// ---- glTF 2.0 ----

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

    // Depth-first with an explicit stack: a deep (or malicious) hierarchy cannot overflow the
    // call stack.
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

  void read_primitive(const tinygltf::Primitive& primitive, const Mat4& world, Part part,
                      const std::string& where) {
    GltfAccessors reader(model_, about(path_) + where + ", ");
    auto attribute = [&](const char* name) {
      auto found = primitive.attributes.find(name);
      return found == primitive.attributes.end() ? -1 : found->second;
    };
    const int position_accessor = attribute("POSITION");
    if (position_accessor < 0) fail_argument(about(path_) + where + " has no POSITION attribute");
    std::vector<double> positions =
        reader.floats(position_accessor, "POSITION", TINYGLTF_TYPE_VEC3);
    const size_t count = positions.size() / 3;
    std::vector<double> normals, uvs;
    if (attribute("NORMAL") >= 0) {
      normals = reader.floats(attribute("NORMAL"), "NORMAL", TINYGLTF_TYPE_VEC3);
    }
    if (attribute("TEXCOORD_0") >= 0) {
      uvs = reader.floats(attribute("TEXCOORD_0"), "TEXCOORD_0", TINYGLTF_TYPE_VEC2);
    }
    if ((!normals.empty() && normals.size() / 3 != count) ||
        (!uvs.empty() && uvs.size() / 2 != count)) {
      fail_argument(about(path_) + where +
                    ": NORMAL or TEXCOORD_0 has a different count than POSITION (" +
                    std::to_string(count) + ")");
    }

    std::vector<uint32_t> indices;
    if (primitive.indices >= 0) {
      indices = reader.indices(primitive.indices, "indices");
    } else {
      indices.resize(count);
      for (size_t i = 0; i < count; ++i) indices[i] = uint32_t(i);
    }
    if (indices.size() % 3 != 0) {
      fail_argument(about(path_) + where + ": " + std::to_string(indices.size()) +
                    " indices do not make whole triangles (not a multiple of 3)");
    }

    const int64_t position_base = int64_t(pools_.positions.size());
    const int64_t normal_base = int64_t(pools_.normals.size());
    const int64_t uv_base = int64_t(pools_.uvs.size());
    NormalTransform normal_transform(world);
    for (size_t i = 0; i < count; ++i) {
      pools_.positions.push_back(
          transform_point(world, {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]}));
      if (!normals.empty()) {
        pools_.normals.push_back(
            normal_transform.apply({normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]}));
      }
      if (!uvs.empty()) pools_.uvs.push_back({uvs[2 * i], uvs[2 * i + 1]});
    }

    // A mirroring transform turns the faces inside out; swapping two corners keeps them
    // counter-clockwise seen from the front, as the spec asks renderers to do.
    const bool mirrored = normal_transform.det < 0.0;
    for (size_t t = 0; t < indices.size(); t += 3) {
      Corner c[3];
      for (size_t k = 0; k < 3; ++k) {
        const uint32_t i = indices[t + k];
        if (i >= count) {
          fail_argument(about(path_) + where + ": index " + std::to_string(i) + " (at " +
                        std::to_string(t + k) + ") is out of range: the primitive has " +
                        std::to_string(count) + " vertices");
        }
        const Vec3& p = pools_.positions[size_t(position_base + i)];
        if (!finite(p)) {
          fail_argument(about(path_) + "vertex " + std::to_string(i) + " of " + where +
                        ", in the " + part_name(part) + " part, has a non-finite position " +
                        vec_text(p) + " (after the node transforms)");
        }
        c[k].position = position_base + i;
        c[k].normal = normals.empty() ? -1 : normal_base + i;
        c[k].uv = uvs.empty() ? -1 : uv_base + i;
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

}  // namespace

MeshModel load_tree_model(const std::string& path, const ModelPartSelection& selection) {
  return load_tree_model(path, read_file_bytes(path, "tree model"), selection);
}

MeshModel load_tree_model(const std::string& path, const std::string& bytes,
                          const ModelPartSelection& selection) {
  const std::string extension = lowercase(fs::path(path).extension().string());
  const PartSelector selector(selection);
  if (extension == ".obj") return load_obj(path, bytes, selector);
  if (extension == ".gltf" || extension == ".glb") return load_gltf(path, bytes, selector);
  fail_argument(about(path) + "unknown file type '" + extension +
                "': boreas reads Wavefront OBJ (.obj) and glTF 2.0 (.gltf, .glb); export the model "
                "to one of these");
}

}  // namespace boreas::impl
