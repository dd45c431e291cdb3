// boreas: the flow primitives and gusts of a world, with ids that catch stale use,
// lifetimes and gust envelopes, turned each step into the forcing list of the grid.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "boreas/boreas.h"
#include "shared/wind_types.h"
#include "slot_map.h"

namespace boreas::impl {

class FlowField {
 public:
  // world_serial: the world's number, in every id issued (slot_map.h).
  explicit FlowField(uint32_t world_serial) : primitives_(world_serial), gusts_(world_serial) {}

  // Arguments are already checked (wind_params.h). now = world time in s.
  boreas_primitive_id add_primitive(const boreas_flow_primitive_def& p, double now);
  boreas_gust_id add_gust(const boreas_gust_def& g, double now);
  // Throw BOREAS_ERROR_NOT_FOUND for a removed, expired, unknown or foreign id.
  void remove(boreas_primitive_id id);
  void remove(boreas_gust_id id);
  // Removes primitives whose lifetime and gusts whose fall has ended by time t.
  void expire(double t);
  // The forcing the grid applies at time t: steady() and varying(t) together.
  std::vector<BoreasGpuForcing> forcing(double t) const;
  // Flow primitives: they do not change from step to step, so the grid keeps their summed
  // field and rebuilds it only when steady_version() changes.
  std::vector<BoreasGpuForcing> steady() const;
  uint64_t steady_version() const { return steady_version_; }
  // Gusts, whose strength follows their envelope at time t (silent ones left out).
  std::vector<BoreasGpuForcing> varying(double t) const;
  bool empty() const { return primitives_.size() == 0 && gusts_.size() == 0; }

  // Strength factor of a gust at time t (0 before its rise and after its fall).
  static double gust_envelope(const boreas_gust_def& g, double created, double t);

 private:
  struct Primitive {
    double created = 0.0;
    boreas_flow_primitive_def primitive{};
  };
  struct Gust {
    double created = 0.0;
    boreas_gust_def gust{};
  };
  static BoreasGpuForcing device_form(const boreas_flow_primitive_def& p);

  SlotMap<boreas_primitive_id, Primitive> primitives_;
  SlotMap<boreas_gust_id, Gust> gusts_;
  uint64_t steady_version_ = 0;
};

}  // namespace boreas::impl
