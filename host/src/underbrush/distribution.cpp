// boreas: where the plants of a meadow grow (Endo et al. sec. 5.2) — propagation from seed
// points toward richer ground, with kinds competing through the nutrients they consume.
//
// The paper gives the idea, not the algorithm: plants spread from propagation points, only
// where the ground has the nutrients a kind needs, more densely where it is richer, and
// kinds compete for space and nutrients. Here, in order:
//
//   1. Two grids over the terrain's rectangle. The spacing grid has cells of the least
//      spacing / sqrt(2), so a cell holds at most about one plant and a spacing test reads
//      a bounded block of cells around the candidate, nearest first: the run is
//      O(plants + cells), never O(plants^2). The ground grid has cells of about a square
//      meter (more for large plants), each with the nutrients taken from it so far.
//   2. Suitability of kind k at x: Liebig's law of the minimum over the nutrients k needs
//      or consumes, each the headroom left above the need once this plant has taken its
//      share, as a fraction of the most there could be:
//          s_k(x) = min_j (r_j(x) - c_kj / A - n_kj) / (1 - n_kj),   r_j = map_j - taken_j
//      where A is a ground cell's area and c_kj the consumption. s <= 0 where a nutrient
//      would fall below the need: nothing grows there.
//   3. Room: each plant takes c_kj of nutrient j (concentration x m^2), so ground at map_j
//      feeds at most D = (map_j - n_kj) / c_kj plants of kind k per m^2. A plant keeps its
//      neighbours (of any kind) at least
//          room_k(x) = sqrt(kPackingDensity / (kBudgetFill D)),   the largest over j,
//      away, and at least the larger of the two kinds' spacings. Growth at exclusion
//      radius r plants kPackingDensity / r^2 per m^2, so the room spreads a kind evenly at
//      kBudgetFill of what the ground feeds. This is what makes richer ground denser: the
//      planted density follows (nutrient - need) / consumption, up to what the spacing
//      allows. A kind that consumes nothing is limited only by its need (where) and its
//      spacing (how dense).
//   4. Seeds: each kind in turn plants `seed_points` seeds, each the most suitable of
//      kSeedCandidates uniform random points (where it is suitable and free).
//   5. Growth: each kind keeps a frontier of its plants, a priority queue by suitability
//      (first queued first among equals), so growth goes toward richer ground first. The
//      next turn goes to the kind with the fewest plants for its weight (stride scheduling:
//      weighted round robin), which takes its best frontier plant and throws up to kTries
//      candidates uniformly over the annulus [r, 2 r] around it, r = max(spacing, room)
//      (Bridson 2007). A candidate grows when it is inside the rectangle, suitable, has its
//      room and spacing, and a uniform draw falls below an acceptance that rises with its
//      suitability. The new plant joins the frontier and the parent goes back; a parent
//      whose kTries all fail leaves it. A parent whose ground was depleted since it was
//      queued is queued again at its present suitability rather than tried first.
//   6. Each plant takes its consumption from its ground cell (stage 2's taken_j). Rooms
//      are sized from the map, as if each kind were alone; where kinds eat the same
//      nutrient, or plants happen to crowd, this budget is what stops them: kinds compete
//      by consumption, and no cell ever gives more than map - need.
//   7. Stop at target_count, or when every frontier is empty.
//
// Distances are horizontal (x, z), and are measured between the float positions returned,
// so a caller checking the spacing finds exactly what was tested here. Every random draw
// comes from splitmix64 streams (trees/tree_random.h) in a fixed order, so the same inputs
// give the same plantings on every run.

#include "underbrush/distribution.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <queue>
#include <string>
#include <vector>

#include "errors.h"
#include "trees/tree_random.h"
#include "validation.h"

namespace boreas::impl {
namespace {

// Candidates per frontier plant before it leaves the frontier. Bridson uses 30; 12 fills
// to 6 % less density (0.59 / r^2 against 0.62, measured) in half the time.
constexpr int kTries = 12;
// Plants per r^2 that growth at exclusion radius r reaches with kTries (measured: 0.59
// on open ground; the densest random packing, maximal Poisson disk sampling, is 0.70).
constexpr double kPackingDensity = 0.59;
// The share of a ground cell's nutrient budget that a kind's room aims to plant, so that
// the budget itself binds only where plants happen to crowd.
constexpr double kBudgetFill = 0.85;
// A plant's room is at most this many times its spacing: on ground barely above a need the
// room would grow without bound, and the spacing test's reach with it.
constexpr double kMaxRoomSpacings = 32.0;
// Acceptance of a try is kMinAcceptance where the ground barely allows the kind, rising to
// 1 on the best ground. Not lower: a frontier plant leaves after kTries failures, and at a
// low acceptance growth would die out on poor but usable ground, leaving it bare.
constexpr double kMinAcceptance = 0.5;
// Random points looked at per seed; the best by suitability is planted.
constexpr int kSeedCandidates = 16;
// Ground cells: about this side, or this many spacings of the largest kind, whichever is
// larger, so a cell pools the nutrients of many plants and the per-cell budget is not
// rounded to a plant or two.
constexpr double kGroundCellSide = 1.0;  // m
constexpr double kGroundCellSpacings = 4.0;
// Grid sizes beyond which cells grow instead (a huge meadow with a small target): the
// spacing grid then holds a few plants per cell, the ground grid pools more ground.
constexpr int64_t kMaxSpacingCells = int64_t(1) << 24;
constexpr int64_t kMaxGroundCells = int64_t(1) << 20;
// Plantings reserved up front at most; beyond, the vectors grow as plants come.
constexpr double kMaxReserved = double(1 << 22);
// Progress is reported about this many times over a run.
constexpr int64_t kProgressReports = 64;

enum Purpose : uint64_t { kSeedPurpose = 1, kGrowPurpose = 2, kShapePurpose = 3 };

void check_inputs(const Terrain& terrain, const NutrientMaps& nutrients,
                  const std::vector<PlantNeeds>& kinds, const DistributionParams& params) {
  const GroundGrid& g = terrain.grid;
  if (g.nx < 1 || g.nz < 1 || terrain.height.size() < size_t(g.nx) * size_t(g.nz)) {
    fail_argument("terrain has " + std::to_string(terrain.height.size()) + " heights for a " +
                  std::to_string(g.nx) + " x " + std::to_string(g.nz) + " grid");
  }
  if (!std::isfinite(g.origin_x) || !std::isfinite(g.origin_z)) {
    fail_argument("terrain.grid origin must be finite (got " + num(g.origin_x) + ", " +
                  num(g.origin_z) + ")");
  }
  if (!(g.size_x > 0.0) || !std::isfinite(g.size_x) || !(g.size_z > 0.0) ||
      !std::isfinite(g.size_z)) {
    fail_argument("terrain.grid size must be > 0 and finite (got " + num(g.size_x) + " x " +
                  num(g.size_z) + ")");
  }
  if (nutrients.channels < 0 || nutrients.channels > kMaxNutrients) {
    fail_argument("nutrients.channels must be in [0, " + std::to_string(kMaxNutrients) + "] (got " +
                  std::to_string(nutrients.channels) + ")");
  }
  const GroundGrid& ng = nutrients.grid;
  for (int c = 0; c < nutrients.channels; ++c) {
    if (ng.nx < 1 || ng.nz < 1 || nutrients.values[c].size() < size_t(ng.nx) * size_t(ng.nz)) {
      fail_argument("nutrients.values[" + std::to_string(c) + "] has " +
                    std::to_string(nutrients.values[c].size()) + " samples for a " +
                    std::to_string(ng.nx) + " x " + std::to_string(ng.nz) + " grid");
    }
  }
  if (kinds.empty()) fail_argument("kinds is empty: at least one kind of plant is needed");
  for (size_t k = 0; k < kinds.size(); ++k) {
    const PlantNeeds& p = kinds[k];
    const std::string name = "kinds[" + std::to_string(k) + "].";
    if (!(p.weight > 0.0) || !std::isfinite(p.weight)) {
      fail_argument(name + "weight must be > 0 and finite (got " + num(p.weight) + ")");
    }
    for (int j = 0; j < kMaxNutrients; ++j) {
      const std::string index = "[" + std::to_string(j) + "]";
      if (!(p.need[j] >= 0.0 && p.need[j] <= 1.0)) {
        fail_argument(name + "need" + index + " must be in [0, 1] (got " + num(p.need[j]) + ")");
      }
      if (!(p.consumption[j] >= 0.0) || !std::isfinite(p.consumption[j])) {
        fail_argument(name + "consumption" + index + " must be >= 0 and finite (got " +
                      num(p.consumption[j]) + ")");
      }
    }
    if (!(p.spacing > 0.0) || !std::isfinite(p.spacing)) {
      fail_argument(name + "spacing must be > 0 and finite (got " + num(p.spacing) + ")");
    }
  }
  if (params.target_count < 0) {
    fail_argument("params.target_count must be >= 0 (got " + std::to_string(params.target_count) +
                  ")");
  }
  if (params.seed_points < 1) {
    fail_argument("params.seed_points must be >= 1 (got " + std::to_string(params.seed_points) +
                  ")");
  }
}

// The rectangle plants may stand in: the terrain's.
struct Rect {
  double x0, z0, x1, z1;
  bool contains(float x, float z) const {
    return double(x) >= x0 && double(x) <= x1 && double(z) >= z0 && double(z) <= z1;
  }
};

// Cells of about `cell` m over the rectangle, grown by half until at most `max_cells`.
struct CellGrid {
  double x0 = 0.0, z0 = 0.0, inv_x = 0.0, inv_z = 0.0;
  int nx = 1, nz = 1;

  // exact: cells tile the rectangle exactly (their side is rounded so), else they are
  // `cell` wide and the last row and column overhang the rectangle.
  CellGrid(const Rect& r, double cell, int64_t max_cells, bool exact) {
    const double sx = r.x1 - r.x0, sz = r.z1 - r.z0;
    for (;;) {
      const double cx = exact ? std::max(1.0, std::round(sx / cell)) : std::ceil(sx / cell);
      const double cz = exact ? std::max(1.0, std::round(sz / cell)) : std::ceil(sz / cell);
      if (cx * cz <= double(max_cells)) {
        nx = int(std::max(1.0, cx));
        nz = int(std::max(1.0, cz));
        inv_x = exact ? double(nx) / sx : 1.0 / cell;
        inv_z = exact ? double(nz) / sz : 1.0 / cell;
        break;
      }
      cell *= 1.5;
    }
    x0 = r.x0;
    z0 = r.z0;
  }
  int column(float x) const { return std::clamp(int((double(x) - x0) * inv_x), 0, nx - 1); }
  int row(float z) const { return std::clamp(int((double(z) - z0) * inv_z), 0, nz - 1); }
  int index(float x, float z) const { return row(z) * nx + column(x); }
  size_t count() const { return size_t(nx) * size_t(nz); }
};

// The spacing grid: who stands where, as a linked list of plants per cell.
class Occupancy {
 public:
  Occupancy(const Rect& r, const std::vector<PlantNeeds>& kinds, double min_spacing,
            double max_spacing)
      : grid_(r, min_spacing / std::sqrt(2.0), kMaxSpacingCells, false),
        kinds_(int(kinds.size())),
        max_spacing_(max_spacing),
        head_(grid_.count(), -1) {
    spacing2_.resize(kinds.size() * kinds.size());
    for (int a = 0; a < kinds_; ++a) {
      for (int b = 0; b < kinds_; ++b) {
        const double s = std::max(kinds[size_t(a)].spacing, kinds[size_t(b)].spacing);
        spacing2_[size_t(a * kinds_ + b)] = s * s;
      }
    }
  }

  // No plant of any kind closer than the larger of its spacing and `kind`'s, nor closer
  // than `room` (m).
  bool is_free(float x, float z, int kind, double room) const {
    const int ci = grid_.column(x), ck = grid_.row(z);
    const double room2 = room * room;
    const double* s2 = &spacing2_[size_t(kind * kinds_)];
    const auto cell_is_free = [&](int i, int k) {
      for (int32_t p = head_[size_t(k) * size_t(grid_.nx) + size_t(i)]; p >= 0;
           p = plants_[size_t(p)].next) {
        const Entry& e = plants_[size_t(p)];
        const double dx = double(x) - double(e.x), dz = double(z) - double(e.z);
        if (dx * dx + dz * dz < std::max(s2[e.kind], room2)) return false;
      }
      return true;
    };
    // Rings of cells around the candidate's, nearest first: a try that fails (most do,
    // once the ground fills) usually fails on a near neighbour, and the grid does not fit
    // in cache, so every cell not read counts. Cells whose nearest point is beyond the
    // largest distance that matters (in cells, with a margin for rounding) are skipped.
    const double limit = std::max(max_spacing_, room) * grid_.inv_x * (1.0 + 1e-9);
    const double limit2 = limit * limit;
    const auto visit = [&](int di, int dk) {
      const int i = ci + di, k = ck + dk;
      if (i < 0 || i >= grid_.nx || k < 0 || k >= grid_.nz) return true;
      const double gi = std::max(std::abs(di) - 1, 0), gk = std::max(std::abs(dk) - 1, 0);
      return gi * gi + gk * gk >= limit2 || cell_is_free(i, k);
    };
    if (!visit(0, 0)) return false;
    const int rings = std::max(grid_.nx, grid_.nz);
    for (int d = 1; d - 1 < limit && d <= rings; ++d) {
      for (int di = -d; di <= d; ++di) {
        if (!visit(di, -d) || !visit(di, d)) return false;
      }
      for (int dk = -d + 1; dk <= d - 1; ++dk) {
        if (!visit(-d, dk) || !visit(d, dk)) return false;
      }
    }
    return true;
  }

  void insert(float x, float z, int kind) {
    const size_t cell = size_t(grid_.index(x, z));
    plants_.push_back(Entry{x, z, kind, head_[cell]});
    head_[cell] = int32_t(plants_.size() - 1);
  }
  void reserve(size_t n) { plants_.reserve(n); }
  float x(int32_t p) const { return plants_[size_t(p)].x; }
  float z(int32_t p) const { return plants_[size_t(p)].z; }

 private:
  struct Entry {
    float x, z;
    int32_t kind;
    int32_t next;  // the next plant in the same cell, -1 at the end
  };
  CellGrid grid_;
  int kinds_;
  double max_spacing_;
  std::vector<double> spacing2_;  // kinds x kinds: the least squared distance, m^2
  std::vector<int32_t> head_;     // per cell: its last plant, -1 if none
  std::vector<Entry> plants_;
};

// What one kind needs, precomputed for stages 2, 3 and 6 of the essay above.
struct KindNeeds {
  int used = 0;  // nutrients that matter to it
  int channel[kMaxNutrients] = {};
  double need[kMaxNutrients] = {};
  double drop[kMaxNutrients] = {};   // its consumption over a ground cell's area
  double scale[kMaxNutrients] = {};  // 1 / (1 - need): headroom as a fraction
  double room2[kMaxNutrients] = {};  // room^2 times (map - need): the consumption's share
  double max_room = 0.0;             // m
};

// What the ground offers a kind at a point.
struct Site {
  double suitability;  // stage 2; <= 0: it cannot grow here
  double room;         // m, stage 3; 0 for a kind that consumes nothing
};

// The ground grid: the nutrients taken from each cell so far.
class Ground {
 public:
  Ground(const Rect& r, const NutrientMaps& maps, const std::vector<PlantNeeds>& kinds,
         double max_spacing)
      : grid_(r, std::max(kGroundCellSide, kGroundCellSpacings * max_spacing), kMaxGroundCells,
              true),
        maps_(maps),
        taken_(grid_.count() * kMaxNutrients, 0.0) {
    const double area = 1.0 / (grid_.inv_x * grid_.inv_z);
    for (const PlantNeeds& p : kinds) {
      KindNeeds n;
      for (int j = 0; j < kMaxNutrients; ++j) {
        if (p.need[j] == 0.0 && p.consumption[j] == 0.0) continue;
        n.channel[n.used] = j;
        n.need[n.used] = p.need[j];
        n.drop[n.used] = p.consumption[j] / area;
        // A need of 1 leaves no headroom anywhere; any huge scale keeps s <= 0 there.
        n.scale[n.used] = 1.0 / std::max(1.0 - p.need[j], 1e-12);
        n.room2[n.used] = kPackingDensity * p.consumption[j] / kBudgetFill;
        ++n.used;
      }
      n.max_room = kMaxRoomSpacings * p.spacing;
      needs_.push_back(n);
    }
  }

  int cell(float x, float z) const { return grid_.index(x, z); }

  // What `kind` finds at (x, z) in ground cell `cell`, after its share is taken.
  Site site(int kind, float x, float z, int cell) const {
    const KindNeeds& n = needs_[size_t(kind)];
    Site site{1.0, 0.0};
    double room2 = 0.0;
    for (int u = 0; u < n.used; ++u) {
      const int j = n.channel[u];
      const double map = maps_.at(j, double(x), double(z));
      const double left = map - taken_[size_t(cell) * kMaxNutrients + size_t(j)] - n.drop[u];
      site.suitability = std::min(site.suitability, (left - n.need[u]) * n.scale[u]);
      if (n.room2[u] > 0.0 && map > n.need[u])
        room2 = std::max(room2, n.room2[u] / (map - n.need[u]));
    }
    site.room = std::min(std::sqrt(room2), n.max_room);
    return site;
  }

  void take(int kind, int cell) {
    const KindNeeds& n = needs_[size_t(kind)];
    for (int u = 0; u < n.used; ++u) {
      taken_[size_t(cell) * kMaxNutrients + size_t(n.channel[u])] += n.drop[u];
    }
  }

 private:
  CellGrid grid_;
  const NutrientMaps& maps_;
  std::vector<KindNeeds> needs_;
  std::vector<double> taken_;  // per cell and nutrient, concentration
};

// A frontier plant: its suitability when queued, the order it was queued in (first queued
// first among equals, so the order does not depend on the heap's implementation), and which.
struct FrontierEntry {
  double key;
  uint64_t order;
  int32_t plant;
};
struct LowerPriority {
  bool operator()(const FrontierEntry& a, const FrontierEntry& b) const {
    if (a.key != b.key) return a.key < b.key;
    return a.order > b.order;
  }
};
using Frontier = std::priority_queue<FrontierEntry, std::vector<FrontierEntry>, LowerPriority>;

// One run of the algorithm: the state the stages share.
class Distributor {
 public:
  Distributor(const Terrain& terrain, const NutrientMaps& nutrients,
              const std::vector<PlantNeeds>& kinds, const DistributionParams& params)
      : terrain_(terrain),
        kinds_(kinds),
        params_(params),
        rect_{terrain.grid.origin_x, terrain.grid.origin_z,
              terrain.grid.origin_x + terrain.grid.size_x,
              terrain.grid.origin_z + terrain.grid.size_z},
        occupancy_(rect_, kinds, min_spacing(kinds), max_spacing(kinds)),
        ground_(rect_, nutrients, kinds, max_spacing(kinds)),
        frontier_(kinds.size()),
        planted_(kinds.size(), 0),
        grow_rng_(params.seed, 0, kGrowPurpose),
        shape_rng_(params.seed, 0, kShapePurpose) {
    // Plant indices are int32; more than 2^31 - 1 plants would be 64 GB of plantings.
    target_ = std::min<int64_t>(params.target_count, std::numeric_limits<int32_t>::max());
    // The densest packing at the least spacing (1.15 / s^2) bounds what can be planted.
    const double area = (rect_.x1 - rect_.x0) * (rect_.z1 - rect_.z0);
    const double s = min_spacing(kinds);
    const double most = std::min({double(target_), 1.2 * area / (s * s) + 16.0, kMaxReserved});
    out_.reserve(size_t(most));
    occupancy_.reserve(size_t(most));
    report_every_ = std::max<int64_t>(1, target_ / kProgressReports);
  }

  std::vector<Planting> run() {
    report(0.0);
    seed();
    grow();
    report(1.0);
    return std::move(out_);
  }

 private:
  static double min_spacing(const std::vector<PlantNeeds>& kinds) {
    double s = kinds[0].spacing;
    for (const PlantNeeds& k : kinds) s = std::min(s, k.spacing);
    return s;
  }
  static double max_spacing(const std::vector<PlantNeeds>& kinds) {
    double s = kinds[0].spacing;
    for (const PlantNeeds& k : kinds) s = std::max(s, k.spacing);
    return s;
  }

  int64_t total() const { return int64_t(out_.size()); }

  void report(double fraction) const {
    if (params_.progress) params_.progress(fraction);
  }

  // Stage 4: seed_points rounds, each kind one seed per round.
  void seed() {
    const double sx = rect_.x1 - rect_.x0, sz = rect_.z1 - rect_.z0;
    std::vector<TreeRandom> rngs;
    for (size_t k = 0; k < kinds_.size(); ++k) rngs.emplace_back(params_.seed, k, kSeedPurpose);
    for (int round = 0; round < params_.seed_points && total() < target_; ++round) {
      for (int k = 0; k < int(kinds_.size()) && total() < target_; ++k) {
        TreeRandom& rng = rngs[size_t(k)];
        Site best{0.0, 0.0};
        float bx = 0.0f, bz = 0.0f;
        for (int c = 0; c < kSeedCandidates; ++c) {
          const float x = float(rect_.x0 + sx * rng.uniform01());
          const float z = float(rect_.z0 + sz * rng.uniform01());
          if (!rect_.contains(x, z)) continue;
          const Site site = ground_.site(k, x, z, ground_.cell(x, z));
          if (site.suitability > best.suitability) {
            best = site;
            bx = x;
            bz = z;
          }
        }
        if (best.suitability > 0.0 && occupancy_.is_free(bx, bz, k, best.room)) {
          plant(k, bx, bz, best.suitability);
        }
      }
    }
  }

  // The kind whose turn it is: the fewest plants for its weight among those that can still
  // grow, the first on ties; -1 when none can.
  int next_kind() const {
    int best = -1;
    double best_share = 0.0;
    for (int k = 0; k < int(kinds_.size()); ++k) {
      if (frontier_[size_t(k)].empty()) continue;
      const double share = double(planted_[size_t(k)] + 1) / kinds_[size_t(k)].weight;
      if (best < 0 || share < best_share) {
        best = k;
        best_share = share;
      }
    }
    return best;
  }

  // Stage 5.
  void grow() {
    while (total() < target_) {
      const int k = next_kind();
      if (k < 0) break;
      Frontier& frontier = frontier_[size_t(k)];
      FrontierEntry parent = frontier.top();
      frontier.pop();
      const float px = occupancy_.x(parent.plant), pz = occupancy_.z(parent.plant);
      const Site here = ground_.site(k, px, pz, ground_.cell(px, pz));
      if (here.suitability < parent.key && !frontier.empty() &&
          here.suitability < frontier.top().key) {
        parent.key = here.suitability;
        frontier.push(parent);
        continue;
      }
      parent.key = here.suitability;
      if (try_around(k, px, pz, std::max(kinds_[size_t(k)].spacing, here.room))) {
        frontier.push(parent);
      }
    }
  }

  // Up to kTries candidates around (px, pz) at distances in [r, 2 r]; true when one grew.
  bool try_around(int k, float px, float pz, double r) {
    const double reach = 2.0 * r;
    for (int t = 0; t < kTries; ++t) {
      // Uniform over the annulus, by rejection from the square: no trigonometry, so the
      // same bits on every math library.
      double a, b, r2;
      do {
        a = grow_rng_.uniform_pm1();
        b = grow_rng_.uniform_pm1();
        r2 = a * a + b * b;
      } while (r2 < 0.25 || r2 >= 1.0);
      const float x = float(double(px) + reach * a), z = float(double(pz) + reach * b);
      if (!rect_.contains(x, z)) continue;
      const Site site = ground_.site(k, x, z, ground_.cell(x, z));
      if (site.suitability <= 0.0 || !occupancy_.is_free(x, z, k, site.room)) continue;
      const double acceptance = kMinAcceptance + (1.0 - kMinAcceptance) * site.suitability;
      if (acceptance < 1.0 && grow_rng_.uniform01() >= acceptance) continue;
      plant(k, x, z, site.suitability);
      return true;
    }
    return false;
  }

  // Stage 6: a plant of kind k at (x, z), with its suitability there.
  void plant(int k, float x, float z, double suitability) {
    const int32_t index = int32_t(out_.size());
    occupancy_.insert(x, z, k);
    ground_.take(k, ground_.cell(x, z));
    ++planted_[size_t(k)];
    frontier_[size_t(k)].push(FrontierEntry{suitability, order_++, index});

    Planting p;
    p.position[0] = x;
    p.position[1] = float(terrain_.height_at(double(x), double(z)));
    p.position[2] = z;
    double n[3];
    terrain_.normal_at(double(x), double(z), n);
    for (int i = 0; i < 3; ++i) p.normal[i] = float(n[i]);
    p.kind = k;
    p.seed = uint32_t(shape_rng_.next_u64() >> 32);
    out_.push_back(p);

    if (total() % report_every_ == 0 && total() < target_) {
      report(double(total()) / double(target_));
    }
  }

  const Terrain& terrain_;
  const std::vector<PlantNeeds>& kinds_;
  const DistributionParams& params_;
  Rect rect_;
  Occupancy occupancy_;
  Ground ground_;
  std::vector<Frontier> frontier_;  // per kind
  std::vector<int64_t> planted_;    // per kind
  TreeRandom grow_rng_, shape_rng_;
  uint64_t order_ = 0;
  int64_t target_ = 0;
  int64_t report_every_ = 1;
  std::vector<Planting> out_;
};

}  // namespace

std::vector<Planting> distribute(const Terrain& terrain, const NutrientMaps& nutrients,
                                 const std::vector<PlantNeeds>& kinds,
                                 const DistributionParams& params) {
  check_inputs(terrain, nutrients, kinds, params);
  if (params.target_count == 0) return {};
  return Distributor(terrain, nutrients, kinds, params).run();
}

}  // namespace boreas::impl
