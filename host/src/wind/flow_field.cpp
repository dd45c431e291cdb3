// boreas: flow primitive and gust bookkeeping.
#include "wind/flow_field.h"

#include <algorithm>

#include "errors.h"

namespace boreas::impl {

namespace {
double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}
}  // namespace

boreas_primitive_id FlowField::add_primitive(const boreas_flow_primitive_def& p, double now) {
  ++steady_version_;
  return primitives_.insert(Primitive{now, p});
}

boreas_gust_id FlowField::add_gust(const boreas_gust_def& g, double now) {
  return gusts_.insert(Gust{now, g});
}

void FlowField::remove(boreas_primitive_id id) {
  primitives_.erase(id);
  ++steady_version_;
}

void FlowField::remove(boreas_gust_id id) { gusts_.erase(id); }

double FlowField::gust_envelope(const boreas_gust_def& g, double created, double t) {
  double tau = t - created - g.delay;
  if (tau < 0.0) return 0.0;
  if (tau < g.rise) return smoothstep(tau / g.rise);
  tau -= g.rise;
  if (tau <= g.hold) return 1.0;
  tau -= g.hold;
  if (tau < g.fall) return 1.0 - smoothstep(tau / g.fall);
  return 0.0;
}

void FlowField::expire(double t) {
  primitives_.keep_if([&](const Primitive& p) {
    const bool ends = p.primitive.lifetime > 0 && t >= p.created + p.primitive.lifetime;
    if (ends) ++steady_version_;
    return !ends;
  });
  gusts_.keep_if([&](const Gust& g) {
    return t < g.created + g.gust.delay + g.gust.rise + g.gust.hold + g.gust.fall;
  });
}

BoreasGpuForcing FlowField::device_form(const boreas_flow_primitive_def& p) {
  BoreasGpuForcing f{};
  f.pos_x = p.position[0];
  f.pos_y = p.position[1];
  f.pos_z = p.position[2];
  f.radius = p.radius;
  f.dir_x = p.direction[0];
  f.dir_y = p.direction[1];
  f.dir_z = p.direction[2];
  f.strength = p.strength;
  f.uniform_weight = p.type == BOREAS_FLOW_UNIFORM ? 1.0f : 0.0f;
  f.radial_weight = p.type == BOREAS_FLOW_SOURCE ? 1.0f : (p.type == BOREAS_FLOW_SINK ? -1.0f : 0.0f);
  f.swirl_weight = p.type == BOREAS_FLOW_VORTEX ? 1.0f : 0.0f;
  return f;
}

std::vector<BoreasGpuForcing> FlowField::steady() const {
  std::vector<BoreasGpuForcing> out;
  primitives_.for_each([&](const Primitive& p) { out.push_back(device_form(p.primitive)); });
  return out;
}

std::vector<BoreasGpuForcing> FlowField::varying(double t) const {
  std::vector<BoreasGpuForcing> out;
  gusts_.for_each([&](const Gust& s) {
    double e = gust_envelope(s.gust, s.created, t);
    if (e <= 0.0) return;
    boreas_flow_primitive_def as_uniform = boreas_default_flow_primitive_def();
    for (int a = 0; a < 3; ++a) {
      as_uniform.position[a] = s.gust.center[a];
      as_uniform.direction[a] = s.gust.direction[a];
    }
    as_uniform.radius = s.gust.radius;
    as_uniform.strength = static_cast<float>(s.gust.strength * e);
    out.push_back(device_form(as_uniform));
  });
  return out;
}

std::vector<BoreasGpuForcing> FlowField::forcing(double t) const {
  std::vector<BoreasGpuForcing> out = steady();
  std::vector<BoreasGpuForcing> gusts = varying(t);
  out.insert(out.end(), gusts.begin(), gusts.end());
  return out;
}

}  // namespace boreas::impl
