// boreas render: a frame's generated trees laid out for the GPU once (shaders/tree_table.glsl):
// per tree its placement and box, per template its impostor's sphere, per draw (a tree's
// level of branches, or its leaves) its records and grid; and the buffers the per-pass
// commands go to (shaders/tree_draws.comp), so that drawing every tree costs one compute
// dispatch and three indirect draws a pass, whatever the number of trees.
#pragma once

#include <cstdint>
#include <vector>

#include "gl/gl_objects.h"
#include "gl/renderer.h"

namespace boreas::render {

class TreeTable {
 public:
  // Lays the geometry's trees out when they are not the ones laid out last (compared by
  // the record buffers' names and the lists' sizes and ends: O(1) a frame otherwise).
  void sync(const FrameGeometry& geometry);

  int branch_draws() const { return branch_draws_; }
  int leaf_draws() const { return leaf_draws_; }
  int trees() const { return trees_; }
  int templates() const { return templates_; }
  // The draw entries (base instances) of a tree's branches and leaves, for the baking.
  struct TreeDraws {
    std::vector<int> branch_entries;
    int leaf_entry = -1;
  };
  const TreeDraws& draws_of(int tree) const { return tree_draws_[size_t(tree)]; }
  // Element indices (into element_indices()) and instances of a branch entry.
  int index_count(int entry) const { return entry_index_count_[size_t(entry)]; }
  int first_index(int entry) const { return entry_first_index_[size_t(entry)]; }
  int instances(int entry) const { return entry_instances_[size_t(entry)]; }
  int first_record(int entry) const { return entry_first_record_[size_t(entry)]; }

  // Binds the tables to their shader storage bindings (10-12) and the commands' (13-16).
  void bind() const;
  // The vertex array whose attribute 0 is each draw's base instance, with the branch grids'
  // element indices.
  unsigned vertex_array() const { return vao_.id(); }
  unsigned branch_commands() const { return branch_commands_.id(); }
  unsigned leaf_commands() const { return leaf_commands_.id(); }
  unsigned impostor_records() const { return impostor_records_.id(); }
  unsigned impostor_command() const { return impostor_command_.id(); }
  // Marks these templates' impostors as baked (trees of others are always drawn in full).
  void mark_baked(const std::vector<int>& templates) const;
  // Empties the impostor list before a pass's dispatch.
  void reset_impostor_count() const;

 private:
  struct Key {
    unsigned branch_records = 0, leaf_records = 0;
    size_t branch_draws = 0, leaf_draws = 0, trees = 0, templates = 0;
    int last_branch_record = -1, last_leaf = -1;
    bool operator==(const Key& o) const {
      return branch_records == o.branch_records && leaf_records == o.leaf_records &&
             branch_draws == o.branch_draws && leaf_draws == o.leaf_draws && trees == o.trees &&
             templates == o.templates && last_branch_record == o.last_branch_record &&
             last_leaf == o.last_leaf;
    }
  };
  static Key key_of(const FrameGeometry& g);
  void build(const FrameGeometry& g);

  Key key_;
  bool built_ = false;
  int branch_draws_ = 0, leaf_draws_ = 0, trees_ = 0, templates_ = 0;
  std::vector<TreeDraws> tree_draws_;
  std::vector<int> entry_index_count_, entry_first_index_, entry_instances_, entry_first_record_;
  GlObject tree_buffer_, template_buffer_, draw_buffer_, draw_ids_, element_indices_;
  GlObject branch_commands_, leaf_commands_, impostor_records_, impostor_command_;
  GlObject vao_;
};

}  // namespace boreas::render
