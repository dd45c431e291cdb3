// boreas: template numbers shared by a mode's tree batches (template_numbers.h).
#include "trees/template_numbers.h"

namespace boreas::impl {

int32_t TemplateNumbers::claim(const std::string& key) {
  auto [it, fresh] = by_key_.try_emplace(key);
  if (fresh) {
    if (!free_.empty()) {
      it->second.number = free_.back();
      free_.pop_back();
    } else {
      it->second.number = next_++;
    }
  }
  ++it->second.holders;
  return it->second.number;
}

void TemplateNumbers::release(const std::string& key) {
  auto it = by_key_.find(key);
  if (it == by_key_.end() || --it->second.holders > 0) return;
  free_.push_back(it->second.number);
  by_key_.erase(it);
}

}  // namespace boreas::impl
