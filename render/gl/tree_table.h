// boreas render: a frame's generated trees laid out for the GPU once (shaders/tree_table.glsl):
// per tree its placement and box, per template its impostor's sphere, per draw (a tree's
// level of branches, or its leaves) its records and grid; the tables that find a tree from
// the records' one call's range records (its id) and a world's template's impostor; and the
// buffers the frame's commands go to (shaders/tree_ranges.comp), so that drawing every tree
// costs one compute dispatch a frame and four indirect draws a pass, whatever the number
// of trees.
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

  // boreas_tree_id indices covered by the id table, world templates by the template table.
  int ids() const { return ids_; }
  int world_templates() const { return world_templates_; }
  // Binds the tables to their shader storage bindings (10-12, 23, 24), the commands' and
  // handover lists' (13-16) and the draws' frame offsets (20).
  void bind() const;
  // The vertex array whose attribute 0 is each draw's base instance, with the branch grids'
  // element indices.
  unsigned vertex_array() const { return vao_.id(); }
  // The frame's commands: branch_draws() DrawElementsIndirectCommands for the scene pass
  // then as many for the shadow pass; leaf_draws() DrawArraysIndirectCommands each; the
  // handover's two impostor commands (scene, shadow) and its records (trees() each).
  unsigned branch_commands() const { return branch_commands_.id(); }
  unsigned leaf_commands() const { return leaf_commands_.id(); }
  unsigned handover_records() const { return handover_records_.id(); }
  unsigned handover_commands() const { return handover_commands_.id(); }
  // Marks these templates' impostors as baked (trees of others are always drawn in full).
  void mark_baked(const std::vector<int>& templates) const;
  // Zeroes the commands and empties the handover lists before the frame's dispatch.
  void reset_commands() const;

 private:
  // The layout, not the record buffers' names: the frame's buffers change as they grow,
  // and the bake's at rest are others again.
  struct Key {
    size_t branch_draws = 0, leaf_draws = 0, trees = 0, templates = 0;
    int last_branch_record = -1, last_leaf = -1;
    bool operator==(const Key& o) const {
      return branch_draws == o.branch_draws && leaf_draws == o.leaf_draws && trees == o.trees &&
             templates == o.templates && last_branch_record == o.last_branch_record &&
             last_leaf == o.last_leaf;
    }
  };
  static Key key_of(const FrameGeometry& g);
  void build(const FrameGeometry& g);
  void build_id_tables(const FrameGeometry& g);

  Key key_;
  bool built_ = false;
  int branch_draws_ = 0, leaf_draws_ = 0, trees_ = 0, templates_ = 0, ids_ = 0, world_templates_ = 0;
  std::vector<TreeDraws> tree_draws_;
  std::vector<int> entry_index_count_, entry_first_index_, entry_instances_, entry_first_record_;
  GlObject tree_buffer_, template_buffer_, draw_buffer_, draw_ids_, element_indices_;
  GlObject branch_commands_, leaf_commands_, handover_records_, handover_commands_, entry_frame_;
  GlObject tree_of_id_, template_of_world_;
  GlObject vao_;
};

}  // namespace boreas::render
