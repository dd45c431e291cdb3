// boreas tests and benchmarks: EmbreeWorld's rays (rtcIntersect1 each, in parallel over
// OpenMP threads) and their hits as boreas_world_cast_rays writes them. Embree's
// conventions, checked: its direction need not be unit and tfar is in units of it, so the
// direction is normalized first (distances are then in m); Ng is the unnormalized
// cross(v1 - v0, v2 - v0) in either winding, so it is normalized and turned to face the
// ray; u and v are the barycentrics of v1 and v2.
#include <omp.h>

#include <cmath>
#include <stdexcept>

#include "embree_world_impl.h"

namespace boreas::reference {

namespace {

constexpr boreas_object_id kNullObject{0, 0, 0};

boreas_hit miss() {
  boreas_hit h{};
  h.distance = INFINITY;
  h.kind = BOREAS_HIT_NONE;
  h.object = kNullObject;
  h.part = -1;
  return h;
}

// The ray as Embree takes it: unit direction, from tnear 0 to max_distance.
RTCRayHit embree_ray(const boreas_ray& r) {
  RTCRayHit rh{};
  const float* d = r.direction;
  const float length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  rh.ray.org_x = r.origin[0];
  rh.ray.org_y = r.origin[1];
  rh.ray.org_z = r.origin[2];
  rh.ray.dir_x = d[0] / length;
  rh.ray.dir_y = d[1] / length;
  rh.ray.dir_z = d[2] / length;
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = r.max_distance;
  rh.ray.mask = ~0u;
  rh.ray.flags = 0;
  rh.ray.time = 0.0f;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  return rh;
}

// The boreas_hit of an Embree hit on geometry g.
boreas_hit to_hit(const RTCRayHit& rh, const EmbreeWorld::Geometry& g) {
  boreas_hit h{};
  const float t = rh.ray.tfar;
  const float d[3] = {rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z};
  const float o[3] = {rh.ray.org_x, rh.ray.org_y, rh.ray.org_z};
  h.distance = t;
  for (int k = 0; k < 3; ++k) h.point[k] = o[k] + t * d[k];
  double n[3] = {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  const double facing = n[0] * d[0] + n[1] * d[1] + n[2] * d[2] > 0.0 ? -1.0 : 1.0;
  for (int k = 0; k < 3; ++k) h.normal[k] = length > 0.0 ? float(facing * n[k] / length) : 0.0f;
  h.kind = g.kind;
  h.object = g.object;
  h.part = g.part(rh.hit.primID);
  return h;
}

}  // namespace

void EmbreeWorld::cast(const boreas_ray* rays, int count, boreas_hit* hits) const {
  if (!impl_->committed) throw std::logic_error("EmbreeWorld::cast before commit");
  const int threads = impl_->options.cast_threads > 0 ? impl_->options.cast_threads
                                                      : omp_get_max_threads();
  const RTCScene scene = impl_->scene;
  const auto& geometries = impl_->geometries;
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1024)
  for (int i = 0; i < count; ++i) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh = embree_ray(rays[i]);
    rtcIntersect1(scene, &context, &rh);
    hits[i] = rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? miss()
                                                       : to_hit(rh, *geometries[rh.hit.geomID]);
  }
}

EmbreeHit EmbreeWorld::cast_one(const boreas_ray& ray) const {
  if (!impl_->committed) throw std::logic_error("EmbreeWorld::cast_one before commit");
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh = embree_ray(ray);
  rtcIntersect1(impl_->scene, &context, &rh);
  EmbreeHit out;
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
    out.hit = miss();
    return out;
  }
  const Geometry& g = *impl_->geometries[rh.hit.geomID];
  out.hit = to_hit(rh, g);
  out.geometry = int32_t(rh.hit.geomID);
  out.triangle = int32_t(rh.hit.primID);
  const float b1 = rh.hit.u, b2 = rh.hit.v;
  out.barycentric[0] = 1.0f - b1 - b2;
  out.barycentric[1] = b1;
  out.barycentric[2] = b2;
  if (g.source == Source::kTreeLeaves) leaf_uv(rh.hit.primID, b1, b2, &out.leaf_uv[0], &out.leaf_uv[1]);
  const double d[3] = {rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z};
  out.cos_incidence = float(std::fabs(d[0] * out.hit.normal[0] + d[1] * out.hit.normal[1] +
                                      d[2] * out.hit.normal[2]));
  // The distance from the hit to the edge opposite vertex k is 2 area b_k / |that edge|.
  double p[3][3];
  for (int v = 0; v < 3; ++v)
    for (int k = 0; k < 3; ++k)
      p[v][k] = g.positions[3 * size_t(g.indices[3 * size_t(rh.hit.primID) + size_t(v)]) + size_t(k)];
  auto sub_length = [&](int a, int b) {
    double s = 0.0;
    for (int k = 0; k < 3; ++k) s += (p[a][k] - p[b][k]) * (p[a][k] - p[b][k]);
    return std::sqrt(s);
  };
  const double e[3] = {sub_length(1, 2), sub_length(2, 0), sub_length(0, 1)};
  double cross[3];
  const double a[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
  const double b[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
  cross[0] = a[1] * b[2] - a[2] * b[1];
  cross[1] = a[2] * b[0] - a[0] * b[2];
  cross[2] = a[0] * b[1] - a[1] * b[0];
  const double twice_area =
      std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
  double nearest = INFINITY;
  for (int k = 0; k < 3; ++k)
    if (e[k] > 0.0) nearest = std::fmin(nearest, twice_area * out.barycentric[k] / e[k]);
  out.edge_distance = float(nearest);
  return out;
}

}  // namespace boreas::reference
