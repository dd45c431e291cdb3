// boreas: checking a boreas_blobtree_def, and building and polygonizing a world tree's
// BlobTree (see blobtree_instance.h).
#include "blobtree/blobtree_instance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "enum_as_int.h"
#include "errors.h"
#include "trees/tree_params.h"
#include "trees/tree_templates.h"

namespace boreas::impl {
namespace {

// The automatic min_radius in grid cells: a branch thinner than half a cell mostly falls
// between the grid's points. Those kept are at least kMinSurfaceCells thick, since a tube
// of radius below sqrt(3)/2 cells can pass between the points of a cell and comes out as
// a string of beads.
constexpr double kAutoMinRadiusCells = 0.5;
constexpr double kMinSurfaceCells = 0.9;

}  // namespace

BlobTreeParams checked_blobtree_def(const boreas_blobtree_def& def) {
  BlobTreeParams p;
  auto bad = [](const std::string& what) { fail_argument("blobtree_def." + what); };
  if (def.resolution < 16 || def.resolution > 1024)
    bad("resolution must be 16..1024 grid points, not " + std::to_string(def.resolution));
  p.resolution = def.resolution;
  if (def.cubic != 0 && def.cubic != 1) bad("cubic must be 0 or 1");
  p.cubic = def.cubic == 1;
  if (def.max_level < 0 || def.max_level > 3)
    bad("max_level must be 0..3, not " + std::to_string(def.max_level));
  p.options.max_level = def.max_level;
  if (!std::isfinite(def.min_radius) || def.min_radius < 0.0f || def.min_radius > 10.0f)
    bad("min_radius must be 0..10 m (0: half a grid cell)");
  p.options.min_radius = def.min_radius;
  const int junctions = enum_as_int(def.junctions);
  if (junctions != BOREAS_BLOBTREE_PCM && junctions != BOREAS_BLOBTREE_BLEND)
    bad("junctions must be BOREAS_BLOBTREE_PCM or BOREAS_BLOBTREE_BLEND, not " +
        std::to_string(junctions));
  p.options.pcm = junctions == BOREAS_BLOBTREE_PCM;
  if (def.offsets != 0 && def.offsets != 1) bad("offsets must be 0 or 1");
  p.options.offsets = def.offsets == 1;
  if (!std::isfinite(def.ridge) || def.ridge < 0.0f || def.ridge > 0.45f)
    bad("ridge must be 0..0.45 (below the iso-value 1/2)");
  p.options.pcm_peak = def.ridge;
  if (!std::isfinite(def.ridge_width) || def.ridge_width < 0.01f || def.ridge_width > 10.0f)
    bad("ridge_width must be 0.01..10 branch radii");
  p.options.pcm_width = def.ridge_width;
  if (!std::isfinite(def.bend) || def.bend < 0.0f || def.bend > 1.5707964f)
    bad("bend must be 0..pi/2 rad");
  p.options.bend_angle = def.bend;
  if (def.cut_count < 0) bad("cut_count must be >= 0, not " + std::to_string(def.cut_count));
  if (def.scar_count < 0) bad("scar_count must be >= 0, not " + std::to_string(def.scar_count));
  if (def.cut_count > 0 && !def.cuts) bad("cuts is NULL with cut_count > 0");
  if (def.scar_count > 0 && !def.scars) bad("scars is NULL with scar_count > 0");
  for (int i = 0; i < def.cut_count; ++i)
    p.options.cuts.push_back(BlobCutRequest{def.cuts[i].branch, def.cuts[i].at});
  for (int i = 0; i < def.scar_count; ++i)
    p.options.scars.push_back(
        BlobScarRequest{def.scars[i].branch, def.scars[i].stub, def.scars[i].depth});
  return p;
}

BlobSetup blobtree_setup(const TreeModel& tree, const glm::dvec3& position,
                         const BlobTreeParams& params, double rotation) {
  BlobSetup setup;
  BlobTreeOptions options = params.options;
  try {
    // The grid depends on the model's bounds and the radii on the grid: build once with
    // every branch, then again without those the grid cannot show.
    setup.model = build_blobtree(tree, position, options, rotation);
    setup.grid = blob_grid(setup.model, params.resolution, params.cubic);
    if (options.min_radius <= 0.0) options.min_radius = kAutoMinRadiusCells * setup.grid.cell;
    options.min_surface = kMinSurfaceCells * setup.grid.cell;
    setup.model = build_blobtree(tree, position, options, rotation);
    setup.grid = blob_grid(setup.model, params.resolution, params.cubic);
  } catch (const std::invalid_argument& e) {
    fail_argument(e.what());
  }
  setup.min_radius = options.min_radius;
  setup.min_surface = options.min_surface;
  return setup;
}

BlobTreeInstance make_blobtree(Runtime& rt, const TreeInstance& tree, const BlobTreeParams& params,
                               const BlobProgress& progress, BlobScratch* scratch) {
  const glm::dvec3 position(tree.params.position[0], tree.params.position[1],
                            tree.params.position[2]);
  // The tree's own model: its template at its scale, standing where it stands.
  BlobSetup setup = blobtree_setup(scaled_model(*whole_model(tree.model), tree.params.scale), position,
                                   params, tree.params.rotation);
  const BlobModel& model = setup.model;
  const BlobGrid& grid = setup.grid;
  BlobTreeInstance out;
  out.mesh = polygonize_blobtree(rt, model, grid, PolygonizeOptions{false, progress, scratch});
  boreas_blobtree_info& info = out.info;
  info.vertices = static_cast<int>(out.mesh.vertex_count());
  info.triangles = static_cast<int>(out.mesh.triangle_count());
  info.primitives = static_cast<int>(model.primitives.size());
  info.branches = model.branches_modeled;
  info.grid[0] = grid.nx;
  info.grid[1] = grid.ny;
  info.grid[2] = grid.nz;
  info.cell = static_cast<float>(grid.cell);
  info.min_radius = static_cast<float>(setup.min_radius);
  for (int c = 0; c < 3; ++c) {
    info.bounds_min[c] = info.vertices ? 1e30f : 0.0f;
    info.bounds_max[c] = info.vertices ? -1e30f : 0.0f;
  }
  for (size_t i = 0; i < out.mesh.positions.size(); ++i) {
    float v = out.mesh.positions[i];
    info.bounds_min[i % 3] = std::min(info.bounds_min[i % 3], v);
    info.bounds_max[i % 3] = std::max(info.bounds_max[i % 3], v);
  }
  return out;
}

}  // namespace boreas::impl
