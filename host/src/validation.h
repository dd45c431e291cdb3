// boreas: the checks every def's validation is made of (finite, in a range, a count, a
// position), and the number formatting their messages share. Each throws
// BOREAS_ERROR_INVALID_ARGUMENT naming the field, the rule and the value.
#pragma once

#include <string>

#include "boreas/boreas.h"

namespace boreas::impl {

// v as messages show it, at six significant digits: "1000", "0.001", "1e+07", "nan".
std::string num(double v);

// Throws unless v is finite: "<what> must be finite (got <num(v)>)".
void check_finite(double v, const std::string& what);

// Throws unless v is finite (check_finite) and in [lo, hi]: "<what> must be in [lo, hi]
// (got v)", the three numbers as std::to_string writes them ("1.000000"). A float argument
// converts exactly, so float fields are checked and shown as they are.
void check_range(double v, double lo, double hi, const std::string& what);

// Throws unless lo <= v <= hi: "<what> must be in [lo, hi] (got v)".
void check_int_range(int v, int lo, int hi, const std::string& what);

// Throws unless lo <= v <= hi: "<what> must be in lo..hi (got v)", for counts.
void check_count(int v, int lo, int hi, const std::string& what);

// Throws unless center is not NULL and each coordinate is finite and within
// +-BOREAS_WORLD_MAX_COORDINATE m: "<what>[a] ...".
void check_position(const float center[3], const char* what);

// Throws unless part is BOREAS_MESH_TRUNK or BOREAS_MESH_LEAVES. By reference, read as an
// int (enum_as_int.h): a C caller may pass any int.
void check_mesh_part(const boreas_mesh_part& part);

}  // namespace boreas::impl
