// boreas: the deformer's tiles and the leaves' thinning permutation (tree_record_tiles.h).
#include "trees/tree_record_tiles.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>

#include "errors.h"
#include "shared/launch_tiles.h"

namespace boreas::impl {

std::vector<int32_t> deform_tiles(const std::vector<DeformRange>& ranges, int width) {
  std::vector<int32_t> ints;
  for (const DeformRange& r : ranges) {
    const int64_t vertices = int64_t(r.count) * (r.rings + 1) * (r.sides + 1);
    if (r.out_first + vertices > INT32_MAX || r.first + r.count > INT32_MAX)
      fail(BOREAS_ERROR_OUT_OF_MEMORY, "the deformer reached vertex 2^31: too many vertices in one call");
    for (int64_t at = 0; at < vertices; at += width) {
      int32_t tile[BOREAS_TILE_INTS] = {};
      tile[BOREAS_TILE_FIRST] = int32_t(at);
      tile[BOREAS_TILE_COUNT] = int32_t(std::min<int64_t>(width, vertices - at));
      tile[BOREAS_TILE_STATIC] = int32_t(r.static_first);
      tile[BOREAS_TILE_ROOT] = int32_t(r.first);
      tile[BOREAS_TILE_VALUE] = r.rings;
      std::memcpy(&tile[BOREAS_TILE_SCALE], &r.scale, sizeof(float));
      tile[BOREAS_TILE_SCALE_ROOT] = r.sides;
      tile[BOREAS_TILE_OBJECT] = int32_t(r.out_first);
      ints.insert(ints.end(), tile, tile + BOREAS_TILE_INTS);
    }
  }
  return ints;
}

namespace {

// x^-1 mod n for x prime to n (extended Euclid).
int64_t inverse_mod(int64_t x, int64_t n) {
  int64_t r0 = n, r1 = x % n, t0 = 0, t1 = 1;
  while (r1 != 0) {
    const int64_t q = r0 / r1;
    const int64_t r2 = r0 - q * r1, t2 = t0 - q * t1;
    r0 = r1, r1 = r2;
    t0 = t1, t1 = t2;
  }
  return ((t0 % n) + n) % n;
}

}  // namespace

LeafPermutation leaf_permutation(int32_t n) {
  LeafPermutation p;
  if (n < 3) return p;
  const double golden = (1.0 + std::sqrt(5.0)) / 2.0;
  const int64_t near = std::max<int64_t>(1, std::llround(double(n) / golden));
  // The nearest stride prime to n, trying below and above in turn.
  for (int64_t d = 0;; ++d) {
    for (int64_t s : {near - d, near + d}) {
      if (s >= 1 && s < n && std::gcd(s, int64_t(n)) == 1) {
        p.stride = int32_t(s);
        p.inverse = int32_t(inverse_mod(s, n));
        return p;
      }
    }
  }
}

}  // namespace boreas::impl
