// boreas render: an imported tree's static shading attributes (mesh_tree_surface.h).
#include "gl/mesh_tree_surface.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numeric>

namespace boreas::render {

namespace {

glm::vec3 position(const boreas_vertex& v) {
  return glm::vec3(v.position[0], v.position[1], v.position[2]);
}
glm::vec3 normal(const boreas_vertex& v) {
  return glm::vec3(v.normal[0], v.normal[1], v.normal[2]);
}
glm::vec2 uv(const boreas_vertex& v) { return glm::vec2(v.uv[0], v.uv[1]); }

// One triangle's surface derivatives dP/du and dP/dv (m per uv unit); false where its uvs
// are degenerate.
bool uv_derivatives(const boreas_vertex& a, const boreas_vertex& b, const boreas_vertex& c,
                    glm::vec3* dp_du, glm::vec3* dp_dv) {
  glm::vec3 e1 = position(b) - position(a), e2 = position(c) - position(a);
  glm::vec2 t1 = uv(b) - uv(a), t2 = uv(c) - uv(a);
  float det = t1.x * t2.y - t2.x * t1.y;
  if (!(std::abs(det) > 1e-12f)) return false;
  *dp_du = (e1 * t2.y - e2 * t1.y) / det;
  *dp_dv = (e2 * t1.x - e1 * t2.x) / det;
  return std::isfinite(dp_du->x + dp_du->y + dp_du->z + dp_dv->x + dp_dv->y + dp_dv->z);
}

// The unit direction in the plane normal to n nearest `toward`; +Y, then +X when that is
// (nearly) along n.
glm::vec3 tangent_toward(const glm::vec3& n, const glm::vec3& toward) {
  for (glm::vec3 d : {toward, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)}) {
    glm::vec3 t = d - glm::dot(d, n) * n;
    if (glm::dot(t, t) > 1e-8f * std::max(glm::dot(d, d), 1e-30f)) return glm::normalize(t);
  }
  return glm::vec3(0.0f, 0.0f, 1.0f);
}

float median(std::vector<float>& values) {
  auto middle = values.begin() + ptrdiff_t(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Per vertex the direction of the texture's +v on the surface: the triangles' dP/dv
// (unit, area-weighted) summed, made normal to the vertex's normal.
std::vector<glm::vec3> along_directions(const std::vector<boreas_vertex>& vertices,
                                        const std::vector<uint32_t>& indices) {
  std::vector<glm::vec3> sum(vertices.size(), glm::vec3(0.0f));
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const boreas_vertex &a = vertices[indices[t]], &b = vertices[indices[t + 1]],
                        &c = vertices[indices[t + 2]];
    glm::vec3 du, dv;
    if (!uv_derivatives(a, b, c, &du, &dv) || glm::dot(dv, dv) == 0.0f) continue;
    float area =
        0.5f * glm::length(glm::cross(position(b) - position(a), position(c) - position(a)));
    glm::vec3 w = glm::normalize(dv) * area;
    for (int k = 0; k < 3; ++k) sum[indices[t + size_t(k)]] += w;
  }
  std::vector<glm::vec3> out(vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v) out[v] = tangent_toward(normal(vertices[v]), sum[v]);
  return out;
}

}  // namespace

std::vector<uint32_t> uv_islands(size_t vertex_count, const std::vector<uint32_t>& indices,
                                 uint32_t* island_count) {
  std::vector<uint32_t> parent(vertex_count);
  std::iota(parent.begin(), parent.end(), 0u);
  auto root = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    for (int k = 1; k < 3; ++k) {
      uint32_t a = root(indices[t]), b = root(indices[t + size_t(k)]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  std::vector<uint32_t> number(vertex_count, UINT32_MAX), out(vertex_count);
  uint32_t count = 0;
  for (size_t v = 0; v < vertex_count; ++v) {
    uint32_t r = root(uint32_t(v));
    if (number[r] == UINT32_MAX) number[r] = count++;
    out[v] = number[r];
  }
  if (island_count) *island_count = count;
  return out;
}

std::vector<float> bark_attributes(const std::vector<boreas_vertex>& vertices,
                                   const std::vector<uint32_t>& indices, float tile_m) {
  uint32_t islands = 0;
  std::vector<uint32_t> island = uv_islands(vertices.size(), indices, &islands);
  // Per island: metres per uv unit of every good triangle, and the uv extent.
  std::vector<std::vector<float>> m_per_u(islands), m_per_v(islands);
  std::vector<glm::vec2> lo(islands, glm::vec2(1e30f)), hi(islands, glm::vec2(-1e30f));
  for (size_t v = 0; v < vertices.size(); ++v) {
    lo[island[v]] = glm::min(lo[island[v]], uv(vertices[v]));
    hi[island[v]] = glm::max(hi[island[v]], uv(vertices[v]));
  }
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    glm::vec3 du, dv;
    if (!uv_derivatives(vertices[indices[t]], vertices[indices[t + 1]], vertices[indices[t + 2]],
                        &du, &dv))
      continue;
    m_per_u[island[indices[t]]].push_back(glm::length(du));
    m_per_v[island[indices[t]]].push_back(glm::length(dv));
  }
  // Repeats per uv unit, per island and axis (0: no usable uvs).
  auto repeats = [&](std::vector<float>& metres, float extent) {
    if (metres.empty()) return 0.0f;
    float per_unit = median(metres) / tile_m;
    float whole = std::round(per_unit * extent);
    return whole >= 1.0f && extent > 0.0f ? whole / extent : per_unit;
  };
  std::vector<glm::vec2> scale(islands);
  for (uint32_t i = 0; i < islands; ++i) {
    scale[i] =
        glm::vec2(repeats(m_per_u[i], hi[i].x - lo[i].x), repeats(m_per_v[i], hi[i].y - lo[i].y));
  }
  std::vector<glm::vec3> along = along_directions(vertices, indices);
  std::vector<float> out;
  out.reserve(vertices.size() * kMeshBarkFloats);
  for (size_t v = 0; v < vertices.size(); ++v) {
    glm::vec3 n = glm::normalize(normal(vertices[v]));
    glm::vec2 t = uv(vertices[v]) * scale[island[v]];
    out.insert(out.end(), {n.x, n.y, n.z, along[v].x, along[v].y, along[v].z, t.x, t.y});
  }
  return out;
}

std::vector<float> leaf_attributes(const std::vector<boreas_vertex>& vertices,
                                   const std::vector<uint32_t>& indices, const Bounds& crown) {
  uint32_t islands = 0;
  std::vector<uint32_t> island = uv_islands(vertices.size(), indices, &islands);
  std::vector<glm::vec2> lo(islands, glm::vec2(1e30f)), hi(islands, glm::vec2(-1e30f));
  for (size_t v = 0; v < vertices.size(); ++v) {
    lo[island[v]] = glm::min(lo[island[v]], uv(vertices[v]));
    hi[island[v]] = glm::max(hi[island[v]], uv(vertices[v]));
  }
  std::vector<glm::vec3> along = along_directions(vertices, indices);
  std::vector<float> out;
  out.reserve(vertices.size() * kMeshLeafFloats);
  for (size_t v = 0; v < vertices.size(); ++v) {
    glm::vec2 extent = hi[island[v]] - lo[island[v]];
    bool textured = std::max(extent.x, extent.y) > 1e-6f;
    glm::vec2 t = textured ? uv(vertices[v]) : glm::vec2(-1.0f);
    float occlusion = leaf_occlusion(position(vertices[v]), crown);
    out.insert(out.end(), {along[v].x, along[v].y, along[v].z, t.x, t.y, occlusion});
  }
  return out;
}

}  // namespace boreas::render
