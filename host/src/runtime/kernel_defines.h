// boreas: the #define lines a kernel is specialized with (the variant's part of its build
// options): item counts rounded up to slots the kernel's loops unroll over, and one
// "#define NAME value" line per choice.
#pragma once

#include <string>
#include <vector>

namespace boreas::impl {

// Slots a kernel sums over for count items: the next of 0, 1, 2, 4, 8, 16, padded with
// silent items, so its loop unrolls and vectorizes on CPUs; -1 (a plain loop) beyond 16.
int unrolled_slots(int count);

// Pads items with silent ones up to unrolled_slots(items.size()) and returns that count.
template <typename T>
int pad_to_slots(std::vector<T>& items, const T& silent) {
  int slots = unrolled_slots(static_cast<int>(items.size()));
  if (slots > 0) items.resize(static_cast<size_t>(slots), silent);
  return slots;
}

// "#define NAME slots\n" for a kernel build.
std::string slot_define(const char* name, int slots);

// "#define BOREAS_W width\n": the kernel built at that SIMD width; "" for 0, the device's.
std::string width_define(int width);

}  // namespace boreas::impl
