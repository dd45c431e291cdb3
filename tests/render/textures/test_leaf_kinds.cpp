// Texture generator tests: the built-in leaf kinds (render/textures/leaf_kinds.h): each is
// drawn from its row of the shared outline table, the outlines have what their species'
// leaves have (the oak's deep sinuses, the tupelo's entire margin, the aspen widest nearer
// its base than the tupelo, the willow narrower than the broadleaf), the optics order their
// greens, and add_leaf_kinds adds what is missing and names what is not a kind.
#include "textures/leaf_kinds.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "textures/leaf_shape.h"
#include "textures/texture_error.h"
#include "textures/texture_files.h"

namespace boreas::render {
namespace {

const LeafKind& kind(const std::string& name) {
  static const std::vector<LeafKind> kinds = leaf_kinds();
  auto k =
      std::find_if(kinds.begin(), kinds.end(), [&](const LeafKind& x) { return x.name == name; });
  if (k == kinds.end()) throw std::runtime_error("no kind " + name);
  return *k;
}

// The blade's width per texel row (fraction of the row covered), rows along v.
std::vector<double> row_widths(const LeafShape& shape, int size = 256) {
  std::vector<float> coverage = leaf_coverage(shape, size, size);
  std::vector<double> rows(size_t(size), 0.0);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) rows[size_t(y)] += coverage[size_t(y) * size + x];
    rows[size_t(y)] /= size;
  }
  return rows;
}

struct Minima {
  int all = 0;   // local minima of the row width over the blade
  int deep = 0;  // those under 0.6 of the lower of the widest rows before and after them
};
Minima blade_minima(const std::vector<double>& rows) {
  const int n = int(rows.size()), y0 = int(0.2 * n), y1 = int(0.92 * n);
  Minima m;
  for (int y = y0 + 1; y < y1; ++y) {
    if (!(rows[y] < rows[y - 1] && rows[y] <= rows[y + 1])) continue;
    double before = *std::max_element(rows.begin() + y0, rows.begin() + y);
    double after = *std::max_element(rows.begin() + y + 1, rows.begin() + y1);
    ++m.all;
    m.deep += rows[y] < 0.6 * std::min(before, after);
  }
  return m;
}

double area(const std::vector<double>& rows) {
  double sum = 0.0;
  for (double r : rows) sum += r;
  return sum / double(rows.size());
}

double widest_v(const std::vector<double>& rows) {
  size_t at = size_t(std::max_element(rows.begin(), rows.end()) - rows.begin());
  return (double(at) + 0.5) / double(rows.size());
}

// Mean green albedo over the texels wholly on the leaf.
double mean_green(const LeafKind& k) {
  LeafTextureParams p = k.params;
  p.width = p.height = 64;
  LeafTextureSet set = generate_leaf_textures(p);
  double sum = 0.0;
  int n = 0;
  for (size_t i = 0; i < size_t(p.width) * size_t(p.height); ++i) {
    if (set.albedo[i * 4 + 3] < 1.0f) continue;
    sum += set.albedo[i * 4 + 1];
    ++n;
  }
  return n ? sum / n : 0.0;
}

TEST(LeafKinds, AreTheFiveKindsBroadleafFirst) {
  EXPECT_EQ(leaf_kind_names(),
            (std::vector<std::string>{"broadleaf", "aspen", "oak", "willow", "tupelo"}));
}

TEST(LeafKinds, EachIsItsOutlinesRow) {
  // The rays read boreas_leaf_outlines[kind] (cl/shared/leaf_outline.h); the texture layer of
  // kind k must be drawn from that row, and every kind shares the one layout (leaf.vert).
  const std::vector<LeafKind> kinds = leaf_kinds();
  ASSERT_EQ(int(kinds.size()), BOREAS_LEAF_OUTLINE_COUNT);
  for (int k = 0; k < BOREAS_LEAF_OUTLINE_COUNT; ++k) EXPECT_EQ(kinds[size_t(k)].params.shape.outline, k);
}

TEST(LeafKinds, TheOakAloneHasDeepSinusesAndTheTupeloAnEntireMargin) {
  // Measured at 256 rows: the oak's 3.5 lobes leave two sinuses cut below 0.6 of the lobes
  // on either side (the third, under the small terminal lobe, is shallower against it);
  // serrate margins make many shallow minima, the tupelo's none.
  Minima oak = blade_minima(row_widths(kind("oak").params.shape));
  EXPECT_GE(oak.deep, 2);
  for (const char* name : {"broadleaf", "aspen", "willow", "tupelo"}) {
    SCOPED_TRACE(name);
    Minima m = blade_minima(row_widths(kind(name).params.shape));
    EXPECT_EQ(m.deep, 0);
    if (std::string(name) == "tupelo") {
      EXPECT_EQ(m.all, 0);
    } else {
      EXPECT_GE(m.all, 5) << "a serrate margin";
    }
  }
}

TEST(LeafKinds, OutlinesDifferAsTheSpeciesLeavesDo) {
  std::vector<double> broadleaf = row_widths(kind("broadleaf").params.shape);
  std::vector<double> aspen = row_widths(kind("aspen").params.shape);
  std::vector<double> oak = row_widths(kind("oak").params.shape);
  std::vector<double> willow = row_widths(kind("willow").params.shape);
  std::vector<double> tupelo = row_widths(kind("tupelo").params.shape);
  // The aspen is nearly round (the fullest), the tupelo obovate (widest past the middle).
  EXPECT_GT(area(aspen), area(broadleaf));
  EXPECT_LT(widest_v(aspen), widest_v(tupelo));
  EXPECT_GT(widest_v(tupelo), 0.55);
  // Sinuses take area; the willow's long tip and tapering base too (its narrowness on the
  // tree comes from its species' LeafScaleX).
  EXPECT_LT(area(oak), 0.85 * area(broadleaf));
  EXPECT_LT(area(willow), area(broadleaf));
}

TEST(LeafKinds, OpticsOrderTheirGreens) {
  // A light yellow-green aspen, a darker oak, the darkest glossy tupelo.
  double broadleaf = mean_green(kind("broadleaf"));
  EXPECT_GT(mean_green(kind("aspen")), broadleaf);
  EXPECT_LT(mean_green(kind("oak")), broadleaf);
  EXPECT_LT(mean_green(kind("tupelo")), mean_green(kind("oak")));
}

TEST(LeafKinds, AddLeafKindsAddsWhatIsMissingOnce) {
  LeafTextureParams small;
  small.width = small.height = 32;
  BarkTextureParams bark;
  bark.width = bark.height = 16;
  TextureSet set = generate_texture_set(small, bark);
  add_leaf_kinds(set, {"broadleaf", "oak", "willow", "oak"}, small);
  ASSERT_EQ(set.kind_leaves.size(), 2u);  // broadleaf is the set's leaf; oak once
  EXPECT_EQ(set.kind_leaves[0].kind, "oak");
  EXPECT_EQ(set.kind_leaves[1].kind, "willow");
  // Generated as the kind says, at the given size.
  LeafTextureParams oak = kind("oak").params;
  oak.width = oak.height = 32;
  EXPECT_EQ(set.kind_leaves[0].maps.albedo, generate_leaf_textures(oak).albedo);
  add_leaf_kinds(set, {"willow", "aspen"}, small);
  ASSERT_EQ(set.kind_leaves.size(), 3u);
  EXPECT_EQ(set.kind_leaves[2].kind, "aspen");
}

TEST(LeafKinds, AddLeafKindsNamesAnUnknownKindAndAddsNothing) {
  LeafTextureParams small;
  small.width = small.height = 16;
  BarkTextureParams bark;
  bark.width = bark.height = 16;
  TextureSet set = generate_texture_set(small, bark);
  try {
    add_leaf_kinds(set, {"oak", "maple"}, small);
    FAIL() << "no error";
  } catch (const TextureError& e) {
    EXPECT_NE(std::string(e.what()).find("'maple'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("broadleaf, aspen, oak, willow, tupelo"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(set.kind_leaves.empty());
}

TEST(LeafKinds, OutlineOutOfRangeIsRefused) {
  LeafTextureParams p;
  p.width = p.height = 16;
  for (int bad : {-1, BOREAS_LEAF_OUTLINE_COUNT}) {
    p.shape.outline = bad;
    try {
      generate_leaf_textures(p);
      ADD_FAILURE() << "no error for outline " << bad;
    } catch (const TextureError& e) {
      EXPECT_NE(std::string(e.what()).find("shape.outline"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace boreas::render
