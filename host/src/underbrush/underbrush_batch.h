// boreas: every meadow of a world on the device as one set of component planes
// (cl/shared/underbrush_types.h), stepped by tile launches (underbrush_step.cl); the
// vertex kernel (underbrush_vertices.cl) writes the strips on request.
//
// Building and changing costs what the change costs, as for trees (runtime/block_space.h):
// a meadow's components are one block (their part and parent indices local to it), added
// after the last block, placed and uploaded a bounded piece at a time (so an add's peak is
// its device planes and one piece), into buffers that grow by doubling; removal leaves a hole, packed on the device once holes pass half. Part
// records and shape tables are appended alike (rebuilt, small, when the components are
// packed).
//
// Levels of detail (set_focus): a meadow's components are ordered by place
// (sort_plantings_by_place), so each tile of 64 covers a small patch; each tile takes a
// rate from its distance to the nearest focus point and its meadow's lod_distances (the
// vertex kernel's): every step, every 4th step (over 4 dt) or every 16th (over 16 dt), and
// none past the last distance, where the vertex kernel culls it anyway. The constraint
// step is exact for any dt, so a component that comes nearer goes on from where it is,
// without a jump. A component left alone in a step keeps its state through the ping-pong
// swap by a copy in the step after its update (cl/tile_copy.cl), and one whose rate
// changes by a copy in that step.
//
// Colliders (colliders/contacts.h): a grid over the ground (underbrush/tile_grid.h) finds
// the tiles each collider's sweep may reach; those tiles are stepped at rate 1 while it
// does (so a fast collider meets every component in its way) with the list of their
// colliders, and only they read any. A contact pass (underbrush_contacts.cl) then sums,
// per (tile, collider) pair, what the tile's components push the collider back with; the
// host adds the pairs up in their order when asked (add_contacts).
//
// The step writes the other half of a ping-pong state, visible only after commit(), so a
// failed step leaves the batch as it was.
//
// Every buffer stays within the device's largest allocation (max_components, fitting): a
// world whose meadows pass it keeps them in several batches, its chunks (world_chunks.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "colliders/contacts.h"
#include "free_places.h"
#include "runtime/block_space.h"
#include "runtime/launch_tiles.h"
#include "runtime/runtime.h"
#include "underbrush/meadow.h"
#include "underbrush/tile_grid.h"
#include "wind/plant_wind.h"

namespace boreas::impl {

struct MeadowInstance {
  uint64_t key = 0;
  Meadow meadow;
};

class UnderbrushBatch {
 public:
  // tile_numbers: the numbers whose low bits are the tiles' phases, shared with the world's
  // other meadow chunks (world_chunks.cpp) so that a tile steps in the same steps
  // whatever chunk holds it; a batch's own otherwise.
  explicit UnderbrushBatch(Runtime& runtime, std::shared_ptr<PlaceNumbers> tile_numbers = nullptr);

  bool empty() const { return by_key_.empty(); }
  bool holds(uint64_t key) const { return by_key_.count(key) != 0; }
  size_t meadow_count() const { return by_key_.size(); }
  // The steps committed, which pick the rate lists a step launches: a chunk made after
  // the world's first steps starts from the world's count (as TreeBatch's).
  void set_step_index(uint64_t steps) { step_index_ = steps; }
  int64_t component_count() const { return component_count_; }

  using Meadows = std::vector<std::shared_ptr<const MeadowInstance>>;
  // m: the origin of the coordinates positions are read out in (the world's 0 by default;
  // a renderer's camera-relative origin: boreas_world_set_output_origin).
  using Origin = std::array<double, 3>;

  // Adds meadows at rest, all or none: on a failure the batch is as it was.
  void add(const Meadows& meadows);
  void add(std::shared_ptr<const MeadowInstance> meadow) { add(Meadows{std::move(meadow)}); }
  // How many of meadows[first...] (in order) one add() could take with every component
  // plane within the device's largest allocation and 2^31 floats (max_components); 0
  // where even the first does not fit.
  size_t fitting(const Meadows& meadows, size_t first) const;
  void remove(uint64_t key);

  // Focus points (xyz packed); none steps every component every step.
  void set_focus(const std::vector<double>& xyz);
  // Components stepped every step, every 4th, every 16th, and not at all (as of the last
  // enqueued step).
  std::array<int64_t, 4> components_by_rate() const;

  // Enqueues one step; the step's colliders (World::step_colliders) and impulses as the
  // kernel reads them (unpadded). Their upload does not wait: the queue must finish before
  // the next enqueue_step (World::step does), as they are copied from this batch's staging
  // vectors. With `events`, the launches' events are appended.
  void enqueue_step(double dt, const PlantWind& wind, const StepColliders& colliders,
                    const std::vector<BoreasGpuImpulse>& impulses,
                    std::vector<cl::Event>* events = nullptr);
  void commit();
  // Adds what the components pushed back on each collider over the last committed step
  // (colliders/contacts.h; sums indexed as the step's colliders): a blocking read of the
  // contact pass's pairs, added up in their order.
  void add_contacts(std::vector<ContactSum>* sums);
  // (tile, collider) pairs of the last committed step's contact pass: the work its
  // colliders cost (tests and benchmarks).
  size_t contact_pairs() const { return contacts_[contacts_current_].colliders.size(); }

  // Blocking readbacks of one meadow (as of the last commit): its range only.
  std::vector<boreas_component> components(uint64_t key, const Origin& output_origin = {});
  // Every part's look, species by species (boreas_meadow_get_parts).
  std::vector<boreas_meadow_part> parts(uint64_t key);
  // Its strips (BOREAS_UB_JOINTS * 2 vertices of 8 floats per component) and counts, LOD
  // from the camera (NULL: full detail).
  void vertices(uint64_t key, const float* camera, std::vector<float>* vertices,
                std::vector<int32_t>* counts, const Origin& output_origin = {});
  // One meadow of a vertex launch: its first component's strip at component slot
  // out_first of the output (boreas_cl.h).
  struct VertexDraw {
    uint64_t key;
    size_t out_first;
    int first = 0;    // the meadow's components [first, first + count) (the rays' runs)
    int count = -1;   // -1: to the meadow's end
  };
  // Enqueues ONE launch of the vertex kernel over the listed meadows (each at its LOD
  // distances from the camera; NULL: full detail) into the given buffers.
  void enqueue_vertices(const std::vector<VertexDraw>& draws, const float* camera,
                        const cl::Buffer& out, const cl::Buffer& counts,
                        const Origin& output_origin = {});

  // For tests and benchmarks: one meadow's state planes (stride: its component count).
  std::vector<float> read_meadow_state(uint64_t key);
  // One meadow's frame and index planes (stride: its component count; indices local to
  // the meadow), read back: the host lets go of its copies once they are uploaded.
  std::vector<float> read_meadow_frame(uint64_t key);
  std::vector<int32_t> read_meadow_index(uint64_t key);
  int first(uint64_t key) const;  // index of the meadow's first component
  int stride() const { return int(components_.capacity); }
  const cl::Buffer& state_buffer() const { return state_[current_]; }

  // Components an add places and uploads at a time from a meadow's plantings (meadow.h,
  // place_piece): the add's peak is the device's planes and one such piece above them
  // (116 bytes a component on the host: ~30 MB). Tests set fewer to split small meadows.
  static constexpr int64_t kPieceComponents = int64_t(1) << 18;
  void set_piece_components(int64_t components) { piece_components_ = components; }

  // The rates of the levels of detail, and how many tile lists a rate's phases take.
  static constexpr int kRates[3] = {1, 4, 16};
  static int rate_list(int rate, int phase) { return (rate == 1 ? 0 : rate == 4 ? 1 : 5) + phase; }
  static constexpr int kListCount = 1 + 4 + 16;

 private:
  // read_meadow_state, _frame, _index: one meadow's range of `planes` planes of a
  // per-component buffer.
  template <typename T>
  std::vector<T> read_meadow_planes(const cl::Buffer& buffer, uint64_t key, int planes);
  // A tile of one meadow's components and where it is on the ground.
  struct Tile {
    int32_t slot = 0;
    int32_t offset = 0;  // its first component, from the meadow's first
    int32_t count = 0;
    float lo[3] = {}, hi[3] = {};  // the components' rest bases and centres of mass
    float margin = 0.0f;  // m beyond that box that their centres of mass and pushes reach
    int rate = 1;         // 0: left alone
    int32_t number = 0;   // in tile_numbers_: its phase's low bits
    TileLists::Segment segment;
  };
  struct Slot {
    std::shared_ptr<const MeadowInstance> meadow;
    int32_t first = 0;       // first component
    int32_t part_first = 0;  // first part record
    int64_t table_first = 0;
    std::vector<int32_t> tiles;  // indices into tiles_
  };
  const Slot& slot_of(uint64_t key) const;
  // add()'s steps: the first three change nothing of the batch but the device memory past
  // its used ends; take_new_parts and take_meadow make the new meadows the batch's.
  struct NewParts;
  int64_t components_needed(const Meadows& meadows) const;  // checks their keys
  NewParts write_new_parts(const Meadows& meadows);
  // A tile's box in the world: its components' rest bases and centres of mass, and how
  // far beyond it they reach (Tile's lo, hi, margin), gathered as they are uploaded.
  struct TileBox {
    float lo[3], hi[3];
    float margin = 0.0f;
  };
  // Uploads the meadows' components (placing those still plantings piece by piece) and
  // returns each meadow's tile boxes.
  std::vector<std::vector<TileBox>> write_new_components(const Meadows& meadows, int64_t first,
                                                         int64_t count);
  // write_new_components' parts: planes at stride count written at component `at` of the
  // current state, the frame and the index; the boxes of a meadow's tiles, empty; the
  // components [first, first + count) of a meadow (planes at stride count) added to them.
  void upload_piece(const float* frame, const int32_t* index, const float* rest_state, int count,
                    int64_t at);
  std::vector<TileBox> empty_boxes(int count) const;
  void add_to_boxes(const Meadow& m, const float* frame, const int32_t* index, int first,
                    int count, std::vector<TileBox>* boxes) const;
  void take_new_parts(const NewParts& parts);
  void take_meadow(const std::shared_ptr<const MeadowInstance>& meadow, int64_t first,
                   int32_t part_first, int64_t table_first, const std::vector<TileBox>& boxes);
  void relayout(int64_t capacity, bool pack);
  // The most components one batch holds: its widest planes (the frame's) within
  // Runtime::max_allocation and 2^31 floats.
  int64_t max_components() const;
  // The part records and tables of every meadow anew, packed (after removals).
  void repack_parts();
  void upload_parts(double dt);
  int rate_of(const Tile& tile, const MeadowParams& params) const;
  void tile_add(int32_t t);
  // Rates for this step (tiles a collider reaches: 1); tiles whose rate changes are
  // re-tiled and copied across.
  void update_rates();
  // The broadphase: which colliders of the step reach each tile (touch_*).
  void find_touches(const StepColliders& colliders);
  // enqueue_step's parts: the impulses uploaded (padded to slots, whose #define it
  // returns); the colliders, the rate-1 list's per-tile collider lists and the contact
  // pairs uploaded (whether any tile has a collider); one tile list's state copied into
  // the next half (tile_copy.cl); one tile list stepped (underbrush_step.cl, built with
  // defines); the contact pass.
  std::string upload_impulses(const std::vector<BoreasGpuImpulse>& impulses);
  // The step's wave phases at each slot's meadow origin (underbrush_step.cl).
  void upload_phases(const PlantWind& wind);
  bool upload_touches(const StepColliders& colliders);
  void copy_list(const cl::Buffer& tiles, size_t count, std::vector<cl::Event>* events);
  void step_list(int list, const std::string& defines, double dt, const PlantWind& wind,
                 int impulses, std::vector<cl::Event>* events);
  void enqueue_contacts(std::vector<cl::Event>* events);
  void rebuild_tiles();

  Runtime& runtime_;
  std::shared_ptr<PlaceNumbers> tile_numbers_;
  std::vector<Slot> slots_;
  std::vector<int32_t> free_slots_;
  std::unordered_map<uint64_t, int32_t> by_key_;
  std::vector<Tile> tiles_host_;  // freed ones have count 0
  std::vector<int32_t> free_tiles_;
  BlockSpace components_;
  // Its smallest capacity: a batch's first buffers, and where shrinking stops.
  static constexpr int64_t kMinComponents = 1024;
  int64_t component_count_ = 0;
  int64_t piece_components_ = kPieceComponents;
  int current_ = 0;
  uint64_t step_index_ = 0;
  std::vector<double> focus_;
  TileLists tiles_{kListCount};
  TileLists changed_{1};  // this step's tiles whose rate changed (copied across)
  bool rebuild_tiles_ = false;
  std::vector<BoreasGpuPart> parts_host_;  // with table offsets into tables_host_
  std::vector<float> tables_host_;
  int64_t dead_parts_ = 0, dead_tables_ = 0;
  size_t parts_capacity_ = 0, tables_capacity_ = 0;
  double parts_dt_ = -1.0;  // dt the device's part records' decay was written for
  cl::Buffer state_[2], frame_, index_, parts_, tables_;
  cl::Buffer impulses_;
  // The vertex launch's meadow table (enqueue_vertices) and its host side.
  cl::Buffer draws_;
  size_t draw_capacity_ = 0;
  std::vector<BoreasUbDraw> draw_staging_;
  std::vector<BoreasGpuImpulse> impulse_staging_;  // read by the step's upload_async
  size_t impulse_capacity_ = 0;
  // Colliders: the grid of tile boxes (rebuilt when tiles come or go), this step's
  // touches (per tile, a range of touch_colliders_), and the device's copies: a collider
  // record per touch, relative to its tile's meadow origin (far out as exact as near 0),
  // the rate-1 list's (first, count) per tile into them, and the contact pairs.
  TileGrid grid_;
  bool grid_stale_ = true;
  std::vector<int32_t> touch_first_, touch_count_, touch_colliders_;
  // A device buffer of `capacity` elements, grown (never shrunk) to hold a staging vector.
  struct Staged {
    cl::Buffer buffer;
    size_t capacity = 0;
  };
  Staged colliders_, tile_colliders_, pairs_, phases_;
  std::vector<float> phase_staging_;
  std::vector<BoreasGpuCollider> collider_staging_;
  std::vector<int32_t> tile_collider_staging_, pair_staging_;
  // The contact pass's output: one being written by the step in flight, one committed.
  struct Contacts {
    Staged out;                      // BOREAS_UB_PAIR_FLOATS per pair
    std::vector<int32_t> colliders;  // each pair's collider
  };
  Contacts contacts_[2];
  int contacts_current_ = 0;
};

}  // namespace boreas::impl
