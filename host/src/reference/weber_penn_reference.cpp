// boreas: the expected Weber-Penn tree, level by level (see the header).
#include "reference/weber_penn_reference.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "trees/tree_model.h"

namespace boreas::impl::reference {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Children of one stem are integrated over their offsets with up to this many samples.
constexpr int kSamples = 8;

// A stem of the expected tree, standing for `weight` stems alike.
struct RefStem {
  int level = 0;
  double weight = 1.0;
  double length = 0.0, radius = 0.0;
  double parent_length = 0.0;  // its parent's length (0 for a trunk)
  double length_max = 0.0;     // its nLength + nLengthV drawn at its mean: nLength
};

// Clones one stem piece makes from segment end `from` on, and its clones in turn:
// Weber-Penn's error diffusion, splits = floor(nSegSplits + error + 1/2) at each segment
// end but the last, the error carried on by what was rounded away, each clone walked to
// its end before its stem goes on (so the error it leaves is the one its stem meets);
// the trunk's first end makes 0BaseSplits instead. Splits stop kMaxSplitDepth deep, a
// limit of boreas's kernels (trees/tree_model.h), not a Weber-Penn rule.
double walk_clones(const Species& s, int level, int ends, int from, int depth, double* error) {
  const double rate = s.level[size_t(level)].seg_splits;
  double clones = 0.0;
  for (int e = from; e < ends; ++e) {
    int count;
    if (level == 0 && e == 0 && s.base_splits > 0) {
      count = s.base_splits;
    } else {
      count = int(std::floor(rate + *error + 0.5));
      *error -= count - rate;
    }
    if (depth >= kMaxSplitDepth || count <= 0) continue;
    for (int i = 0; i < count; ++i)
      clones += 1.0 + walk_clones(s, level, ends, e + 1, depth + 1, error);
    ++depth;  // the stem goes on one split deeper
  }
  return clones;
}

// Clones per stem of a level of `stems` stems: the error is carried from stem to stem in
// growth order, starting at 0, and that chain settles into a rhythm of its own (rush's
// level 2, 0.4 splits over 4 segment ends: 2 clones from an error of 0, 4 once the chain
// has settled), so it is walked stem after stem, not averaged over starting errors.
double clones_per_stem(const Species& s, int level, double stems) {
  const int ends = int(s.level[size_t(level)].curve_res) - 1;
  if (ends < 1) return 0.0;
  const int count = std::clamp(int(std::lround(stems)), 1, 20000);
  double error = 0.0, sum = 0.0;
  for (int k = 0; k < count; ++k) sum += walk_clones(s, level, ends, 0, 0, &error);
  return sum / count;
}

// Radius of `stem` at `offset` m from its base: linear taper for nTaper <= 1 (Weber-Penn's
// unit taper); a rounded or periodic tip (nTaper > 1) keeps the base radius here.
double radius_at(const Species& s, const RefStem& stem, double offset) {
  const double taper = s.level[size_t(stem.level)].taper;
  const double z = std::clamp(offset / stem.length, 0.0, 1.0);
  return taper <= 1.0 ? stem.radius * (1.0 - taper * z) : stem.radius;
}

// The children of `parent` (the whole stem: they are shared among its clones).
void grow_children(const Species& s, double tree_scale, const RefStem& parent,
                   std::vector<RefStem>* out) {
  const int level = parent.level + 1;
  if (level >= s.levels) return;
  const SpeciesLevel& lc = s.level[size_t(level)];
  const double length_max = lc.length;
  // How many, and over which offsets.
  double count = 0.0, from = 0.0;
  if (parent.level == 0) {
    count = lc.branches;
    from = std::min(s.base_size * tree_scale, parent.length);
  } else if (parent.level == 1) {
    count = lc.branches * (0.2 + 0.8 * (parent.length / parent.parent_length) / parent.length_max);
  }
  const int samples = std::max(1, std::min(kSamples, int(std::ceil(lc.branches))));
  for (int k = 0; k < samples; ++k) {
    const double offset = from + (parent.length - from) * (k + 0.5) / samples;
    double n = count / samples;
    if (parent.level >= 2) n = lc.branches * (1.0 - 0.5 * offset / parent.length) / samples;
    if (!(n > 0.0)) continue;
    RefStem c;
    c.level = level;
    c.weight = parent.weight * n;
    c.parent_length = parent.length;
    c.length_max = length_max;
    if (level == 1) {
      const double base = parent.length - s.base_size * tree_scale;
      const double ratio = base > 0.0 ? (parent.length - offset) / base : 0.0;
      c.length = parent.length * length_max * reference_shape_ratio(s, s.shape, ratio);
    } else {
      c.length = length_max * (parent.length - 0.6 * offset);
    }
    if (!(c.length > 0.0)) continue;
    c.radius = std::min(parent.radius * std::pow(c.length / parent.length, s.ratio_power),
                        radius_at(s, parent, offset));
    out->push_back(c);
  }
}

}  // namespace

double reference_shape_ratio(const Species& s, int shape, double r) {
  switch (shape) {
    case 0:
      return r;
    case 1:
      return 0.2 + 0.8 * std::sin(kPi * r);
    case 2:
      return 0.2 + 0.8 * std::sin(0.5 * kPi * r);
    case 3:
      return 1.0;
    case 4:
      return 0.5 + 0.5 * r;
    case 5:
      return r <= 0.7 ? r / 0.7 : (1.0 - r) / 0.3;
    case 6:
      return 1.0 - 0.8 * r;
    case 7:
      return r <= 0.7 ? 0.5 + 0.5 * r / 0.7 : 0.5 + 0.5 * (1.0 - r) / 0.3;
    default: {
      if (r < 0.0 || r > 1.0) return 0.0;
      const double peak = 1.0 - s.prune_width_peak;
      return r < peak ? std::pow(r / peak, s.prune_power_high)
                      : std::pow((1.0 - r) / (1.0 - peak), s.prune_power_low);
    }
  }
}

std::array<WeberPennLevel, kMaxTreeLevels> weber_penn_expected(const Species& s) {
  std::array<WeberPennLevel, kMaxTreeLevels> figures{};
  std::array<double, kMaxTreeLevels> length_sum{}, radius_sum{};
  const double tree_scale = s.scale;
  RefStem trunk;
  trunk.level = 0;
  trunk.weight = std::max(1.0, s.level[0].branches);  // 0Branches trunks
  trunk.length = s.level[0].length * tree_scale;
  trunk.radius = trunk.length * s.ratio * s.trunk_scale;
  trunk.length_max = s.level[0].length;
  std::vector<RefStem> level{trunk};
  for (int l = 0; l < s.levels && !level.empty(); ++l) {
    double first_pieces = 0.0;
    for (const RefStem& stem : level) first_pieces += stem.weight;
    const double stems_per = 1.0 + clones_per_stem(s, l, first_pieces);
    std::vector<RefStem> next;
    for (const RefStem& stem : level) {
      const double w = stem.weight * stems_per;
      figures[size_t(l)].stems += w;
      length_sum[size_t(l)] += w * stem.length;
      radius_sum[size_t(l)] += w * stem.radius;
      grow_children(s, tree_scale, stem, &next);
    }
    level = std::move(next);
  }
  for (int l = 0; l < kMaxTreeLevels; ++l) {
    if (figures[size_t(l)].stems > 0.0) {
      figures[size_t(l)].mean_length = length_sum[size_t(l)] / figures[size_t(l)].stems;
      figures[size_t(l)].mean_radius = radius_sum[size_t(l)] / figures[size_t(l)].stems;
    }
  }
  return figures;
}

}  // namespace boreas::impl::reference
