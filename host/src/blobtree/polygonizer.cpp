// boreas: the device polygonizer of BlobTree trees (see polygonizer.h for the stages).
#include "blobtree/polygonizer.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "blobtree/cube_cases.h"
#include "errors.h"
#include "shared/blobtree_types.h"

namespace boreas::impl {
namespace {

constexpr int kFieldSlabs = 16;  // progress reports over the field stage
// Fractions of the whole work, for progress: the field dominates.
constexpr double kFieldShare = 0.75;
constexpr double kCountShare = 0.05;
constexpr double kEmitShare = 0.05;

std::string megabytes(double bytes) {
  std::ostringstream s;
  s.precision(3);
  s << bytes / (1024.0 * 1024.0) << " MiB";
  return s.str();
}

// Refuses a buffer the device cannot hold, naming what it was for.
void check_fits(const Runtime& rt, double bytes, const char* what) {
  cl_ulong max_alloc = rt.device().device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
  if (bytes > double(max_alloc))
    throw Error(BOREAS_ERROR_OUT_OF_MEMORY, std::string("blobtree: the ") + what + " needs " +
                                                megabytes(bytes) + " but the device allows " +
                                                megabytes(double(max_alloc)) +
                                                " per buffer; lower the resolution");
}

struct DeviceModel {
  BlobPlanes planes;
  BlobBins bins;
  cl::Buffer prims, ints, cuts, bin_first, bin_items, all_items;
};

DeviceModel upload_model(Runtime& rt, const BlobModel& model, const BlobGrid& grid, bool naive) {
  DeviceModel d;
  d.planes = blob_planes(model, grid.origin);
  d.bins = blob_bins(model, grid);
  d.prims =
      rt.buffer(CL_MEM_READ_ONLY, d.planes.prims.size() * sizeof(float), "blobtree primitives");
  d.ints = rt.buffer(CL_MEM_READ_ONLY, d.planes.ints.size() * sizeof(int32_t),
                     "blobtree primitive ints");
  d.cuts = rt.buffer(CL_MEM_READ_ONLY, d.planes.cuts.size() * sizeof(float), "blobtree cuts");
  check_fits(rt, double(d.bins.items.size()) * sizeof(int32_t), "bin lists");
  d.bin_first = rt.buffer(CL_MEM_READ_ONLY, d.bins.first.size() * sizeof(int32_t), "blobtree bins");
  d.bin_items =
      rt.buffer(CL_MEM_READ_ONLY, d.bins.items.size() * sizeof(int32_t), "blobtree bin items");
  rt.upload(d.prims, d.planes.prims);
  rt.upload(d.ints, d.planes.ints);
  rt.upload(d.cuts, d.planes.cuts);
  rt.upload(d.bin_first, d.bins.first);
  rt.upload(d.bin_items, d.bins.items);
  if (naive) {
    std::vector<int32_t> all(d.planes.n);
    std::iota(all.begin(), all.end(), 0);
    d.all_items = rt.buffer(CL_MEM_READ_ONLY, all.size() * sizeof(int32_t), "blobtree bin items");
    rt.upload(d.all_items, all);
  }
  return d;
}

// Stage 1 into `field`. Every kernel works in the grid's frame (point (x, y, z) at
// cell * (x, y, z), see BlobPlanes); the mesh's positions get the origin back on the
// host, in double.
void run_field(Runtime& rt, DeviceModel& d, const BlobGrid& grid, bool naive, cl::Buffer& field,
               const BlobProgress& progress) {
  cl::Kernel& k = naive ? rt.kernel("blobtree_field.cl", "boreas_blobtree_field_naive")
                        : rt.kernel("blobtree_field.cl", "boreas_blobtree_field");
  // A slab of bins starting at grid z z0 (the naive twin takes the list of all primitives
  // where the binned kernel takes the bins).
  auto launch_slab = [&](int z0, size_t z_points) {
    const Items range = blobtree_field_items(grid, rt.simd_width(), z_points);
    if (naive) {
      launch(rt, k, range, d.prims, d.ints, d.planes.n, d.all_items, d.cuts, d.planes.cut_count,
             float(grid.cell), grid.nx, grid.ny, z0, field);
    } else {
      launch(rt, k, range, d.prims, d.ints, d.planes.n, d.bin_first, d.bin_items, d.bins.bx,
             d.bins.by, d.cuts, d.planes.cut_count, float(grid.cell), grid.nx, grid.ny, z0, field);
    }
  };
  const int bins_z = grid.bins_z();
  const int slabs = std::min(kFieldSlabs, bins_z);
  int done = 0;
  for (int s = 0; s < slabs; ++s) {
    int end = bins_z * (s + 1) / slabs;
    launch_slab(done * BOREAS_BT_BIN, size_t(end - done) * BOREAS_BT_BIN);
    done = end;
    if (progress) {
      BOREAS_CL_CHECK(rt.queue().finish());
      progress(kFieldShare * double(done) / bins_z, "field");
    }
  }
}

// The field grid's buffer: the scratch's when it is big enough, else a new one (kept in
// the scratch when small enough to keep).
cl::Buffer field_buffer(Runtime& rt, const BlobGrid& grid, BlobScratch* scratch) {
  const size_t bytes = size_t(grid.points()) * sizeof(float);
  if (scratch && scratch->field_bytes >= bytes) return scratch->field;
  cl::Buffer field = rt.buffer(CL_MEM_READ_WRITE, bytes, "blobtree field grid");
  if (scratch && bytes <= BlobScratch::kMaxKeptBytes) {
    scratch->field = field;
    scratch->field_bytes = bytes;
  }
  return field;
}

// Stage 2's results: the marching-cubes tables on the device, and per row of cubes the
// vertices and triangles it makes (on the device, and read back).
struct RowCounts {
  cl::Buffer case_buffer, table_buffer, row_vertices, row_triangles;
  std::vector<int32_t> vertex_counts, triangle_counts;
};

// Stage 2: counts per row.
RowCounts count_rows(Runtime& rt, const BlobGrid& grid, const cl::Buffer& field) {
  const int rows = grid.ny * grid.nz;
  RowCounts counts;
  // Ints, not bytes: the count kernel gathers them per lane (cl/blobtree_mesh.cl).
  std::vector<int32_t> case_triangles(256);
  for (int c = 0; c < 256; ++c) case_triangles[c] = cube_case_triangles(c);
  const auto& table = cube_case_table();
  std::vector<int8_t> table_bytes(table.begin(), table.end());
  counts.case_buffer =
      rt.buffer(CL_MEM_READ_ONLY, case_triangles.size() * sizeof(int32_t), "marching cubes cases");
  counts.table_buffer = rt.buffer(CL_MEM_READ_ONLY, table_bytes.size(), "marching cubes table");
  rt.upload(counts.case_buffer, case_triangles);
  rt.upload(counts.table_buffer, table_bytes);
  counts.row_vertices =
      rt.buffer(CL_MEM_READ_WRITE, size_t(rows) * sizeof(int32_t), "blobtree rows");
  counts.row_triangles =
      rt.buffer(CL_MEM_READ_WRITE, size_t(rows) * sizeof(int32_t), "blobtree rows");
  {
    cl::Kernel& k = rt.kernel("blobtree_mesh.cl", "boreas_blobtree_count");
    launch(rt, k, Items(size_t(rows)), field, grid.nx, grid.ny, grid.nz, counts.case_buffer,
           counts.row_vertices, counts.row_triangles);
  }
  counts.vertex_counts.resize(rows);
  counts.triangle_counts.resize(rows);
  BOREAS_CL_CHECK(rt.queue().enqueueReadBuffer(
      counts.row_vertices, CL_FALSE, 0, rows * sizeof(int32_t), counts.vertex_counts.data()));
  BOREAS_CL_CHECK(rt.queue().enqueueReadBuffer(
      counts.row_triangles, CL_TRUE, 0, rows * sizeof(int32_t), counts.triangle_counts.data()));
  return counts;
}

// Stage 3: each row's first vertex and triangle, and the totals.
struct RowFirsts {
  std::vector<int32_t> vertex_first, triangle_first;
  int64_t vertices = 0, triangles = 0;
};

RowFirsts row_firsts(const RowCounts& counts) {
  const size_t rows = counts.vertex_counts.size();
  RowFirsts f;
  f.vertex_first.resize(rows);
  f.triangle_first.resize(rows);
  for (size_t r = 0; r < rows; ++r) {
    f.vertex_first[r] = static_cast<int32_t>(f.vertices);
    f.triangle_first[r] = static_cast<int32_t>(f.triangles);
    f.vertices += counts.vertex_counts[r];
    f.triangles += counts.triangle_counts[r];
    if (f.vertices > INT32_MAX / 8 || f.triangles > INT32_MAX / 4)
      throw Error(BOREAS_ERROR_OUT_OF_MEMORY,
                  "blobtree: the mesh has more than 2^28 vertices; lower the resolution");
  }
  return f;
}

// Stage 4's results: the vertices' positions and the triangles' indices.
struct Emitted {
  cl::Buffer positions, indices;
};

// Stage 4: vertices and triangles.
Emitted emit_triangles(Runtime& rt, const BlobGrid& grid, const cl::Buffer& field,
                       const RowCounts& counts, const RowFirsts& f) {
  const int rows = grid.ny * grid.nz;
  cl::Buffer first_v = rt.buffer(CL_MEM_READ_ONLY, size_t(rows) * sizeof(int32_t), "blobtree rows");
  cl::Buffer first_t = rt.buffer(CL_MEM_READ_ONLY, size_t(rows) * sizeof(int32_t), "blobtree rows");
  rt.upload(first_v, f.vertex_first);
  rt.upload(first_t, f.triangle_first);
  Emitted e;
  e.positions =
      rt.buffer(CL_MEM_READ_WRITE, size_t(f.vertices) * 3 * sizeof(float), "blobtree vertices");
  e.indices =
      rt.buffer(CL_MEM_WRITE_ONLY, size_t(f.triangles) * 3 * sizeof(uint32_t), "blobtree indices");
  {
    cl::Kernel& k = rt.kernel("blobtree_mesh.cl", "boreas_blobtree_emit");
    launch(rt, k, Items(size_t(rows)), field, grid.nx, grid.ny, grid.nz, float(grid.cell),
           counts.table_buffer, first_v, first_t, counts.row_vertices, counts.row_triangles,
           e.positions, e.indices);
  }
  return e;
}

// The mesh's vertices: positions back in the world (the origin added in double), normals
// and texture coordinates from the attribute planes, whose slot s holds vertex order[s].
void fill_vertices(const std::vector<float>& emitted, const std::vector<float>& planes,
                   const std::vector<int32_t>& order, const BlobGrid& grid, BlobMesh* mesh) {
  const int nv = static_cast<int>(order.size());
  mesh->positions.resize(size_t(nv) * 3);
  mesh->normals.resize(size_t(nv) * 3);
  mesh->uvs.resize(size_t(nv) * 2);
  for (size_t i = 0; i < emitted.size(); ++i)
    mesh->positions[i] = static_cast<float>(emitted[i] + grid.origin[i % 3]);
  // Slot s of the planes holds vertex order[s].
  for (int s = 0; s < nv; ++s) {
    const size_t i = size_t(order[size_t(s)]);
    for (int c = 0; c < 3; ++c)
      mesh->normals[3 * i + c] = planes[size_t(BOREAS_BT_VERTEX_NORMAL + c) * nv + s];
    for (int c = 0; c < 2; ++c)
      mesh->uvs[2 * i + c] = planes[size_t(BOREAS_BT_VERTEX_UV + c) * nv + s];
  }
}

// Stage 5: normals and texture coordinates, the vertices taken in the order of their
// bins (vertices_by_bin), so that a work-item's lanes walk few lists. The positions read
// back for the order are the mesh's (the attributes leave them out).
void add_attributes(Runtime& rt, DeviceModel& d, const BlobGrid& grid, const Emitted& e,
                    const RowFirsts& f, BlobMesh* mesh) {
  const int nv = static_cast<int>(f.vertices);
  std::vector<float> emitted(size_t(nv) * 3);
  BOREAS_CL_CHECK(rt.queue().enqueueReadBuffer(e.positions, CL_TRUE, 0,
                                               emitted.size() * sizeof(float), emitted.data()));
  const std::vector<int32_t> order = vertices_by_bin(emitted, grid, d.bins);
  cl::Buffer order_buffer =
      rt.buffer(CL_MEM_READ_ONLY, order.size() * sizeof(int32_t), "blobtree vertex order");
  rt.upload(order_buffer, order);
  cl::Buffer attributes = rt.buffer(
      CL_MEM_WRITE_ONLY, size_t(nv) * BOREAS_BT_VERTEX_FLOATS * sizeof(float), "blobtree mesh");
  {
    cl::Kernel& k = rt.kernel("blobtree_mesh.cl", "boreas_blobtree_attributes");
    // simd_width() vertices per work-item (cl/blobtree_mesh.cl).
    launch(rt, k, Items(size_t(nv)).per_work_item(size_t(rt.simd_width())), d.prims, d.ints,
           d.planes.n, d.bin_first, d.bin_items, d.bins.bx, d.bins.by, d.bins.bz, d.cuts,
           d.planes.cut_count, float(grid.cell), float(0.25 * grid.cell), e.positions, order_buffer,
           nv, nv, attributes);
  }
  std::vector<float> planes(size_t(nv) * BOREAS_BT_VERTEX_FLOATS);
  mesh->indices.resize(size_t(f.triangles) * 3);
  BOREAS_CL_CHECK(rt.queue().enqueueReadBuffer(
      e.indices, CL_FALSE, 0, mesh->indices.size() * sizeof(uint32_t), mesh->indices.data()));
  BOREAS_CL_CHECK(rt.queue().enqueueReadBuffer(attributes, CL_TRUE, 0,
                                               planes.size() * sizeof(float), planes.data()));
  fill_vertices(emitted, planes, order, grid, mesh);
}

}  // namespace

std::vector<int32_t> vertices_by_bin(const std::vector<float>& positions, const BlobGrid& grid,
                                     const BlobBins& bins) {
  const size_t n = positions.size() / 3;
  const float inv_bin = 1.0f / (float(grid.cell) * float(BOREAS_BT_BIN));
  const int extent[3] = {bins.bx, bins.by, bins.bz};
  std::vector<int32_t> key(n);
  std::vector<int32_t> first(size_t(bins.bx) * bins.by * bins.bz + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    int b[3];
    for (int a = 0; a < 3; ++a) {
      // Clamped as floats first: NaN or a far point must still land in some bin.
      const float c = std::floor(positions[3 * i + a] * inv_bin);
      b[a] = c >= 0.0f ? (c < float(extent[a]) ? int(c) : extent[a] - 1) : 0;
    }
    key[i] = (b[2] * bins.by + b[1]) * bins.bx + b[0];
    ++first[size_t(key[i]) + 1];
  }
  for (size_t b = 1; b < first.size(); ++b) first[b] += first[b - 1];
  std::vector<int32_t> order(n);
  for (size_t i = 0; i < n; ++i) order[size_t(first[size_t(key[i])]++)] = static_cast<int32_t>(i);
  return order;
}

Items blobtree_field_items(const BlobGrid& grid, int simd_width, size_t z_points) {
  const int lanes_x = std::min(simd_width, BOREAS_BT_BIN);
  const int lanes_y = simd_width / lanes_x;
  return Items(size_t(grid.nx), size_t(grid.ny), z_points)
      .per_work_item(size_t(lanes_x), size_t(lanes_y));
}

std::vector<float> sample_blobtree_field(Runtime& rt, const BlobModel& model, const BlobGrid& grid,
                                         bool naive) {
  check_fits(rt, double(grid.points()) * sizeof(float), "field grid");
  DeviceModel d = upload_model(rt, model, grid, naive);
  cl::Buffer field =
      rt.buffer(CL_MEM_READ_WRITE, size_t(grid.points()) * sizeof(float), "blobtree field grid");
  run_field(rt, d, grid, naive, field, {});
  std::vector<float> out(grid.points());
  BOREAS_CL_CHECK(
      rt.queue().enqueueReadBuffer(field, CL_TRUE, 0, out.size() * sizeof(float), out.data()));
  return out;
}

BlobMesh polygonize_blobtree(Runtime& rt, const BlobModel& model, const BlobGrid& grid,
                             const PolygonizeOptions& options) {
  const BlobProgress& progress = options.progress;
  check_fits(rt, double(grid.points()) * sizeof(float), "field grid");
  DeviceModel d = upload_model(rt, model, grid, options.naive);
  BlobMesh mesh;
  mesh.grid = grid;
  mesh.bin_items = int64_t(d.bins.items.size());
  cl::Buffer field = field_buffer(rt, grid, options.scratch);
  run_field(rt, d, grid, options.naive, field, progress);
  const RowCounts counts = count_rows(rt, grid, field);
  if (progress) progress(kFieldShare + kCountShare, "count");
  const RowFirsts firsts = row_firsts(counts);
  if (firsts.triangles == 0) {
    if (progress) progress(1.0, "done");
    return mesh;
  }
  check_fits(rt, double(firsts.vertices) * BOREAS_BT_VERTEX_FLOATS * sizeof(float),
             "vertex buffer");
  check_fits(rt, double(firsts.triangles) * 3 * sizeof(uint32_t), "index buffer");
  const Emitted emitted = emit_triangles(rt, grid, field, counts, firsts);
  if (progress) {
    BOREAS_CL_CHECK(rt.queue().finish());
    progress(kFieldShare + kCountShare + kEmitShare, "triangles");
  }
  add_attributes(rt, d, grid, emitted, firsts, &mesh);
  if (progress) progress(1.0, "done");
  return mesh;
}

}  // namespace boreas::impl
