// boreas tests and benchmarks: an Embree 3 scene of a boreas world's current triangles
// (embree_world.h). Each object part is one Embree geometry holding its own copy of the
// vertices (shared with Embree, padded for its 16-byte loads) and a label: the hit kind,
// the object's id and, per triangle, the part (branch, leaf, component, triangle).
#include <string>
#include <utility>

#include "embree_world_impl.h"

namespace boreas::reference {

namespace {

void on_error(void* user, RTCError, const char* message) {
  static_cast<std::string*>(user)->assign(message ? message : "");
}

bool on_memory(void* user, ssize_t bytes, bool /*post*/) {
  auto* m = static_cast<MemoryMonitor*>(user);
  const int64_t now = m->bytes.fetch_add(int64_t(bytes)) + int64_t(bytes);
  if (bytes > 0 && m->limit > 0 && now > m->limit) {
    m->bytes.fetch_sub(int64_t(bytes));
    return false;  // Embree cancels the build with RTC_ERROR_OUT_OF_MEMORY
  }
  return true;
}

// Rejects hits on a leaf's quad outside its outline (the renderer's alpha test).
void leaf_filter(const RTCFilterFunctionNArguments* args) {
  const auto* g = static_cast<const EmbreeWorld::Geometry*>(args->geometryUserPtr);
  const bool custom = g->outline && *g->outline;
  if (!custom && g->outline_kind < 0) return;
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const uint32_t triangle = RTCHitN_primID(args->hit, args->N, i);
    float u = 0.0f, v = 0.0f;
    leaf_uv(triangle, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i), &u, &v);
    const bool inside = custom ? (*g->outline)(g->part(triangle), u, v)
                               : boreas_leaf_outline_inside(g->outline_kind, u, v) != 0;
    if (!inside) args->valid[i] = 0;
  }
}

}  // namespace

void leaf_quad_corner(const boreas_leaf& leaf, float u, float v, float out[3]) {
  // leaf.vert: p = base + axis (v - base_v) L / (tip_v - base_v)
  //              + across (u - 0.5) W / (2 half_width), across = cross(axis, normal).
  const float* a = leaf.axis;
  const float* n = leaf.normal;
  const float across[3] = {a[1] * n[2] - a[2] * n[1], a[2] * n[0] - a[0] * n[2],
                           a[0] * n[1] - a[1] * n[0]};
  const float along = (v - kLeafBaseV) * leaf.length / (kLeafTipV - kLeafBaseV);
  const float side = (u - 0.5f) * leaf.width / (2.0f * kLeafHalfWidth);
  for (int k = 0; k < 3; ++k) out[k] = leaf.position[k] + a[k] * along + across[k] * side;
}

EmbreeWorld::Geometry& EmbreeWorld::Impl::add(Source source, boreas_hit_kind kind,
                                              boreas_object_id object) {
  auto g = std::make_unique<Geometry>();
  g->source = source;
  g->kind = kind;
  g->object = object;
  g->handle = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  throw_if_failed("rtcNewGeometry");
  if (options.update == EmbreeUpdate::kRefit)
    rtcSetGeometryBuildQuality(g->handle, RTC_BUILD_QUALITY_REFIT);
  rtcSetGeometryUserData(g->handle, g.get());
  if (source == Source::kTreeLeaves) {
    g->outline = &outline;
  }
  rtcAttachGeometryByID(scene, g->handle, unsigned(geometries.size()));
  throw_if_failed("rtcAttachGeometryByID");
  geometries.push_back(std::move(g));
  return *geometries.back();
}

// Hands the geometry's buffers to Embree: shared anew when they moved or changed size,
// else marked updated (Embree refits or rebuilds from them on commit).
void EmbreeWorld::Impl::share(Geometry& g) {
  if (g.positions.empty()) g.positions.assign(1, 0.0f);
  const bool same = g.shared_positions == g.positions.data() &&
                    g.shared_indices == g.indices.data() &&
                    g.shared_vertex_count == g.vertex_count() &&
                    g.shared_triangle_count == g.triangle_count();
  if (same) {
    rtcUpdateGeometryBuffer(g.handle, RTC_BUFFER_TYPE_VERTEX, 0);
  } else {
    rtcSetSharedGeometryBuffer(g.handle, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               g.positions.data(), 0, 3 * sizeof(float), g.vertex_count());
    rtcSetSharedGeometryBuffer(g.handle, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               g.indices.data(), 0, 3 * sizeof(uint32_t), g.triangle_count());
    g.shared_positions = g.positions.data();
    g.shared_indices = g.indices.data();
    g.shared_vertex_count = g.vertex_count();
    g.shared_triangle_count = g.triangle_count();
  }
  throw_if_failed("sharing a geometry's buffers");
  g.changed = true;
}

EmbreeWorld::EmbreeWorld(const EmbreeOptions& options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
  impl_->device = rtcNewDevice(nullptr);
  if (!impl_->device)
    throw std::runtime_error("EmbreeWorld: rtcNewDevice failed (error " +
                             std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
  rtcSetDeviceErrorFunction(impl_->device, on_error, &impl_->error);
  impl_->memory.limit = options.memory_limit;
  rtcSetDeviceMemoryMonitorFunction(impl_->device, on_memory, &impl_->memory);
  impl_->scene = rtcNewScene(impl_->device);
  int flags = options.robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE;
  if (options.update == EmbreeUpdate::kRefit) {
    flags |= RTC_SCENE_FLAG_DYNAMIC;
    rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_LOW);  // two levels: refit per geometry
  } else {
    rtcSetSceneBuildQuality(impl_->scene, RTC_BUILD_QUALITY_MEDIUM);
  }
  rtcSetSceneFlags(impl_->scene, RTCSceneFlags(flags));
  impl_->throw_if_failed("creating the scene");
}

EmbreeWorld::~EmbreeWorld() {
  for (auto& g : impl_->geometries) rtcReleaseGeometry(g->handle);
  if (impl_->scene) rtcReleaseScene(impl_->scene);
  if (impl_->device) rtcReleaseDevice(impl_->device);
}

void EmbreeWorld::add_tree(boreas_world world, boreas_tree_id tree,
                           const boreas_tree_level_def* levels, int outline) {
  const boreas_tree_def defaults = boreas_default_tree_def();
  if (!levels) levels = defaults.levels;
  Geometry& branches = impl_->add(Source::kTreeBranches, BOREAS_HIT_BRANCH, object_of(tree));
  for (int l = 0; l < 4; ++l) branches.levels[size_t(l)] = levels[l];
  impl_->read(world, branches);
  Geometry& leaves = impl_->add(Source::kTreeLeaves, BOREAS_HIT_LEAF, object_of(tree));
  leaves.outline_kind = outline;
  // Only with an outline: Embree calls a filter at every candidate hit.
  if (outline >= 0 || impl_->outline) rtcSetGeometryIntersectFilterFunction(leaves.handle, leaf_filter);
  impl_->read(world, leaves);
}

void EmbreeWorld::add_meadow(boreas_world world, boreas_meadow_id meadow) {
  impl_->read(world, impl_->add(Source::kMeadow, BOREAS_HIT_UNDERBRUSH, object_of(meadow)));
}

void EmbreeWorld::add_mesh_tree(boreas_world world, boreas_mesh_tree_id tree) {
  impl_->read(world, impl_->add(Source::kMeshTrunk, BOREAS_HIT_MESH_TRUNK, object_of(tree)));
  impl_->read(world, impl_->add(Source::kMeshLeaves, BOREAS_HIT_MESH_LEAF, object_of(tree)));
}

void EmbreeWorld::add_blobtree(boreas_world world, boreas_blobtree_id blobtree) {
  Geometry& g = impl_->add(Source::kFixed, BOREAS_HIT_BLOBTREE, object_of(blobtree));
  g.blobtree = blobtree;
  impl_->read_blobtree(world, g);
}

int EmbreeWorld::add_triangles(boreas_hit_kind kind, boreas_object_id object,
                               std::vector<float> positions, std::vector<uint32_t> indices,
                               std::vector<int32_t> parts) {
  if (positions.size() % 3 != 0 || indices.size() % 3 != 0)
    throw std::invalid_argument("EmbreeWorld::add_triangles: positions and indices must come "
                                "in threes");
  if (!parts.empty() && parts.size() != indices.size() / 3)
    throw std::invalid_argument("EmbreeWorld::add_triangles: " + std::to_string(parts.size()) +
                                " parts for " + std::to_string(indices.size() / 3) +
                                " triangles");
  const size_t vertices = positions.size() / 3;
  for (size_t i = 0; i < indices.size(); ++i)
    if (indices[i] >= vertices)
      throw std::invalid_argument("EmbreeWorld::add_triangles: indices[" + std::to_string(i) +
                                  "] = " + std::to_string(indices[i]) + " past the " +
                                  std::to_string(vertices) + " vertices");
  Geometry& g = impl_->add(Source::kFixed, kind, object);
  g.positions = std::move(positions);
  g.positions.push_back(0.0f);
  g.indices = std::move(indices);
  g.parts = std::move(parts);
  impl_->share(g);
  return int(impl_->geometries.size()) - 1;
}

void EmbreeWorld::set_triangles(int geometry, const std::vector<float>& positions) {
  if (geometry < 0 || geometry >= geometry_count() ||
      impl_->geometries[size_t(geometry)]->source != Source::kFixed)
    throw std::invalid_argument("EmbreeWorld::set_triangles: geometry " +
                                std::to_string(geometry) + " was not made by add_triangles");
  Geometry& g = *impl_->geometries[size_t(geometry)];
  if (positions.size() != 3 * g.vertex_count())
    throw std::invalid_argument("EmbreeWorld::set_triangles: " + std::to_string(positions.size()) +
                                " floats for " + std::to_string(g.vertex_count()) + " vertices");
  std::copy(positions.begin(), positions.end(), g.positions.begin());
  impl_->share(g);
}

void EmbreeWorld::set_leaf_outline(LeafOutline outline) {
  impl_->outline = std::move(outline);
  for (auto& g : impl_->geometries) {
    if (g->source != Source::kTreeLeaves) continue;
    const bool filter = impl_->outline || g->outline_kind >= 0;
    rtcSetGeometryIntersectFilterFunction(g->handle, filter ? leaf_filter : nullptr);
    g->changed = true;
  }
}

void EmbreeWorld::read(boreas_world world) {
  for (auto& g : impl_->geometries) impl_->read(world, *g);
}

void EmbreeWorld::commit() {
  for (auto& g : impl_->geometries) {
    if (!g->changed) continue;
    rtcCommitGeometry(g->handle);
    g->changed = false;
  }
  impl_->throw_if_failed("rtcCommitGeometry");
  rtcCommitScene(impl_->scene);
  impl_->throw_if_failed("rtcCommitScene");
  impl_->committed = true;
}

int64_t EmbreeWorld::triangle_count() const {
  int64_t n = 0;
  for (const auto& g : impl_->geometries) n += int64_t(g->triangle_count());
  return n;
}

int EmbreeWorld::geometry_count() const { return int(impl_->geometries.size()); }

int64_t EmbreeWorld::embree_bytes() const { return impl_->memory.bytes.load(); }

}  // namespace boreas::reference
