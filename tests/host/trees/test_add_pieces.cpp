// boreas tests: a world's add of trees in pieces (world_tree_pieces.cpp) — the templates
// grown a round at a time, each piece's trees handed to the batches and its models packed
// before the next is grown. The pieces give the bits of one piece; an add holds at most
// its piece of whole models (and a round) at once, whatever its count; and a template
// that will not grow in a later piece leaves the world as it was: its state, its counted
// device memory, and what the next add and steps give (a twin's bits).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "boreas/boreas.h"
#include "errors.h"
#include "support/test_support.h"
#include "trees/species.h"
#include "trees/tree_model.h"
#include "world.h"

namespace boreas {
namespace {

using test::make_world_with_wave;
using test::windy_wave;

constexpr float kDt = 1.0f / 60.0f;

// BOREAS_THREADS for one test (a round is 4 templates a thread), put back after it.
class Threads {
 public:
  explicit Threads(const char* value) {
    if (const char* old = std::getenv("BOREAS_THREADS")) old_ = old, had_ = true;
    setenv("BOREAS_THREADS", value, 1);
  }
  ~Threads() { had_ ? (void)setenv("BOREAS_THREADS", old_.c_str(), 1) : (void)unsetenv("BOREAS_THREADS"); }

 private:
  std::string old_;
  bool had_ = false;
};

// Aspens of distinct seeds from `seed` on a lattice (every fifth exact, every seventh a
// template another tree of the call has: the same seed as the tree before it).
std::vector<boreas_tree_def> distinct(int count, uint64_t seed, float z = 0.0f) {
  std::vector<boreas_tree_def> defs;
  for (int i = 0; i < count; ++i) {
    boreas_tree_def d = boreas_default_tree_def();
    d.seed = seed + uint64_t(i % 7 == 6 ? i - 1 : i);
    d.position[0] = float(i % 6) * 7.0f - 17.5f;
    d.position[2] = float(i / 6) * 7.0f - 10.0f + z;
    d.rotation = 0.41f * float(i);
    if (i % 5 == 2) d.mode = BOREAS_TREE_EXACT;
    defs.push_back(d);
  }
  return defs;
}

std::unique_ptr<impl::World> world_with(const std::vector<boreas_tree_def>& defs,
                                        size_t piece_bytes) {
  auto world = make_world_with_wave(windy_wave());
  world->set_add_piece_bytes(piece_bytes);
  world->add_trees(defs.data(), int(defs.size()));
  return world;
}

// What a whole aspen of this seed holds beyond its packed form (branches and leaves).
size_t whole_bytes(uint64_t seed) {
  static const impl::Species aspen =
      impl::parse_species_source(impl::read_species_source("quaking_aspen"));
  const impl::TreeModel m = impl::grow_tree(aspen, seed, 1.0);
  return m.branches.capacity() * sizeof(impl::BranchModel) +
         m.leaves.capacity() * sizeof(impl::LeafModel);
}

TEST(AddPieces, PiecesGiveTheBitsOfOnePiece) {
  const Threads one("1");  // rounds of 4 templates: this add grows 18 in 5 pieces
  const std::vector<boreas_tree_def> defs = distinct(21, 1);
  auto whole = world_with(defs, SIZE_MAX);
  auto pieces = world_with(defs, 1);
  ASSERT_EQ(pieces->tree_count(), defs.size());
  ASSERT_EQ(pieces->template_count(), whole->template_count());
  // One piece held every whole model; the pieces one round's at most (4 templates).
  std::vector<size_t> grown;
  for (size_t i = 0; i < defs.size(); ++i)
    if (i % 7 != 6) grown.push_back(whole_bytes(defs[i].seed));
  size_t all = 0, round = 0;
  for (size_t g = 0; g < grown.size(); g += 4) {
    size_t r = 0;
    for (size_t k = g; k < std::min(grown.size(), g + 4); ++k) r += grown[k];
    all += r;
    round = std::max(round, r);
  }
  EXPECT_EQ(whole->add_peak_whole_bytes(), all);
  EXPECT_EQ(pieces->add_peak_whole_bytes(), round);
  EXPECT_EQ(pieces->state_hash(), whole->state_hash());
  for (int s = 0; s < 20; ++s) {
    whole->step(kDt);
    pieces->step(kDt);
    ASSERT_EQ(pieces->state_hash(), whole->state_hash()) << "step " << s;
  }
}

TEST(AddPieces, AnAddHoldsAtMostItsPieceOfWholeModels) {
  const Threads two("2");  // rounds of 8 templates
  const std::vector<boreas_tree_def> defs = distinct(30, 40);
  size_t largest = 0;
  for (const boreas_tree_def& d : defs) largest = std::max(largest, whole_bytes(d.seed));
  const size_t piece = 10 * largest;
  auto world = world_with(defs, piece);
  EXPECT_GT(world->add_peak_whole_bytes(), piece / 2);
  EXPECT_LE(world->add_peak_whole_bytes(), piece + 8 * largest);
  EXPECT_EQ(world->tree_count(), defs.size());
}

// A species whose trees are refused as they grow (Arbaro's splits without a split
// angle: the clones would grow inside their stem), written to a file for a def to name.
std::string refused_species() {
  const std::string path = ::testing::TempDir() + "add_pieces_refused.json";
  std::ofstream(path) << R"({"format": "boreas-species-1", "name": "refused", )"
                      << R"("params": {"Levels": 3, "1SegSplits": 0.2}})";
  return path;
}

// The world's state, trees, templates, chunks and counted device memory.
struct Seen {
  uint64_t hash, memory;
  size_t trees, templates, chunks;
  bool operator==(const Seen& o) const {
    return hash == o.hash && memory == o.memory && trees == o.trees && templates == o.templates &&
           chunks == o.chunks;
  }
};
Seen seen(impl::World& w) {
  return {w.state_hash(), w.runtime().memory_in_use(), w.tree_count(), w.template_count(),
          w.tree_chunks(BOREAS_TREE_LAGGED).size() + w.tree_chunks(BOREAS_TREE_EXACT).size()};
}

void refused_in_a_later_piece(const std::vector<boreas_tree_def>& before) {
  const Threads one("1");
  auto world = make_world_with_wave(windy_wave());
  auto twin = make_world_with_wave(windy_wave());
  for (auto* w : {world.get(), twin.get()}) {
    if (!before.empty()) w->add_trees(before.data(), int(before.size()));
    for (int s = 0; s < 5; ++s) w->step(kDt);
    w->set_add_piece_bytes(1);  // a piece a round: 4 templates
  }
  const Seen was = seen(*world);
  std::vector<boreas_tree_def> defs = distinct(24, 100, 30.0f);
  const std::string refused = refused_species();
  defs[22].species = refused.c_str();  // its template the 20th grown: pieces 0-3 added first
  try {
    world->add_trees(defs.data(), int(defs.size()));
    FAIL() << "a tree that cannot grow was added";
  } catch (const impl::Error& e) {
    EXPECT_EQ(e.status(), BOREAS_ERROR_INVALID_ARGUMENT) << e.what();
    EXPECT_NE(std::string(e.what()).find("defs[22]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("SplitAngle"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(seen(*world) == was) << "memory " << seen(*world).memory << " was " << was.memory;
  // The same add without it, and steps: the bits and memory of a world that never saw the
  // refusal.
  defs.erase(defs.begin() + 22);
  for (auto* w : {world.get(), twin.get()}) w->add_trees(defs.data(), int(defs.size()));
  for (int s = 0; s < 10; ++s) {
    ASSERT_EQ(world->state_hash(), twin->state_hash()) << "step " << s;
    world->step(kDt);
    twin->step(kDt);
  }
  EXPECT_EQ(world->runtime().memory_in_use(), twin->runtime().memory_in_use());
}

TEST(AddPieces, ATreeRefusedInALaterPieceLeavesTheWorldAsItWas) {
  refused_in_a_later_piece(distinct(9, 500));
}

TEST(AddPieces, ATreeRefusedInALaterPieceLeavesAnEmptyWorldAsItWas) {
  refused_in_a_later_piece({});
}

}  // namespace
}  // namespace boreas
