// boreas: the trees of a world that share one animation mode, on the device as planes
// (cl/shared/tree_types.h) in the blocks of trees/tree_layout.h, stepped together: per
// step one tile launch for every stepped branch and one for every carried branch (lagged),
// or two per level (exact), then the leaves.
//
// Building and changing a forest costs what the change costs:
//  - trees of one template (same model and physics) share one template block: adding a
//    tree of a known template writes only its own state (its rest pose, one rectangular
//    upload per buffer for a whole add() call) and computes its leaves on the device;
//  - buffers grow by doubling with a device-side copy that keeps every index, so a tree is
//    never read back or re-uploaded because another one came;
//  - removing a tree leaves a hole that no launch covers (or shortens the batch when it
//    was last); once holes pass half the batch, the blocks after them are moved down on
//    the device (parent indices are local to a tree's root, so nothing is uploaded), and
//    once the live trees fill less than a quarter of it they are moved into smaller
//    buffers (runtime/block_space.h: the capacity follows the population, with
//    hysteresis);
//  - ids map to blocks through hash maps; getters read their tree's ranges only.
// Entry 0 of every set of planes is a sink (trees/tree_layout.h) where removed trees'
// tiles point until the lists are rebuilt.
//
// Every buffer of a batch stays within the device's largest allocation (space_limits); a
// world whose trees pass that keeps them in several batches of a mode, its chunks
// (world_chunks.cpp), which ask fitting() how many trees they take.
//
// Leaves are not stored: a leaf is a function of its branch's current state, so it is
// made when read (cl/tree_leaves.cl, straight into the caller's records). A forest's
// hundreds of millions of leaves take no memory or step time of their own; a renderer
// pays for the leaves it draws, when it draws them.
//
// Levels of detail (set_focus): each tree takes one from its base's distance to the
// nearest focus point (TreeParams::lod_distances). Carried branches keep their place on
// their parent's current frame while their bend decays to rest over kCarryTimeConstant;
// a tree past the last distance is carried whole until it rests (kSettleTime), then its
// state is left alone. A branch that starts being stepped again starts from where it was
// drawn and eases into the wind over kResumeTimeConstant.
//
// Derived branches: a tree's finest level, once carried for kSettleTime (its bend has
// decayed as a frozen tree's does), is no longer carried at all: it sits rigidly on its
// parent's current frame, so every reader derives its pose when it reads it
// (cl/shared/tree_state.h, boreas_tree_pose) and the step never writes it. Its state
// planes then hold a mark and where its inputs are (written in both halves, and again
// after blocks move); its motion planes stay as the last carry left them, equal in both
// halves. It is stepped again when its level of detail steps it, its derived poses first
// written over the marks (tree_batch_derived_tiers.cpp: a split piece's lagged step reads
// its parent's previous state, a piece of the same level).
// Its entries then move to the settled space (tree_batch_settled.cpp); a tree added with a
// focus that derives its finest level puts it there at once (tree_batch_settled_add.cpp:
// a carry from rest would leave F, dF/dt and the broken flag 0, so nothing differs once
// the twin added whole has derived it).
//
// Its members are defined by idea: tree_batch.cpp (adding and removing trees),
// tree_batch_layout.cpp (the blocks' buffers, relayout), tree_batch_lod.cpp (levels of
// detail and tiles), tree_batch_step.cpp (the step's launches), tree_batch_contacts.cpp
// (colliders: which trees they touch, the contact launches, what the branches push back
// with), tree_batch_readback.cpp (blocking readbacks), tree_batch_records.cpp (records
// and meshes made on the device), tree_batch_view.cpp (a view's records of every tree in
// one call: the view table, culling, thinning, impostors).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "colliders/contacts.h"
#include "runtime/block_space.h"
#include "runtime/launch_tiles.h"
#include "runtime/runtime.h"
#include "shared/tree_origin.h"
#include "shared/tree_records.h"
#include "shared/tree_types.h"
#include "trees/template_numbers.h"
#include "trees/tree_layout.h"
#include "trees/tree_model.h"
#include "trees/tree_params.h"
#include "trees/tree_tiles.h"
#include "wind/plant_wind.h"

namespace boreas::impl {

struct TreeInstance {
  uint64_t key = 0;  // unique within the world
  TreeParams params;
  std::shared_ptr<const TreeModel> model;  // the template, grown at scale 1 (shared)
  std::string template_key;                // its key in the world's templates
};

// A tree's params with its base at 0: the placement its state is kept in, relative to its
// base (cl/shared/tree_origin.h; tree_batch_origin.cpp).
TreeParams at_own_base(const TreeParams& params);

// The launches of one step, for benchmarks that time the library's own launches.
struct TreeStepEvents {
  std::vector<cl::Event> branches;  // step and carry launches, in order
};

// Time constants of level-of-detail changes, s.
inline constexpr double kCarryTimeConstant =
    0.5;  // a carried branch's bend decays as exp(-t / this)
inline constexpr double kResumeTimeConstant = 0.2;  // a resumed branch eases into the wind so
inline constexpr double kResumeTime = 1.0;          // ... for this long, then is stepped plainly
inline constexpr double kSettleTime = 3.0;          // a tree carried whole before it freezes

class TreeBatch {
 public:
  // numbers: shared with the other batches (chunks) of the mode where a world splits its
  // trees over several (world_chunks.cpp); a batch of its own otherwise.
  TreeBatch(Runtime& runtime, boreas_tree_mode mode,
            std::shared_ptr<TemplateNumbers> numbers = nullptr);

  bool empty() const { return by_key_.empty(); }
  bool holds(uint64_t key) const { return by_key_.count(key) != 0; }
  // The steps committed, which pick the carry lists a step launches: a chunk made after
  // the world's first steps starts from the world's count, so its trees are carried in the
  // same steps as in the chunks made before it.
  void set_step_index(uint64_t steps) { step_index_ = steps; }
  size_t tree_count() const { return by_key_.size(); }
  size_t template_block_count() const { return template_by_key_.size(); }
  int64_t branch_count() const { return branch_count_; }  // real branches, roots excluded
  int64_t leaf_count() const { return leaf_count_; }

  using Trees = std::vector<std::shared_ptr<const TreeInstance>>;
  // Where handed-out positions count from (boreas_world_set_output_origin; {} : world
  // coordinates). The state is kept relative to each tree's base (cl/shared/tree_origin.h).
  using Origin = std::array<double, 3>;

  // Adds trees, placed unbent at rest, all or none: on a failure the batch is as it was.
  void add(const Trees& trees);
  void add(std::shared_ptr<const TreeInstance> tree) { add(Trees{std::move(tree)}); }
  // How many of trees[first...] (in order) one add() could take with every buffer of the
  // batch within the device's largest allocation and its indices within int
  // (space_limits): the world splits a forest into chunks by it. 0 where even the first
  // does not fit (a tree, or its template block, bigger than a whole chunk).
  size_t fitting(const Trees& trees, size_t first) const;
  // Removes the tree with this key (it must be present).
  void remove(uint64_t key);

  // Focus points for the levels of detail (xyz packed); none puts every tree at full detail.
  void set_focus(const std::vector<double>& xyz);
  // Trees per level of detail (TreeLod order), as of the last enqueued step.
  std::array<int64_t, kTreeLodCount> lod_counts() const;
  // Branches stepped and carried (not stepped: carried or derived) by the last enqueued
  // step; the derived ones now (left to their readers, not written).
  int64_t branches_stepped() const { return stepped_; }
  int64_t branches_carried() const { return carried_; }
  int64_t branches_derived() const;
  // Tests: whether settled finest levels become derived (on by default, off where the
  // environment has BOREAS_TREE_DERIVATION=0; off, they are carried as before and the
  // derived ones are carried again from the next step).
  void set_derivation(bool on);
  // Tests: every derived branch written as tree_step.cl's carry with hold 1 writes it (into
  // both halves, over its marks), what a reader derives must equal; it is derived again
  // from the next step.
  void carry_derived_branches(const PlantWind& wind);
  // Tests: whether readers pose derived branches first (cl/tree_derive.cl; on by default);
  // off, the deformer and leaf records derive each branch lane by lane.
  void set_posing(bool on) { posing_ = on; }
  // Branches that broke in the last committed step (cl/tree_step.cl counts them).
  int64_t branches_broken() const { return broken_; }

  // Puts a tree back at rest, unbent and whole: its broken branches mended.
  void heal(uint64_t key);

  // Enqueues one step of every branch into the next state, pushed out of the colliders
  // (tree_batch_contacts.cpp). Nothing is visible until commit(); without it (a failure),
  // the batch stays as it was.
  void enqueue_step(double dt, const PlantWind& wind, const StepColliders& colliders,
                    TreeStepEvents* events = nullptr);
  void commit();
  // Adds what the branches pushed each collider with in the last committed step to sums
  // (indexed in that step's collider order), summed in a fixed order: blocking.
  void add_contacts(std::vector<ContactSum>* sums);
  // Trees some collider met in the last enqueued step (stepped at full detail).
  int64_t trees_touched() const { return int64_t(pending_.touches.size()); }

  // Blocking readbacks of one tree (as of the last commit): its ranges only; the leaves
  // made from its branches now.
  std::vector<boreas_branch> branches(uint64_t key, const Origin& output_origin = {});
  std::vector<boreas_leaf> leaves(uint64_t key, const Origin& output_origin = {});
  // Enqueues one tree's branch records (cl/export_records.cl) or leaf records (made by
  // cl/tree_leaves.cl) into out from record first_record; out must hold them (boreas_cl.h).
  void enqueue_branch_records(uint64_t key, const cl::Buffer& out, size_t first_record,
                              const Origin& output_origin = {});
  void enqueue_leaf_records(uint64_t key, const cl::Buffer& out, size_t first_record,
                            const Origin& output_origin = {});
  // The same records for some of the tree's leaves alone: those in `runs` (first leaf,
  // count pairs, ascending and apart), each written where enqueue_leaf_records writes it,
  // with the same bits; others nearby may be written too (tiles are made whole). For the
  // ray structure, which places only the leaves of the branches its rays reach.
  void enqueue_leaf_runs(uint64_t key, const cl::Buffer& out, size_t first_record,
                         const std::vector<int32_t>& runs, const Origin& output_origin = {});
  // The deformed mesh of one tree (vertices), with indices built on the host.
  void mesh(uint64_t key, std::vector<boreas_vertex>* vertices, std::vector<uint32_t>* indices,
            const Origin& output_origin = {});

  // tree_batch_view.cpp: a view's records of every tree of the batch (boreas_cl.h,
  // boreas_world_enqueue_tree_records; cl/shared/tree_records.h): the cull and offset
  // launches, then one launch of each record kernel over the batch's record tiles. The
  // view's first_batch says whether the counts start at 0 or after an earlier batch's.
  struct RecordOutputs {
    cl::Buffer branches, leaves, impostors, ranges, indirect;
  };
  void enqueue_view_records(const BoreasRecordView& view, const RecordOutputs& out,
                            const Origin& output_origin = {});
  // The tree's id, for the range records (the world sets it once the tree is in its table).
  void set_tree_id(uint64_t key, uint32_t index, uint32_t generation);
  // The tree's template as boreas_tree_get_template numbers it: its index among the batch's
  // template blocks, times 2, plus 1 in exact mode (the world's two batches never share one).
  int template_number(uint64_t key) const { return template_number(slot_of(key)); }
  // The tree's base (a float: a def's position is one): its state's positions are relative
  // to it (cl/shared/tree_origin.h), so a reader of the state planes adds it.
  std::array<float, 3> base_of(uint64_t key) const { return offset_of(slot_of(key), {}); }

  // For benchmarks and tests. One tree's state or motion planes (stride: its entry count).
  std::vector<float> read_tree_state(uint64_t key);
  std::vector<float> read_tree_motion(uint64_t key);
  // The first `count` entries of every state plane (stride count): a batch built by one
  // add() holds its trees' states as tree_layout lays them out (benchmarks).
  std::vector<float> read_state_prefix(int64_t count);
  // Index of branch b of a tree in the state planes, and those planes' stride.
  int32_t branch_index(uint64_t key, int b) const;
  int stride() const { return int(entries_.capacity); }
  // The smallest capacities of its spaces (the trees' entries; the templates' entries and
  // leaves): a batch's first buffers, and where shrinking stops (runtime/block_space.h).
  static constexpr int64_t kMinEntries = 256, kMinTemplateEntries = 256, kMinTemplateLeaves = 1024;
  const cl::Buffer& state_buffer() const { return state_[current_]; }
  // What a reader of the state needs besides it (cl/shared/tree_state.h, boreas_tree_pose:
  // a derived branch's F and broken flag, its template's shape) and the shape's stride.
  const cl::Buffer& motion_buffer() const { return motion_[current_]; }
  // The motion buffers' planes: all of them where the batch holds a damped template's
  // planes (its dF/dt and response), the still ones until it does (cl/shared/tree_types.h;
  // a quasi-static branch's dF/dt and response are 0, 24 and 32 bytes an entry not held).
  int motion_planes() const { return motion_planes_; }
  const cl::Buffer& shape_buffer() const { return shape_; }
  int static_stride() const { return int(static_entries_.capacity); }
  // The settled space (cl/shared/tree_types.h, BOREAS_TREE_SETTLED_*): a reader's entry
  // index past stride() is an entry there. With none held, any buffer (the shape planes)
  // and stride 0: no reader's index passes stride() then.
  const cl::Buffer& settled_buffer() const { return settled_entries_.capacity > 0 ? settled_ : shape_; }
  int settled_stride() const { return int(settled_entries_.capacity); }
  // The posed scratch (tree_batch_posed.cpp): with none, any buffer (the settled buffer)
  // and stride 0 (no settled entry is posed then).
  const cl::Buffer& posed_buffer() const { return posed_rows_ > 0 ? posed_planes_ : settled_buffer(); }
  int posed_stride() const { return int(posed_rows_); }
  // Tests: the rows of the posed scratch (0: none held) and the settled entries the last
  // view call's cull asked to pose (read back by the next view call; call finish first).
  int64_t posed_rows() const { return posed_rows_; }
  int64_t posed_asked() {
    take_posed_count();
    return posed_asked_;
  }
  // What the view's per-call tables are built from (tree_batch_view.cpp): moves whenever a
  // tree's view row is written (a tree added, removed, settled, woken, or blocks moved).
  uint64_t view_generation() const { return view_generation_; }
  const cl::Buffer& radius_buffer() const { return radius_; }
  // tree_batch_settled.cpp. Tests of the readers' settled form, the settled space's first
  // use (its own space per tree is bench/RESULTS.md's "Issue 39, fourth round: compact2"):
  // every derived range's inputs copied into a new settled space, one range after another
  // from entry 1, its own entries left as they are; where each went.
  struct SettledRange {
    int32_t own_first = 0;      // the range's first entry in the trees' own planes
    int32_t settled_first = 0;  // ... and in the settled space
    int32_t count = 0;
    int32_t static_first = 0;  // its first template entry
    float scale = 1.0f;        // its tree's
  };
  // Until the next step or blocks moving, every reader (records, the view's records, the
  // mesh, the getters, rays' refit) then reads those ranges from the settled space; the
  // marks and motion stay in the own planes (a step reads and writes them as before).
  std::vector<SettledRange> copy_derived_to_settled();
  // Where a tree's branches are read from: branches [0, own) at branch_index(key, 0) + b,
  // the rest at settled_entry + b - own (own = its branch count where none is settled).
  void settled_split(uint64_t key, int32_t* own, int32_t* settled_entry) const;
  // Settling (tree_batch_settled.cpp): a derived finest level that no collider touches
  // moves into the settled space and its own entries are released (the tail of its
  // block); it comes back, bit for bit as it left, before anything steps, heals or
  // carries it. On by default; off where the environment has BOREAS_TREE_SETTLING=0
  // (benchmarks' A/B) or for tests' twins: settled trees come back at the next step.
  void set_settling(bool on) { settling_ = on; }
  int64_t branches_settled() const;  // derived branches held in the settled space now
  // Tests: the most entries add() stages on the host at once (its rest poses and settled
  // inputs are uploaded in pieces of at most this many entries, whatever the add's size).
  void set_add_piece(int64_t entries) { add_piece_ = std::max<int64_t>(1, entries); }
  // Entries of the trees' own planes and of the settled space (capacity, the live ones and
  // the sink): what their buffers hold and what of it is used.
  int64_t own_capacity() const { return entries_.capacity; }
  int64_t own_used() const { return entries_.used(); }
  int64_t settled_used() const { return settled_entries_.used(); }
  // tree_batch_room.cpp: the capacities of its spaces (own, settled, template entries and
  // leaves), and the spaces moved back into buffers of such capacities (packed; a space
  // of capacity 0 holds no buffer, as in a new batch). The world's add in pieces
  // (World::add_trees) takes a refused add's earlier pieces out and gives the batch back
  // the room it had before the add: its counted device memory as it was.
  struct Room {
    int64_t own = 0, settled = 0, template_entries = 0, template_leaves = 0;
    bool operator==(const Room& o) const {
      return own == o.own && settled == o.settled && template_entries == o.template_entries &&
             template_leaves == o.template_leaves;
    }
  };
  Room room() const;
  // The live entries must fit: a room taken before trees were added, those trees removed.
  void restore_room(const Room& room);
  // Each space whose capacity is no longer the room's, and passes its live entries by more
  // than a quarter, moved into buffers that just hold them (not below its minimum): an add
  // made in pieces may have grown the spaces by doubling, where one add grows them once to
  // what it needs.
  void fit_room(const Room& before);
  // The live entries of each space (a Room of them), and each space grown (packed) to at
  // least want's capacity within the chunk's limits: the rest of a pieced add's room made
  // at once, from what its first piece took, rather than by doubling piece after piece.
  Room used_room() const;
  void reserve_room(const Room& want);
  // Builds the kernels with 64-bit plane offsets whatever the size (tests of that path).
  void force_wide_planes(bool wide) { wide_planes_ = wide; }

 private:
  using Space = BlockSpace;
  // A template block on the device, shared by its trees.
  struct Template {
    std::string key;
    std::shared_ptr<const TreeTemplateBlock> block;  // host copy: rest pose, frequencies
    int32_t first = 0;                               // static entries
    int64_t leaf_first = 0;
    int64_t users = 0;
    int32_t number = 0;  // in numbers_ (template_number)
  };
  struct Slot {
    std::shared_ptr<const TreeInstance> tree;
    int32_t template_index = 0;
    int32_t first = 0;  // the root's entry
    int32_t count = 0;  // root + branches
    int32_t leaf_count = 0;
    TreeLod lod = TreeLod::kFull;
    bool frozen = false;                    // settled and no longer launched
    double settle_left = 0.0;               // s of whole-tree carrying before it freezes
    double resume_left = 0.0;               // s of easing into the wind
    float hold = 0.0f;                      // the resume blend its tiles carry
    std::vector<TileLists::Segment> tiles;  // where its tiles are
    TileLists::Segment record_tiles[2];     // its branch and leaf record tiles
    double reach = 0.0;     // m: no branch of it reaches farther from its base
    bool touching = false;  // a collider meets its reach in the step being enqueued
    bool touched = false;   // ... in the last committed step (its contact planes are live)
    bool pushed = false;    // a collider pushed one of its branches in the last committed step
    bool derived = false;             // its finest level is derived (tree_state.h)
    TileLists::Segment derive_tiles;  // ... and where its tiles are (cl/tree_derive.cl)
    double derive_left = kSettleTime;  // s its finest level is still carried before that
    int32_t settled_first = -1;  // its derived range's first settled entry, or -1 (none)
  };
  // A tree that colliders touch in one step: its slot, the colliders (step order) and its
  // first record row (cl/shared/tree_types.h).
  struct Touch {
    int32_t slot = 0;
    int32_t entries = 0;  // its root and branches
    std::vector<int32_t> colliders;
    int64_t record = 0;
  };
  // One step's contact launch: the trees and the records they wrote.
  struct Contacts {
    std::vector<Touch> touches;
    int64_t rows = 0;
    cl::Buffer records;
    std::vector<int32_t> flags;  // the touches as the launch left them (read back, no wait)
  };

  // tree_batch.cpp: which trees and templates the batch holds.
  const Slot& slot_of(uint64_t key) const;
  const Template& template_of(const Slot& slot) const {
    return templates_[size_t(slot.template_index)];
  }
  // The key of a tree's template block: its model and the physics the block holds.
  static std::string template_block_key(const TreeInstance& tree);
  // add()'s steps. Those up to write_new_states change nothing of the batch but device
  // memory past its used ends (a relayout moves blocks into bigger buffers, contents and
  // all); take_new_templates and take_tree make the new trees the batch's.
  struct NewTrees;
  void check_new_keys(const Trees& trees) const;
  NewTrees find_templates(const Trees& trees) const;
  void count_entries(const Trees& trees, NewTrees& n) const;
  void make_room(NewTrees& n);
  // Tree t's template block: a known one, or one that write_new_templates made.
  const TreeTemplateBlock& block_of(const NewTrees& n, size_t t) const;
  void write_new_templates(const Trees& trees, NewTrees& n);
  void write_new_response(const NewTrees& n);
  void write_new_states(const Trees& trees, NewTrees& n);
  std::vector<int32_t> take_new_templates(const NewTrees& n);  // their indices
  void take_tree(const std::shared_ptr<const TreeInstance>& tree, int32_t template_index,
                 int64_t first, const TreeTemplateBlock& block, int64_t settled_first = -1);
  // A kept template's rest state (trees/tree_layout.h, rest_state), from its block's planes
  // on the device: blocking.
  std::vector<float> template_rest(const Template& tp);
  // tree_batch_settled_add.cpp: settling at add. A tree whose finest level its level of
  // detail derives (the focus set before the add) takes it straight into the settled
  // space, as settle() would leave it after kSettleTime of carrying from rest (F, dF/dt and
  // the broken flag 0: a carry from rest keeps them 0, bit for bit), and never holds it in
  // the own planes. plan_settling decides it per tree and makes the settled room first
  // (where that is refused, every tree is added whole to the own planes, as before);
  // write_new_settled writes their settled entries past the space's used end.
  bool settles_at_add(const TreeInstance& tree) const;
  void plan_settling(const Trees& trees, NewTrees& n);
  void write_new_settled(const Trees& trees, const NewTrees& n);
  // Room for `need` more settled entries (grown, and with the batch's settled planes), the
  // own planes' stride then being own_capacity; false where it is refused (the batch as it
  // was). Settling is only memory: a caller that is refused keeps the entries own.
  bool settled_room(int64_t need, int64_t own_capacity);

  // tree_batch_layout.cpp: the blocks' buffers.
  // Moves the trees' own planes (state and motion) or the template blocks into buffers of
  // these capacities, packed or at the same indices; all new buffers are made before
  // anything changes.
  // whole: settled slots coming back (unsettle), laid out with their whole blocks (only
  // their own entries copied); with pack only.
  void relayout_trees(int64_t capacity, bool pack, const std::vector<int32_t>* whole = nullptr);
  void relayout_templates(int64_t capacity, int64_t leaf_capacity, bool pack);
  // relayout_trees' plan with the whole blocks of these slots.
  void lay_whole_blocks(const std::vector<int32_t>& whole, BlockPlan* plan) const;
  // relayout_templates' steps: new buffers for c entries and lc leaves; the sink written
  // into them (a new batch), or every template block moved into them.
  struct TemplateBuffers;
  TemplateBuffers template_buffers(size_t c, size_t lc);
  void write_template_sink(const TemplateBuffers& b, size_t c, size_t lc);
  void copy_template_blocks(TemplateBuffers& b, const BlockPlan& plan, const BlockPlan& leaf_plan,
                            size_t c, size_t lc);
  // The most entries each space may hold: its widest buffer (state planes, template shape
  // planes, leaf planes) within Runtime::max_allocation, and every index within int.
  struct SpaceLimits {
    int64_t entries, template_entries, template_leaves;
  };
  SpaceLimits space_limits() const;
  // Whether some plane passes 2^31 floats (or wide planes were asked for): 64-bit offsets.
  bool uses_wide_planes() const;
  // The kernels' #defines for this batch's size (BOREAS_WIDE_PLANES past 2^31 floats, and
  // then width 1).
  std::string plane_defines() const;
  // Branches per work-item of the step, vertices of the deformer, leaves of the leaf
  // records (cl/shared/simd_width.h): the device's SIMD width, or 1 with 64-bit offsets.
  int step_width() const;

  // tree_batch_lod.cpp: levels of detail and the tiles they decide.
  // The level of detail of a tree for the focus points.
  TreeLod lod_of(const TreeParams& params) const;
  // Levels of detail and blends for this step: re-tiles the trees whose launches change.
  void update_lods(double dt);
  // A slot's level of detail for the focus points now, or its settling when frozen;
  // whether its tiles change.
  bool change_lod(Slot& slot, double dt);
  // A slot's state and motion copied into the next half of the ping-pong planes.
  void copy_to_next_state(const Slot& slot);
  // Whether a slot's finest level becomes derived or stepped again this step (then its
  // tiles change); its marks (cl/shared/tree_state.h) in both halves of the state; every
  // derived slot's again (blocks moved: the marks name entries).
  bool update_derivation(Slot& slot, double dt);
  void write_derived_marks(const Slot& slot);
  // tree_batch_settled.cpp: a slot's local index where its settled entries begin (its
  // block's count where none is), and the reader entry its local indices count from there.
  int32_t settled_begin(const Slot& slot) const;
  int32_t settled_root(const Slot& slot) const;
  // The settled space let go where it holds copy_derived_to_settled's copies (of one
  // step's state, its parents' entries of one layout): every reader reads the own planes
  // again. Settled trees' entries are their only copy and stay.
  void drop_settled();
  // The own planes' entries a slot holds: its block's count, or up to its settled entries.
  int32_t own_count(const Slot& slot) const;
  // Settling and coming back (tree_batch_settled.cpp). settle_slots: every derived slot
  // that may settle moves its finest level to the settled space (a failed allocation
  // leaves them derived in their own planes, as before). unsettle: the slots' own blocks
  // whole again (allocated first: on a failure nothing has changed), their marks, F, the
  // broken flag and dF/dt written back into both halves, their settled entries released.
  void settle_slots();
  void settle(Slot& slot);
  void unsettle(const std::vector<int32_t>& slots);
  // The settled slots a step would step or touch (level of detail, collider, derivation
  // off): brought back by update_lods before anything else changes.
  std::vector<int32_t> slots_to_unsettle() const;
  // The settled space's buffer moved into one of capacity entries (packed or in place) and
  // planes planes (its rate planes zero where new); made before anything changes.
  void relayout_settled(int64_t capacity, bool pack, int planes);
  int settled_planes() const { return holds_rates() ? BOREAS_TREE_SETTLED_RATE_PLANES : BOREAS_TREE_SETTLED_PLANES; }
  // A settled slot's inputs (parent entry, template entry, scale) written again.
  void write_settled_inputs(const Slot& slot);
  // Packs or shrinks the settled space after releases (runtime/block_space.h's rule);
  // lets its buffer go when it is empty.
  void trim_settled();
  // A slot's record tiles and view row made again (its settled split or block moved).
  void rerecord_tree(int32_t slot);
  // A derived slot's marks (planes 0..3 of tree_state.h's form, stride: the range's count)
  // and where its range starts (in its block); `settled`: for the settled space (a parent
  // in the same level named relative to its child, derived_inputs).
  std::vector<float> derived_marks(const Slot& slot, int32_t* begin, bool settled) const;
  // Planes 1..3 of those marks (the settled space's inputs: parent entry, template entry,
  // scale) of a tree of model m whose derived level is `level`, its root at `root` and its
  // template block at `static_first`: into out (stride `stride`) from `at`. A split piece's
  // parent in the same level: its own entry in the own planes (marks), or with `settled`
  // -d, the settled entry d before it (cl/shared/tree_types.h, BOREAS_TREE_SETTLED_PARENT).
  static void derived_inputs(const TreeModel& m, int level, int32_t root, int32_t static_first,
                             float scale, float* out, size_t stride, size_t at, bool settled);
  void rewrite_derived_marks();
  // cl/tree_derive.cl: a slot's tiles of its derived range (added, or turned into no-ops);
  // the poses of the derived branches of tiles [first, first + count) written over their
  // marks in the current half (with use_table, of the trees the out table draws), for the
  // readers of many items a branch; every posed branch's marks written back before the
  // next step (the poses are of the current state only).
  void tile_derived(Slot& slot);
  void untile_derived(Slot& slot);
  // tree_batch_derived_tiers.cpp: the slot's finest level's tiles, one list a step tier
  // in tier order from list 0 (each tile's object `object`); the lists used.
  int add_derived_tier_tiles(TileLists& tiles, const Slot& slot, int32_t object) const;
  // A slot's derived level, leaving derivation, posed over its marks in the current half.
  void write_derived_poses(const Slot& slot);
  void pose_derived(int32_t first, int32_t count, bool use_table);
  void mark_posed();
  TreeTileSource tile_source(const Slot& slot) const;
  // A slot's tiles: added (for its level of detail and blend), or turned into no-ops.
  void tile(Slot& slot);
  void untile(Slot& slot);
  // Every tile list anew (after blocks moved, or when dead tiles pile up).
  void rebuild_tiles();

  // tree_batch_step.cpp: the damped template blocks' response for a new dt.
  void upload_response(double dt);
  // tree_batch_layout.cpp: the planes of a damped template (dF/dt in the motion buffers,
  // the response planes, zero) made before the first one comes: all new buffers made
  // before the batch takes them. Whether it has them; tree_step.cl's defines for them, and
  // its response argument (none read without them).
  void hold_rates();
  // ... and let go once the last damped template has gone (the quasi-static branches'
  // dF/dt is 0: new motion buffers with the still planes).
  void release_rates();
  bool holds_rates() const { return motion_planes_ == BOREAS_TREE_MOTION_PLANES; }
  std::string step_defines(const PlantWind& wind) const;
  const cl::Buffer& response_planes() const { return holds_rates() ? response_ : shape_; }

  // tree_batch_contacts.cpp: the trees whose reach the colliders' swept bounds meet (their
  // slots marked touching, so update_lods steps them at full detail); their contact
  // launch's buffers and tiles; its launch after a step list.
  void find_touches(const StepColliders& colliders);
  void prepare_contacts(const StepColliders& colliders);
  // The template blocks' children planes, which only the contact launch reads: none until a
  // collider first touches a tree of the batch (16 bytes a template entry), then every
  // block's made from its parents on the device (trees/tree_layout.h, tree_children), and
  // new blocks' written with them from then on.
  void make_children();
  cl::Kernel& contact_kernel(const std::string& defines);  // tree_step.cl's contact variant
  void enqueue_contacts(cl::Kernel& k, const PlantWind& wind, const cl::Buffer& parent_state,
                        int list, TreeStepEvents* events);

  // tree_batch_origin.cpp (issue 40, cl/shared/tree_origin.h): a slot's row of the step's
  // places and the readers' offsets; the places for this step's wind (every slot's base
  // and its waves' phases there, in double), uploaded; the readers' offsets for an output
  // origin, uploaded where they changed; one slot's offset as the host adds it; a
  // collider relative to a slot's base.
  int32_t place_row(const Slot& slot) const { return int32_t(&slot - slots_.data()) + 1; }
  void upload_places(const PlantWind& wind);
  // (nullptr: zeros, the state's own coordinates relative to each base); with `only`, that
  // slot's row alone is brought up to date (a one-tree call reads no other).
  const cl::Buffer& reader_offsets(const Origin* output_origin, const Slot* only = nullptr);
  static std::array<float, 3> offset_of(const Slot& slot, const Origin& output_origin);
  static BoreasGpuCollider relative_collider(BoreasGpuCollider c,
                                             const std::array<double, 3>& center,
                                             const Slot& slot);

  // tree_batch_readback.cpp: one tree's entries of `planes` planes of a per-entry buffer
  // (stride: its entry count).
  std::vector<float> read_tree_planes(const cl::Buffer& buffer, uint64_t key, int planes);

  // tree_batch_records.cpp: enqueues the making of one tree's leaf records into out from
  // record first_record (negative: the records before it are not written, see
  // read_leaf_records).
  void enqueue_leaves(const Slot& slot, const cl::Buffer& out, int64_t first_record);
  // What a launch over one tree's leaf tiles needs first (its derived branches posed, the
  // tiles laid), and where its tiles are then.
  const TileLists::Segment& prepare_leaves(const Slot& slot);
  // tree_batch_posed.cpp (cl/tree_derive_settled.cl): settled branches posed for the
  // deformer and leaf records (and the view's branch records, which then read rather
  // than derive): one's (one tree's reads) or the view's drawn trees', into
  // the posed scratch, their scales marked; unpose_settled (right after the reading launch,
  // before anything else reads or moves the settled planes) writes the scales back.
  void pose_settled(const Slot* one);
  void unpose_settled();
  void add_settled_pose_tiles(const Slot& slot, std::vector<int32_t>* ints, int64_t* asked) const;
  void fit_posed_planes(int64_t need);
  void launch_settled_poses(bool use_table, int restore);
  void upload_posed_tiles(const std::vector<int32_t>& ints, bool view);  // view: view_pose_tiles
  // tree_batch_view.cpp: the view's posed tiles (every settled tree's), walked again only
  // when view_generation_ moved; the last view call's count of drawn settled entries taken
  // where its read has landed, without a wait (false: still in flight).
  const std::vector<int32_t>& view_pose_tiles(int64_t* asked);
  bool take_posed_count();
  void read_posed_count();
  // tree_batch_readback.cpp: one tree's leaf records made on the device and read into
  // `records`, through scratch buffers of at most the device's largest allocation.
  void read_leaf_records(const Slot& slot, std::vector<float>* records);
  // The record kernels over tiles [tile_first, tile_first + tiles) of their list: one
  // tree's (one_tree, from out_first) or the view's (where the out table says).
  void launch_branch_records(int32_t tile_first, int32_t tiles, bool one_tree,
                             const cl::Buffer& out, size_t out_first);
  void launch_leaf_records(int32_t tile_first, int32_t tiles, bool one_tree,
                           const cl::Buffer& out, int64_t out_first);
  // The leaf kernel over tiles [tile_first, tile_first + tiles) of another list (one tree's).
  void launch_leaf_tiles(const cl::Buffer& list, int32_t tile_first, int32_t tiles, bool one_tree,
                         const cl::Buffer& out, int64_t out_first);

  // tree_batch_view.cpp: the record tiles and view table (kept as trees come and go, all
  // anew after blocks moved), and their upload before a launch reads them.
  void record_tree(int32_t slot);
  void unrecord_tree(int32_t slot);
  void refresh_records();
  BoreasTreeView tree_view(int32_t slot) const;
  void write_view(int32_t slot, const BoreasTreeView& view);  // its row, marked for upload
  int template_number(const Slot& slot) const {
    return 2 * template_of(slot).number + (mode_ == BOREAS_TREE_EXACT ? 1 : 0);
  }

  Runtime& runtime_;
  boreas_tree_mode mode_;
  std::shared_ptr<TemplateNumbers> numbers_;
  std::vector<Slot> slots_;  // by slot index; freed ones have no tree
  std::vector<int32_t> free_slots_;
  std::unordered_map<uint64_t, int32_t> by_key_;
  std::vector<Template> templates_;  // by index; freed ones have no block
  std::vector<int32_t> free_templates_;
  std::unordered_map<std::string, int32_t> template_by_key_;
  int64_t branch_count_ = 0, leaf_count_ = 0;
  Space entries_;                         // the trees' own planes
  Space static_entries_, static_leaves_;  // the template blocks
  Space settled_entries_;                 // the settled space (capacity 0: none held)
  double response_dt_ = -1.0;             // dt the device's response planes were made for
  int current_ = 0;
  uint64_t step_index_ = 0;  // steps committed, for the leaves' rates
  std::vector<double> focus_;
  bool rebuild_tiles_ = false;  // blocks moved: every tile list anew before the next launch
  TileLists tiles_{kTreeListCount};
  double hold_dt_ = -1.0;  // the dt the resume blends' h was computed for
  int64_t stepped_ = 0, carried_ = 0;
  bool derivation_ = true;  // set_derivation
  TileLists derive_tiles_{1};
  cl::Buffer posed_;  // an int per view-table row: its derived branches are posed
  size_t posed_capacity_ = 0;
  bool any_posed_ = false;
  bool posing_ = true;  // set_posing
  cl::Buffer posed_planes_;  // the posed scratch: 15 planes, stride posed_rows_
  int64_t posed_rows_ = 0;
  cl::Buffer posed_counter_, posed_tiles_;  // rows asked for; the last pose's tiles
  size_t posed_tile_count_ = 0;
  std::vector<int32_t> posed_tile_ints_;  // what posed_tiles_ holds (upload_posed_tiles)
  size_t posed_tile_capacity_ = 0;        // its ints
  bool posed_live_ = false;  // scales marked: unpose_settled owed
  cl_int posed_asked_ = 0;   // the last view call's count, as last taken ...
  cl_int posed_count_read_ = 0;  // ... from here, where posed_counted_ reads it
  cl::Event posed_counted_;
  // The per-call tables' generation (view_generation) and what was built at which: the
  // view's posed tiles, and the readers' offsets (for which origin; nullptr's zeros as
  // offsets_zero_). kNoGeneration: build anew.
  static constexpr uint64_t kNoGeneration = ~uint64_t(0);
  uint64_t view_generation_ = 0;
  uint64_t view_pose_generation_ = kNoGeneration;
  std::vector<int32_t> view_pose_ints_;
  int64_t view_pose_asked_ = 0;
  bool posed_tiles_hold_view_ = false;  // posed_tiles_ holds view_pose_ints_
  uint64_t offsets_generation_ = kNoGeneration;
  std::array<double, 3> offsets_origin_{};
  bool offsets_zero_ = false;
  bool settling_ = true;  // set_settling
  int64_t add_piece_ = int64_t(1) << 20;  // set_add_piece: 60 MB of rest poses
  bool settled_copy_ = false;  // the settled space holds copy_derived_to_settled's copies
  int settled_planes_ = BOREAS_TREE_SETTLED_PLANES;  // the settled buffer's planes
  // The step's break count: one int on the device, zeroed and read back by every step
  // (without a wait: the world finishes the step), taken by commit().
  cl::Buffer breaks_;
  int32_t breaks_read_ = 0;
  int64_t broken_ = 0;
  bool wide_planes_ = false;
  // The record tiles (kRecordBranchList, kRecordLeafList), a row per slot of the view
  // table and of the out table (cl/shared/tree_records.h), the ids of the range records.
  // records_stale_: blocks moved, every tile and row anew before the next record launch.
  static constexpr int kRecordBranchList = 0, kRecordLeafList = 1;
  TileLists record_tiles_{2};
  bool records_stale_ = false;
  std::vector<BoreasTreeView> views_;  // row 0 the sink (no tree), slot s at row s + 1
  std::vector<std::pair<uint32_t, uint32_t>> tree_ids_;  // by slot
  int32_t views_dirty_first_ = 0, views_dirty_end_ = 0;
  cl::Buffer views_buffer_, table_buffer_;
  size_t views_capacity_ = 0, table_capacity_ = 0;
  // The trees' own planes (motion_planes_ planes of motion).
  cl::Buffer state_[2], motion_[2];
  int motion_planes_ = BOREAS_TREE_MOTION_STILL_PLANES;
  // The template blocks' planes (children_ and response_ only where made: make_children,
  // hold_rates).
  cl::Buffer parents_, children_, shape_, response_, radius_;
  cl::Buffer settled_;  // BOREAS_TREE_SETTLED_PLANES planes, stride settled_entries_.capacity
  cl::Buffer leaves_;  // BOREAS_TREE_LEAF_PLANES int planes: packed (cl/shared/leaf_pack.h)
  // The step's places and the readers' offsets (tree_batch_origin.cpp).
  cl::Buffer places_, offsets_;
  size_t places_capacity_ = 0, offsets_capacity_ = 0;
  std::vector<float> places_host_;  // staging: written without a wait (upload_async)
  // Colliders: this step's touched trees and the last committed step's, the contact
  // launches' tiles, the contact planes (ping-pong with the state, allocated when a
  // collider first touches a tree; stale after a relayout moved the trees), the launch's
  // touched trees and colliders, and record buffers (one per ping-pong half).
  Contacts pending_, committed_;
  TileLists contact_tiles_{kTreeListCount};
  cl::Buffer contact_[2];
  int64_t contact_capacity_ = 0;
  bool contact_stale_ = false;
  cl::Buffer touches_buffer_, colliders_buffer_, record_buffers_[2];
  size_t touches_capacity_ = 0, colliders_capacity_ = 0, record_capacity_[2] = {0, 0};
};

}  // namespace boreas::impl
