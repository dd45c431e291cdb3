// boreas tests: tree meshes of known structure built from tapered tubes (one connected
// run of triangles per branch, each starting inside its parent, seam vertices duplicated
// as exporters do) with quad leaves at the twigs' tips.
#pragma once

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "mesh_trees/obj_writer.h"
#include "mesh_trees/tree_model.h"

namespace boreas::test {

struct Tube {
  glm::dvec3 base{0.0};
  glm::dvec3 dir{0.0, 1.0, 0.0};  // unit
  double length = 1.0;
  double r_base = 0.1, r_tip = 0.05;
  int parent = -1;  // index in the tree's tubes
  int level = 0;
  uint32_t first_vertex = 0, vertex_count = 0;  // its vertices in the trunk part
};

inline glm::dvec3 tube_point(const Tube& t, double u) { return t.base + u * t.length * t.dir; }

// rings + 1 rings of sides + 1 vertices (the seam's first and last coincide), open ends.
inline void add_tube(impl::MeshPart* part, Tube* t, int sides = 8, int rings = 6) {
  glm::dvec3 ref = std::abs(t->dir.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  glm::dvec3 a = glm::normalize(glm::cross(t->dir, ref));
  glm::dvec3 b = glm::cross(t->dir, a);
  t->first_vertex = uint32_t(part->vertex_count());
  for (int i = 0; i <= rings; ++i) {
    double u = double(i) / rings;
    double r = t->r_base + u * (t->r_tip - t->r_base);
    for (int j = 0; j <= sides; ++j) {
      double phi = 2.0 * M_PI * (j % sides) / sides;
      glm::dvec3 n = std::cos(phi) * a + std::sin(phi) * b;
      glm::dvec3 p = tube_point(*t, u) + r * n;
      for (int k = 0; k < 3; ++k) {
        part->positions.push_back(float(p[k]));
        part->normals.push_back(float(n[k]));
      }
      part->uvs.push_back(float(j) / sides);
      part->uvs.push_back(float(u));
    }
  }
  t->vertex_count = uint32_t(part->vertex_count()) - t->first_vertex;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sides; ++j) {
      uint32_t v00 = t->first_vertex + i * (sides + 1) + j, v01 = v00 + 1;
      uint32_t v10 = v00 + (sides + 1), v11 = v10 + 1;
      part->indices.insert(part->indices.end(), {v00, v10, v11, v00, v11, v01});
    }
}

// A unit direction from azimuth (around Y, from +X towards +Z) and elevation, radians.
inline glm::dvec3 direction(double azimuth, double elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
          std::cos(elevation) * std::sin(azimuth)};
}

struct TubeTree {
  impl::MeshModel model;
  std::vector<Tube> tubes;     // tubes[0] is the stem
  std::vector<int> leaf_twig;  // per leaf, the tube it hangs from
};

// A stem, 3 limbs, 6 twigs, 6 level-3 twigs with a leaf at each tip, and one level-4
// twig: 17 branches of 5 levels, each thinner than its parent.
inline TubeTree make_tube_tree() {
  TubeTree tree;
  auto add = [&](int parent, double at, glm::dvec3 dir, double length, double r_base,
                 double r_tip) {
    Tube t;
    t.parent = parent;
    t.level = parent < 0 ? 0 : tree.tubes[parent].level + 1;
    t.base = parent < 0 ? glm::dvec3(0.0) : tube_point(tree.tubes[parent], at);
    t.dir = glm::normalize(dir);
    t.length = length;
    t.r_base = r_base;
    t.r_tip = r_tip;
    add_tube(&tree.model.trunk, &t);
    tree.tubes.push_back(t);
    return int(tree.tubes.size()) - 1;
  };
  add(-1, 0.0, {0, 1, 0}, 8.0, 0.30, 0.12);
  const double heights[3] = {3.0 / 8.0, 4.5 / 8.0, 6.0 / 8.0};
  for (int l = 0; l < 3; ++l) {
    double azimuth = 2.0 * M_PI * l / 3.0;
    int limb = add(0, heights[l], direction(azimuth, 0.7), 3.5, 0.12, 0.04);
    for (int s = 0; s < 2; ++s) {
      double side = s == 0 ? 0.9 : -0.9;
      int twig = add(limb, s == 0 ? 0.4 : 0.75, direction(azimuth + side, 0.5), 1.5, 0.04, 0.015);
      int small = add(twig, 0.6, direction(azimuth + 2.0 * side, 0.3), 0.6, 0.015, 0.006);
      if (l == 0 && s == 0)
        add(small, 0.5, direction(azimuth + 2.5 * side, 0.9), 0.25, 0.006, 0.003);
    }
  }
  // A leaf (two triangles) a little beyond each level-3 twig's tip.
  impl::MeshPart& leaves = tree.model.leaves;
  for (int i = 0; i < int(tree.tubes.size()); ++i) {
    const Tube& t = tree.tubes[i];
    if (t.level != 3) continue;
    glm::dvec3 p = tube_point(t, 1.0) + 0.005 * t.dir;
    glm::dvec3 side = glm::normalize(glm::cross(t.dir, glm::dvec3(0, 1, 0))) * 0.03;
    glm::dvec3 corners[4] = {p - side, p + side, p + side + 0.12 * t.dir, p - side + 0.12 * t.dir};
    uint32_t first = uint32_t(leaves.vertex_count());
    for (const glm::dvec3& c : corners) {
      for (int k = 0; k < 3; ++k) {
        leaves.positions.push_back(float(c[k]));
        leaves.normals.push_back(k == 1 ? 1.0f : 0.0f);
      }
      leaves.uvs.insert(leaves.uvs.end(), {0.0f, 0.0f});
    }
    leaves.indices.insert(leaves.indices.end(),
                          {first, first + 1, first + 2, first, first + 2, first + 3});
    tree.leaf_twig.push_back(i);
  }
  return tree;
}

// The tube tree (17 branches, 5 levels) as an OBJ with a "trunk" and a "leaves" object.
inline std::string write_tube_tree_obj(const std::filesystem::path& dir) {
  test::TubeTree tree = test::make_tube_tree();
  std::string path = (dir / "tubes.obj").string();
  std::ofstream out(path);
  impl::write_obj(out, tree.model);
  return path;
}

}  // namespace boreas::test
