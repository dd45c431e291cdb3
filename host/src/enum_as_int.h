// boreas: the value a C caller stored in an enum field, read as an int. A C caller can
// store any int there, and loading an out-of-range value as the C++ enum type is
// undefined (UBSan reports it), so checks read the bits before trusting them.
#pragma once

#include <cstring>

namespace boreas::impl {

template <typename Enum>
int enum_as_int(const Enum& value) {
  static_assert(sizeof(Enum) == sizeof(int), "boreas's C enums are int-sized");
  int bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

}  // namespace boreas::impl
