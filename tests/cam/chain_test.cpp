#include "cam/chain.hpp"

#include <gtest/gtest.h>

#include "cam/dxf_import.hpp"

namespace usina::cam {
namespace {

Path line(Vec2 a, Vec2 b) {
  return {a, {{b, std::nullopt, 0}}, false};
}

TEST(Chain, ReversesEntitiesAndClosesTheSquareOfTheFixture) {
  core::DiagnosticList d;
  DxfOptions o;
  o.layer = "CUT";
  const auto entities =
      read_dxf(std::string(USINA_TEST_DIR) + "/programs/dxf/square_lines.dxf", o, d);
  ASSERT_TRUE(entities);
  const auto paths = chain(*entities);
  ASSERT_EQ(paths.size(), 1u);
  const Path& p = paths[0];
  EXPECT_TRUE(p.closed);
  EXPECT_EQ(p.start, (Vec2{0, 0}));
  ASSERT_EQ(p.segs.size(), 4u);
  EXPECT_EQ(p.segs[0].to, (Vec2{20, 0}));
  EXPECT_EQ(p.segs[1].to, (Vec2{20, 10.004}));  // B reversed; its end is the joined point
  EXPECT_EQ(p.segs[2].to, (Vec2{0, 10}));
  EXPECT_EQ(p.segs[3].to, (Vec2{0, 0}));  // D reversed, closing on the start
}

TEST(Chain, GrowsAtTheStartTooSoTheFirstDrawnEntityNeedNotBeAnEnd) {
  // Drawn: the middle segment first, then the last, then the first reversed.
  const auto paths = chain({line({10, 0}, {20, 0}), line({20, 0}, {30, 0}), line({10, 0}, {0, 0})});
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(paths[0].start, (Vec2{0, 0}));
  ASSERT_EQ(paths[0].segs.size(), 3u);
  EXPECT_EQ(paths[0].segs[0].to, (Vec2{10, 0}));
  EXPECT_EQ(paths[0].segs[2].to, (Vec2{30, 0}));
  EXPECT_FALSE(paths[0].closed);
}

TEST(Chain, EndsFartherThanTheToleranceStayApart) {
  const auto paths = chain({line({0, 0}, {10, 0}), line({10.02, 0}, {20, 0})});
  EXPECT_EQ(paths.size(), 2u);
  const auto joined = chain({line({0, 0}, {10, 0}), line({10.009, 0}, {20, 0})});
  EXPECT_EQ(joined.size(), 1u);
}

TEST(Chain, FirstEntityInDrawingOrderWinsAtAFork) {
  // Three lines meet at (10, 0): the path takes the earlier-drawn branch.
  const auto paths = chain({line({0, 0}, {10, 0}), line({10, 5}, {10, 0}), line({10, 0}, {20, 0})});
  ASSERT_EQ(paths.size(), 2u);
  EXPECT_EQ(paths[0].segs.back().to, (Vec2{10, 5}));  // the second entity, reversed
  EXPECT_EQ(paths[1].start, (Vec2{10, 0}));
}

TEST(Chain, ArcsStayArcsAndTurnWhenReversed) {
  const Path arc{{10, 0}, {{{0, 10}, Vec2{0, 0}, 1}}, false};
  const auto paths = chain({line({20, 0}, {10, 0}), line({0, 20}, {0, 10}), arc});
  ASSERT_EQ(paths.size(), 1u);
  const Path& p = paths[0];
  ASSERT_EQ(p.segs.size(), 3u);
  EXPECT_TRUE(p.segs[1].center);
  EXPECT_EQ(p.segs[1].turn, 1);  // (10,0) to (0,10) counter-clockwise, as drawn
  EXPECT_EQ(p.segs[2].to, (Vec2{0, 20}));
}

TEST(Chain, ClosedEntitiesKeepTheirPlace) {
  const Path circle{{5, 0}, {{{5, 0}, Vec2{0, 0}, 1}}, true};
  const auto paths = chain({line({0, 0}, {1, 0}), circle, line({9, 9}, {8, 8})});
  ASSERT_EQ(paths.size(), 3u);
  EXPECT_TRUE(paths[1].closed);
  EXPECT_EQ(paths[2].start, (Vec2{9, 9}));
}

TEST(Chain, TenThousandSegmentsHalfOfThemReversed) {
  std::vector<Path> entities;
  for (int i = 0; i < 10000; ++i) {
    const Vec2 a{i * 1.0, (i % 2) * 1.0};
    const Vec2 b{(i + 1) * 1.0, ((i + 1) % 2) * 1.0};
    entities.push_back(i % 2 == 0 ? line(a, b) : line(b, a));
  }
  const auto paths = chain(std::move(entities));
  ASSERT_EQ(paths.size(), 1u);
  ASSERT_EQ(paths[0].segs.size(), 10000u);
  for (std::size_t i = 0; i < paths[0].segs.size(); ++i) {
    EXPECT_EQ(paths[0].segs[i].to.x, static_cast<double>(i + 1));
  }
}

}  // namespace
}  // namespace usina::cam
