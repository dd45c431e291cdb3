// boreas: the meadows and imported trees of boreas_world_export_animation, gathered as
// morphed meshes (boreas_gltf/animation_gltf.h). A meadow is cut into pieces of whole
// components (at most 65,535 strip vertices: 16-bit indices), each a base of its own in
// world space (less the piece's origin, kept in double); an imported tree's trunk and leaves
// are bases in its model's space, shared by every tree of that model (file and parts).
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "boreas_gltf/animation_gltf.h"
#include "export/clump_export.h"

namespace boreas::impl {

class World;

class MorphGather {
 public:
  // Checks every id (errors name meadows[i] / mesh_trees[i]) and adds the bases and copies
  // to *a, without keys yet; meadows as clumps where clumps.clumps > 0 (clump_export.h).
  MorphGather(World& world, const std::vector<boreas_meadow_id>& meadows,
              const std::vector<boreas_mesh_tree_id>& mesh_trees, const ClumpParams& clumps,
              gltf::ForestAnimation* a);
  // Appends every copy's vertices as the world has them now.
  void key();
  // Keys past the animation's last, for the clumps' loops to be sought in (clump_export.h):
  // how many the world is to be stepped for (none without clumps), and one such key.
  int loop_search_keys(int frames) const { return clumps_.empty() ? 0 : 2 * (frames - 1); }
  void search_key();
  // After the last key: the clumps' keys made loops of `frames` keys.
  void finish(int frames);

 private:
  struct MeadowPiece {
    size_t copy;                 // index in a_->morphed
    size_t first, end;           // its components [first, end)
  };
  struct MeadowCopies {
    boreas_meadow_id id;
    std::vector<MeadowPiece> pieces;
  };
  struct TreeCopy {
    boreas_mesh_tree_id id;
    boreas_mesh_part part;
    size_t copy;
  };
  void add_meadow(boreas_meadow_id id, size_t index);
  void add_mesh_tree(boreas_mesh_tree_id id, size_t index);

  World& world_;
  gltf::ForestAnimation* a_;
  std::vector<MeadowCopies> meadows_;
  std::vector<MeadowClumps> clumps_;
  std::vector<TreeCopy> trees_;
  std::map<std::string, int> model_bases_;  // model, parts and part -> base index
};

}  // namespace boreas::impl
