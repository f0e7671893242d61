// A bare hole (a generator's Hole feature) as the moves LinuxCNC's G81
// makes in G98: what stats and simulate follow (canon/bare_hole.hpp).
#include "canon/bare_hole.hpp"

#include <gtest/gtest.h>

namespace usina::canon {
namespace {

Vec3 end_of(const Op& op) {
  if (const auto* t = std::get_if<Traverse>(&op.kind)) return t->to;
  return std::get<Feed>(op.kind).to;
}

TEST(BareHole, FromAboveItGoesOverDownToRDrillsAndComesBack) {
  const Op hole{Hole{{10, 20, 1}, 5, 11}, {0, 7, 1, 0, 0}, Origin::Program};
  Feed feed;
  feed.f = 120.0;
  const auto moves = bare_hole_moves(hole, std::get<Hole>(hole.kind), {0, 0, 5}, {}, feed);
  ASSERT_EQ(moves.size(), 4u);
  EXPECT_EQ(end_of(moves[0]), (Vec3{10, 20, 5}));  // over the hole at the start's height
  EXPECT_EQ(end_of(moves[1]), (Vec3{10, 20, 1}));  // down to R
  ASSERT_TRUE(std::holds_alternative<Feed>(moves[2].kind));
  EXPECT_EQ(end_of(moves[2]), (Vec3{10, 20, -10}));  // R - depth at the feed in force
  EXPECT_EQ(std::get<Feed>(moves[2].kind).f, 120.0);
  EXPECT_EQ(end_of(moves[3]), (Vec3{10, 20, 5}));  // back where it started (G98)
  for (const Op& m : moves) {
    EXPECT_EQ(m.src.line, 7u);
    EXPECT_EQ(m.origin, Origin::Cycle);
  }
}

TEST(BareHole, FromBelowRItFirstRisesToR) {
  const Op hole{Hole{{10, 0, 2}, 5, 4}, {}, Origin::Program};
  const auto moves = bare_hole_moves(hole, std::get<Hole>(hole.kind), {0, 0, -1}, {}, Feed{});
  ASSERT_EQ(moves.size(), 4u);
  EXPECT_EQ(end_of(moves[0]), (Vec3{0, 0, 2}));
  EXPECT_EQ(end_of(moves[1]), (Vec3{10, 0, 2}));
  EXPECT_EQ(end_of(moves[2]), (Vec3{10, 0, -2}));
  EXPECT_EQ(end_of(moves[3]), (Vec3{10, 0, 2}));
}

TEST(BareHole, ACyclesHoleOrOneOfNoDepthHasNoMoves) {
  const Op cycle{Hole{{10, 0, 2}, 5, 4}, {}, Origin::Cycle};
  EXPECT_TRUE(bare_hole_moves(cycle, std::get<Hole>(cycle.kind), {}, {}, Feed{}).empty());
  const Op flat{Hole{{10, 0, 2}, 5, 0}, {}, Origin::Program};
  EXPECT_TRUE(bare_hole_moves(flat, std::get<Hole>(flat.kind), {}, {}, Feed{}).empty());
}

}  // namespace
}  // namespace usina::canon
