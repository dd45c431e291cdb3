// boreas tests: a meadow placed a piece at a time (meadow.h, place_piece; the batch's add
// uploads it so, to bound the add's peak) is the meadow placed whole, to the bit: its
// planes, its tiles' levels of detail and every step after.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "underbrush_fixtures.h"
#include "underbrush/frame_pack.h"

namespace boreas {
namespace {

// The default mix (grass, clover and daisies, whose heads hang from stalks) on 3 m.
boreas_meadow_def mixed_meadow() {
  boreas_meadow_def d = boreas_default_meadow_def();
  d.center[0] = 40.0f;
  d.center[2] = -12.0f;
  d.size[0] = d.size[1] = 3.0f;
  d.density = 300.0f;
  d.seed = 11;
  return d;
}

template <typename T>
bool same_bits(const T* a, const T* b, size_t count) {
  return std::memcmp(a, b, count * sizeof(T)) == 0;
}

// Plane p of planes at stride n, components [first, first + count).
template <typename T>
const T* plane_at(const std::vector<T>& planes, size_t n, int p, int first) {
  return planes.data() + size_t(p) * n + size_t(first);
}

TEST(MeadowPieces, PiecesOfAnySizeAreTheMeadowPlacedWhole) {
  const impl::Meadow planted = impl::plant_meadow(impl::checked_meadow_def(mixed_meadow()));
  ASSERT_FALSE(planted.plantings.empty());
  ASSERT_TRUE(planted.frame.empty()) << "plant_meadow leaves its components as plantings";
  const impl::Meadow whole =
      impl::meadow_from_plantings(planted.params, planted.plantings, {}, planted.origin);
  ASSERT_EQ(whole.count, planted.count);
  const size_t n = size_t(whole.count);
  int children = 0;
  for (size_t c = 0; c < n; ++c)
    children += impl::parent_of(whole.index.data(), int(n), int(c)) != int(c) ? 1 : 0;
  ASSERT_GT(children, 0) << "the mix should hang parts from others (daisy heads)";

  for (size_t plantings_a_piece : {size_t(1), size_t(7), size_t(100)}) {
    impl::MeadowPiece piece;
    int first = 0;
    for (size_t p = 0; p < planted.plantings.size(); p += plantings_a_piece) {
      const size_t end = std::min(p + plantings_a_piece, planted.plantings.size());
      impl::place_piece(planted, p, end, first, &piece);
      ASSERT_EQ(piece.first, first);
      const size_t k = size_t(piece.count);
      for (int q = 0; q < BOREAS_UB_FRAME_PLANES; ++q)
        ASSERT_TRUE(same_bits(plane_at(piece.frame, k, q, 0), plane_at(whole.frame, n, q, first), k))
            << "frame plane " << q << ", piece at " << first << " of " << plantings_a_piece;
      for (int q = 0; q < BOREAS_UB_INDEX_PLANES; ++q)
        ASSERT_TRUE(same_bits(plane_at(piece.index, k, q, 0), plane_at(whole.index, n, q, first), k))
            << "index plane " << q << ", piece at " << first;
      for (int q = 0; q < BOREAS_UB_STATE_PLANES; ++q)
        ASSERT_TRUE(same_bits(plane_at(piece.rest_state, k, q, 0),
                              plane_at(whole.rest_state, n, q, first), k))
            << "rest state plane " << q << ", piece at " << first;
      first += piece.count;
    }
    EXPECT_EQ(first, whole.count);
  }
}

// A world's meadow, added from its def with the batch placing `piece` components at a time,
// or (piece 0) added placed whole.
struct PieceWorld {
  std::unique_ptr<impl::World> world = test::meadow_world(3.0f);
  boreas_meadow_id id{};
  explicit PieceWorld(int64_t piece) {
    const float focus[3] = {40.0f, 0.0f, -12.0f};
    world->set_focus(focus, 1);
    if (piece > 0) {
      world->underbrush().set_piece_components(piece);
      id = world->add_meadow(mixed_meadow());
    } else {
      impl::Meadow m = impl::plant_meadow(impl::checked_meadow_def(mixed_meadow()));
      impl::Meadow whole = impl::meadow_from_plantings(m.params, m.plantings, {}, m.origin);
      whole.terrain = std::move(m.terrain);
      id = world->add_meadow(std::move(whole));
    }
  }
  uint64_t key() { return world->meadow(id).key; }
};

TEST(MeadowPieces, AWorldAddedInPiecesStepsAsOneAddedWhole) {
  PieceWorld whole(0), pieces(300);
  const int n = pieces.world->underbrush().component_count();
  ASSERT_GT(n, 3 * 300) << "the meadow should take several pieces";
  ASSERT_EQ(n, whole.world->underbrush().component_count());
  const std::vector<float> frame = pieces.world->underbrush().read_meadow_frame(pieces.key());
  const std::vector<int32_t> index = pieces.world->underbrush().read_meadow_index(pieces.key());
  EXPECT_EQ(frame, whole.world->underbrush().read_meadow_frame(whole.key()));
  EXPECT_EQ(index, whole.world->underbrush().read_meadow_index(whole.key()));
  // The tiles' boxes, gathered piece by piece, give the same levels of detail and colliders'
  // reach: every step equal to the bit (the focus stands in the meadow, its far tiles slower).
  for (int s = 0; s < 40; ++s) {
    whole.world->step(1.0f / 60.0f);
    pieces.world->step(1.0f / 60.0f);
  }
  EXPECT_EQ(pieces.world->underbrush().components_by_rate(),
            whole.world->underbrush().components_by_rate());
  const std::vector<float> a = pieces.world->underbrush().read_meadow_state(pieces.key());
  const std::vector<float> b = whole.world->underbrush().read_meadow_state(whole.key());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(same_bits(a.data(), b.data(), a.size()));
  EXPECT_TRUE(pieces.world->meadow(pieces.id).meadow.plantings.empty())
      << "the plantings go once the meadow is on the device";
}

}  // namespace
}  // namespace boreas
