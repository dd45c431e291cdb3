// boreas: the trees of one TreeBatch::add() as it plans them (tree_batch.cpp,
// tree_batch_settled_add.cpp): private to those files.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "trees/tree_batch.h"

namespace boreas::impl {

// The trees of one add(): the template block of each (a known one, or one of the new ones,
// each built once) and the entries both kinds of block take.
struct TreeBatch::NewTrees {
  struct Template {
    std::string key;
    size_t tree = 0;  // the first tree that has it
    std::shared_ptr<const TreeTemplateBlock> block;
    std::vector<float> rest;            // the block's rest state (not kept: template_rest)
    int64_t count = 0, leaf_count = 0;  // its entries (root and branches) and leaves
    int64_t first = 0, leaf_first = 0;  // offsets among the new blocks
  };
  std::vector<Template> fresh;
  std::vector<int64_t> tree_template;             // >= 0: known index; < 0: -(1 + fresh index)
  int64_t static_need = 0, static_leaf_need = 0;  // the new blocks' entries and leaves
  int64_t need = 0;                               // the trees' own entries
  int64_t static_at = 0, static_leaf_at = 0;      // where the new blocks go
  std::vector<int64_t> tree_first;                // per tree: its root's entry
  std::vector<int64_t> tree_count;                // per tree: its block's entries (count_entries)
  // Settling at add (plan_settling): per tree its own entries (its block's, or those before
  // its finest level) and its settled entries' first among the new ones (-1: none); all
  // the new settled entries, and where they go.
  std::vector<int64_t> tree_own, tree_settled;
  int64_t settled_need = 0, settled_at = 0;
};

}  // namespace boreas::impl
