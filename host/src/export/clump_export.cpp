// boreas: a meadow as representative clumps in the animated glTF (clump_export.h).
#include "export/clump_export.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

#include "export/meadow_strips.h"
#include "underbrush/underbrush_batch.h"
#include "world.h"

namespace boreas::impl {
namespace {

// A cell's phase: a hash of meadow and cell (splitmix64), so neighbours differ.
int phase_of(size_t meadow, size_t cell, int frames) {
  if (frames < 2) return 0;
  uint64_t z = (uint64_t(meadow) << 32) + cell + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return int(z % uint64_t(frames - 1));
}

// Per cell: its components (meadow order), species counts and ground height (the mean y
// of its ground-fixed components' bases, world).
struct Cell {
  std::vector<uint32_t> components;
  size_t vertices = 0;  // their strips' (full detail): what a viewer draws
  std::vector<int> species;
  double ground = 0.0;
  int roots = 0;
};

}  // namespace

std::vector<int> component_cells(const std::vector<boreas_component>& components,
                                 const std::array<double, 3>& origin, double center_x,
                                 double center_z, double size_x, double size_z, double size,
                                 int* columns, int* rows) {
  *columns = std::max(1, int(std::lround(size_x / size)));
  *rows = std::max(1, int(std::lround(size_z / size)));
  const double w = size_x / *columns, h = size_z / *rows;
  std::vector<int> cells(components.size());
  for (size_t i = 0; i < components.size(); ++i) {
    size_t root = i;
    while (components[root].parent >= 0) root = size_t(components[root].parent);
    const double x = origin[0] + components[root].base[0] - (center_x - 0.5 * size_x);
    const double z = origin[2] + components[root].base[2] - (center_z - 0.5 * size_z);
    const int cx = std::clamp(int(std::floor(x / w)), 0, *columns - 1);
    const int cz = std::clamp(int(std::floor(z / h)), 0, *rows - 1);
    cells[i] = cx + *columns * cz;
  }
  return cells;
}

MeadowClumps::MeadowClumps(World& world, boreas_meadow_id id, size_t index, const ClumpParams& p,
                           gltf::ForestAnimation* a)
    : world_(world), id_(id), a_(a) {
  const Meadow& meadow = world_.meadow(id).meadow;
  const GroundRect& rect = meadow.params.rect;  // its size; the center is the meadow's origin
  const double center_x = meadow.origin[0], center_z = meadow.origin[2];
  const std::array<double, 3>& origin = world_.output_origin();
  const std::vector<boreas_component> components = world_.meadow_components(id);
  int columns = 0, rows = 0;
  const std::vector<int> of = component_cells(components, origin, center_x, center_z,
                                              rect.size_x, rect.size_z, p.size, &columns, &rows);
  const size_t species = meadow.params.species.size();
  std::vector<float> vertices;
  std::vector<int32_t> counts;
  world_.meadow_vertices(id, nullptr, &vertices, &counts);
  std::vector<Cell> cells(size_t(columns) * size_t(rows));
  for (size_t i = 0; i < components.size(); ++i) {
    Cell& c = cells[size_t(of[i])];
    if (c.species.empty()) c.species.assign(species, 0);
    c.components.push_back(uint32_t(i));
    c.vertices += size_t(counts[i]);
    ++c.species[size_t(components[i].species)];
    if (components[i].parent < 0) {
      c.ground += origin[1] + components[i].base[1];
      ++c.roots;
    }
  }
  std::vector<size_t> filled;
  for (size_t c = 0; c < cells.size(); ++c)
    if (cells[c].roots > 0) {
      cells[c].ground /= cells[c].roots;
      filled.push_back(c);
    }
  if (filled.empty()) return;
  // The filled cells ranked by their plants' strip vertices, in n equal shares; a share's
  // clump is its cell nearest the share's mean (then mean species counts), every cell of it an
  // instance of it: the meadow's density and mix kept share by share. (Cells spread over the
  // ground, each matched to the nearest clump, kept the few dense ones out: the default
  // scene's meadows came to half their strip vertices.)
  const size_t n = std::min(filled.size(), size_t(p.clumps));
  std::vector<size_t> ranked = filled;
  std::stable_sort(ranked.begin(), ranked.end(), [&](size_t x, size_t y) {
    return cells[x].vertices < cells[y].vertices;
  });
  std::vector<size_t> chosen, share_of(cells.size(), 0);
  for (size_t k = 0; k < n; ++k) {
    const size_t first = k * ranked.size() / n, end = (k + 1) * ranked.size() / n;
    std::vector<double> mean(species, 0.0);
    double mean_count = 0.0;
    for (size_t r = first; r < end; ++r) {
      share_of[ranked[r]] = k;
      mean_count += double(cells[ranked[r]].vertices) / double(end - first);
      for (size_t s = 0; s < species; ++s) mean[s] += double(cells[ranked[r]].species[s]) / double(end - first);
    }
    // Nearest the mean first (the density), then the mean mix.
    size_t best = ranked[first];
    std::pair<double, double> best_distance{-1.0, 0.0};
    for (size_t r = first; r < end; ++r) {
      std::pair<double, double> d{std::abs(double(cells[ranked[r]].vertices) - mean_count), 0.0};
      for (size_t s = 0; s < species; ++s) d.second += std::abs(double(cells[ranked[r]].species[s]) - mean[s]);
      if (best_distance.first < 0 || d < best_distance) {
        best = ranked[r];
        best_distance = d;
      }
    }
    chosen.push_back(best);
  }
  std::map<std::pair<int32_t, int32_t>, std::array<float, 3>> colors;
  for (const boreas_meadow_part& part : world_.meadow_parts(id))
    colors[{part.species, part.part}] = {linear(part.color[0]), linear(part.color[1]), linear(part.color[2])};
  const double w = rect.size_x / columns, h = rect.size_z / rows;
  auto cell_origin = [&](size_t c) -> std::array<double, 3> {
    return {center_x - 0.5 * rect.size_x + (double(c % size_t(columns)) + 0.5) * w, cells[c].ground,
            center_z - 0.5 * rect.size_z + (double(c / size_t(columns)) + 0.5) * h};
  };
  for (size_t k = 0; k < n; ++k) {
    const Cell& cell = cells[chosen[k]];
    const std::array<double, 3> at = cell_origin(chosen[k]);
    gltf::MorphBase base;
    base.name = "meadow" + std::to_string(index) + "_clump" + std::to_string(k);
    base.leaf_material = true;
    for (uint32_t i : cell.components) {
      const std::array<float, 3> color = colors[{components[i].species, components[i].part}];
      strip_triangles(uint32_t(base.vertex_count()), uint32_t(counts[i]), &base.indices);
      for (int32_t v = 0; v < counts[i]; ++v) {
        const float* x = &vertices[(i * BOREAS_MEADOW_VERTEX_STRIDE + size_t(v)) * kMeadowFloats];
        for (size_t c = 0; c < 3; ++c) base.positions.push_back(float(origin[c] + double(x[c]) - at[c]));
        base.normals.insert(base.normals.end(), x + 3, x + 6);
        base.colors.insert(base.colors.end(), color.begin(), color.end());
      }
    }
    gltf::MorphedMesh copy;
    copy.name = base.name;
    copy.base = int(a_->morph_bases.size());
    copy.position = at;
    a_->morph_bases.push_back(std::move(base));
    clumps_.push_back({a_->morphed.size(), cell.components});
    a_->morphed.push_back(std::move(copy));
  }
  // Every filled cell: its share's clump (at the clump's own cell in phase 0, so it plays
  // as boreas stepped it but for the loop's drift), at a phase of its own elsewhere.
  for (size_t c : filled) {
    const size_t best = share_of[c];
    gltf::MorphedMesh& copy = a_->morphed[clumps_[best].copy];
    const bool own = chosen[best] == c;
    copy.instances.push_back({copy.name + "_cell" + std::to_string(c), cell_origin(c),
                              own ? 0 : phase_of(index, c, p.frames)});
  }
}

void MeadowClumps::key() {
  const std::array<double, 3>& origin = world_.output_origin();
  std::vector<float> vertices;
  std::vector<int32_t> counts;
  world_.meadow_vertices(id_, nullptr, &vertices, &counts);
  for (const Clump& clump : clumps_) {
    gltf::MorphedMesh& copy = a_->morphed[clump.copy];
    std::vector<float> key;
    for (uint32_t i : clump.components)
      for (int32_t v = 0; v < counts[i]; ++v) {
        const float* x = &vertices[(i * BOREAS_MEADOW_VERTEX_STRIDE + size_t(v)) * kMeadowFloats];
        for (size_t c = 0; c < 3; ++c) key.push_back(float(origin[c] + double(x[c]) - copy.position[c]));
      }
    copy.keys.push_back(std::move(key));
  }
}

namespace {

double farthest(const std::vector<float>& a, const std::vector<float>& b) {
  double most = 0.0;
  for (size_t i = 0; i + 2 < a.size(); i += 3)
    most = std::max(most, std::hypot(double(a[i]) - b[i], double(a[i + 1]) - b[i + 1], double(a[i + 2]) - b[i + 2]));
  return most;
}

}  // namespace

size_t loop_start(const std::vector<std::vector<float>>& keys, size_t frames) {
  size_t best = 0;
  double seam = -1.0;
  for (size_t s = 0; s + frames <= keys.size(); ++s) {
    const double d = farthest(keys[s + frames - 1], keys[s]);
    if (seam < 0 || d < seam) best = s, seam = d;
  }
  return best;
}

void MeadowClumps::close_loops(size_t frames) {
  for (const Clump& clump : clumps_) {
    std::vector<std::vector<float>>& keys = a_->morphed[clump.copy].keys;
    if (frames < 2 || keys.size() < frames) continue;
    const size_t start = loop_start(keys, frames);
    keys.erase(keys.begin(), keys.begin() + std::ptrdiff_t(start));
    keys.resize(frames);
    const size_t last = frames - 1;
    std::vector<float> drift(keys[0].size());
    for (size_t i = 0; i < drift.size(); ++i) drift[i] = keys[last][i] - keys[0][i];
    for (size_t k = 1; k <= last; ++k)
      for (size_t i = 0; i < drift.size(); ++i) keys[k][i] -= float(double(k) / double(last) * drift[i]);
    keys[last] = keys[0];
  }
}

}  // namespace boreas::impl
