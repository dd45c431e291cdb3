// boreas: a meadow component's part, parent, axis, side and scale in its three packed
// index words (cl/shared/underbrush_pack.h decodes them, on the device and here): the
// encoders, which pick the code whose decoding is nearest the exact value, and the host
// readers' decoding of a component at once.
#pragma once

#include <cstdint>

#include "boreas/boreas.h"
// The host's float path uses the polynomial math the CPU kernels use (as meadow.h).
#ifndef BOREAS_FAST_MATH
#define BOREAS_FAST_MATH 1
#endif
#include "shared/underbrush_pack.h"

namespace boreas::impl {

// What the packed words of one component decode to.
struct UnpackedFrame {
  BoreasV3 axis, side;  // e_u, e_w: unit, perpendicular
  float scale;
};

// LINK for part `part` (meadow-local) whose parent is `back` components before it (0: a
// root). Fails (BOREAS_ERROR_INVALID_ARGUMENT, naming `where`) past the fields' 16 bits.
int32_t pack_link(int part, int back, const char* where);

// AXIS: the code whose e_u is nearest `axis` (unit; of the four codes around it).
int32_t pack_axis(const double axis[3]);

// TURN for the side nearest `side` about the e_u that `axis_word` decodes to (`side`
// need not be exactly perpendicular: its part along e_u is dropped), and the half
// nearest `scale` (BOREAS_UB_SCALE_MIN..BOREAS_UB_SCALE_MAX, else fails naming `where`).
int32_t pack_turn(int32_t axis_word, const double side[3], double scale, const char* where);

// Component c of index planes at stride n.
UnpackedFrame unpack_frame(const int32_t* index, int n, int c);
inline int part_of(const int32_t* index, int n, int c) {
  return boreas_ub_link_part(index[BOREAS_UB_INDEX_LINK * n + c]);
}
// The parent's index (c itself for a root), in the same numbering as c.
inline int parent_of(const int32_t* index, int n, int c) {
  return c - boreas_ub_link_back(index[BOREAS_UB_INDEX_LINK * n + c]);
}

}  // namespace boreas::impl
