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

boreas_id FlowField::claim() {
  int index;
  if (!free_.empty()) {
    index = free_.back();
    free_.pop_back();
  } else {
    index = static_cast<int>(slots_.size());
    slots_.emplace_back();
  }
  Slot& s = slots_[static_cast<size_t>(index)];
  s.alive = true;
  ++s.generation;
  ++live_;
  return boreas_id{index, s.generation};
}

void FlowField::release(size_t index) {
  Slot& s = slots_[index];
  s.alive = false;
  if (!s.is_gust) ++steady_version_;
  free_.push_back(static_cast<int>(index));
  --live_;
}

boreas_id FlowField::add_primitive(const boreas_flow_primitive& p, double now) {
  boreas_id id = claim();
  ++steady_version_;
  Slot& s = slots_[static_cast<size_t>(id.index)];
  s.is_gust = false;
  s.created = now;
  s.primitive = p;
  return id;
}

boreas_id FlowField::add_gust(const boreas_gust& g, double now) {
  boreas_id id = claim();
  Slot& s = slots_[static_cast<size_t>(id.index)];
  s.is_gust = true;
  s.created = now;
  s.gust = g;
  return id;
}

void FlowField::remove(boreas_id id) {
  if (id.index < 0 || static_cast<size_t>(id.index) >= slots_.size() ||
      !slots_[static_cast<size_t>(id.index)].alive ||
      slots_[static_cast<size_t>(id.index)].generation != id.generation) {
    fail(BOREAS_ERROR_NOT_FOUND, "flow id {" + std::to_string(id.index) + ", " +
                                     std::to_string(id.generation) +
                                     "} is not a live primitive or gust (removed, expired or "
                                     "never created)");
  }
  release(static_cast<size_t>(id.index));
}

double FlowField::gust_envelope(const boreas_gust& g, double created, double t) {
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
  for (size_t i = 0; i < slots_.size(); ++i) {
    Slot& s = slots_[i];
    if (!s.alive) continue;
    double end = s.is_gust ? s.created + s.gust.delay + s.gust.rise + s.gust.hold + s.gust.fall
                           : (s.primitive.lifetime > 0 ? s.created + s.primitive.lifetime : -1.0);
    if (end >= 0.0 && t >= end) release(i);
  }
}

BoreasGpuForcing FlowField::device_form(const boreas_flow_primitive& p) {
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
  for (const Slot& s : slots_) {
    if (s.alive && !s.is_gust) out.push_back(device_form(s.primitive));
  }
  return out;
}

std::vector<BoreasGpuForcing> FlowField::varying(double t) const {
  std::vector<BoreasGpuForcing> out;
  for (const Slot& s : slots_) {
    if (!s.alive || !s.is_gust) continue;
    double e = gust_envelope(s.gust, s.created, t);
    if (e <= 0.0) continue;
    boreas_flow_primitive as_uniform = boreas_default_flow_primitive();
    for (int a = 0; a < 3; ++a) {
      as_uniform.position[a] = s.gust.center[a];
      as_uniform.direction[a] = s.gust.direction[a];
    }
    as_uniform.radius = s.gust.radius;
    as_uniform.strength = static_cast<float>(s.gust.strength * e);
    out.push_back(device_form(as_uniform));
  }
  return out;
}

std::vector<BoreasGpuForcing> FlowField::forcing(double t) const {
  std::vector<BoreasGpuForcing> out = steady();
  std::vector<BoreasGpuForcing> gusts = varying(t);
  out.insert(out.end(), gusts.begin(), gusts.end());
  return out;
}

}  // namespace boreas::impl
