// boreas: the numbers boreas_tree_get_template gives a mode's template blocks, shared by
// the tree batches ("chunks") of that mode, so that a template has one number in all of
// them whatever chunk a tree landed in (a renderer instances and bakes impostors by it).
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include "free_places.h"

namespace boreas::impl {

// A block's number is claimed by the first chunk that holds the block and freed when the
// last one lets it go. Numbers are given out as a batch's own template indices are
// (PlaceNumbers, free_places.h), so a world of one chunk numbers its templates as it did
// before there were chunks.
class TemplateNumbers {
 public:
  // The block's number, claimed for one more holder.
  int32_t claim(const std::string& key);
  // One holder fewer; the number is freed with the last.
  void release(const std::string& key);

 private:
  struct Entry {
    int32_t number = 0;
    int64_t holders = 0;
  };
  std::unordered_map<std::string, Entry> by_key_;
  PlaceNumbers numbers_;
};

}  // namespace boreas::impl
