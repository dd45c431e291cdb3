// boreas: the #define lines kernels are specialized with (kernel_defines.h).
#include "runtime/kernel_defines.h"

namespace boreas::impl {

int unrolled_slots(int count) {
  if (count <= 0) return 0;
  for (int slots = 1; slots <= 16; slots *= 2) {
    if (count <= slots) return slots;
  }
  return -1;
}

std::string slot_define(const char* name, int slots) {
  return std::string("#define ") + name + " " + std::to_string(slots) + "\n";
}

std::string width_define(int width) { return width ? slot_define("BOREAS_W", width) : ""; }

}  // namespace boreas::impl
