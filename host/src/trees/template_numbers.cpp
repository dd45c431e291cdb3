// boreas: template numbers shared by a mode's tree batches (template_numbers.h).
#include "trees/template_numbers.h"

namespace boreas::impl {

int32_t TemplateNumbers::claim(const std::string& key) {
  auto [it, fresh] = by_key_.try_emplace(key);
  if (fresh) it->second.number = numbers_.claim();
  ++it->second.holders;
  return it->second.number;
}

void TemplateNumbers::release(const std::string& key) {
  auto it = by_key_.find(key);
  if (it == by_key_.end() || --it->second.holders > 0) return;
  numbers_.release(it->second.number);
  by_key_.erase(it);
}

}  // namespace boreas::impl
