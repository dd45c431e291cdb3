// boreas: the general checks of def validation (validation.h).
#include "validation.h"

#include <cmath>
#include <sstream>

#include "boreas/boreas.h"
#include "enum_as_int.h"
#include "errors.h"

namespace boreas::impl {

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void check_finite(double v, const std::string& what) {
  if (!std::isfinite(v)) fail_argument(what + " must be finite (got " + num(v) + ")");
}

void check_range(double v, double lo, double hi, const std::string& what) {
  check_finite(v, what);
  if (v < lo || v > hi)
    fail_argument(what + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                  "] (got " + std::to_string(v) + ")");
}

void check_int_range(int v, int lo, int hi, const std::string& what) {
  if (v < lo || v > hi)
    fail_argument(what + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                  "] (got " + std::to_string(v) + ")");
}

void check_count(int v, int lo, int hi, const std::string& what) {
  if (v < lo || v > hi)
    fail_argument(what + " must be in " + std::to_string(lo) + ".." + std::to_string(hi) +
                  " (got " + std::to_string(v) + ")");
}

void check_position(const float center[3], const char* what) {
  if (!center) fail_argument(std::string(what) + " is NULL");
  for (int a = 0; a < 3; ++a)
    check_range(center[a], -BOREAS_WORLD_MAX_COORDINATE, BOREAS_WORLD_MAX_COORDINATE,
                std::string(what) + "[" + std::to_string(a) + "]");
}

void check_mesh_part(const boreas_mesh_part& part) {
  const int value = enum_as_int(part);
  if (value != BOREAS_MESH_TRUNK && value != BOREAS_MESH_LEAVES)
    fail_argument("part must be BOREAS_MESH_TRUNK or BOREAS_MESH_LEAVES (got " +
                  std::to_string(value) + ")");
}

}  // namespace boreas::impl
