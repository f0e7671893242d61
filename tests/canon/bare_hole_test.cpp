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

TEST(BareHole, AHoleWithItsOwnFeedIsCutAtItPerMinute) {
  Hole h{{10, 0, 2}, 5, 4, HoleCycle::Bore};
  h.f = 9.5;
  const Op hole{h, {}, Origin::Program};
  Feed in_force;  // a feed per revolution in force: not the hole's
  in_force.programmed = {ProgrammedFeed::Mode::PerRevolution, 0.1};
  const auto moves = bare_hole_moves(hole, h, {0, 0, 10}, {}, in_force);
  ASSERT_EQ(moves.size(), 5u);
  for (const std::size_t i : {2u, 3u}) {
    const Feed& f = std::get<Feed>(moves[i].kind);
    EXPECT_EQ(f.f, 9.5);
    EXPECT_EQ(f.programmed.mode, ProgrammedFeed::Mode::PerMinute);
  }
}

TEST(BareHole, G89DwellsThenFeedsOutG86StopsAndRapidsOut) {
  Hole h{{10, 0, 2}, 5, 4, HoleCycle::BoreDwell, 50.0, 0.5};
  const Op dwell{h, {}, Origin::Program};
  const auto d = bare_hole_moves(dwell, h, {10, 0, 5}, {}, Feed{}, Spindle{900, SpindleDir::Cw});
  ASSERT_EQ(d.size(), 6u);  // over, down to R, in, the dwell, out, up
  EXPECT_EQ(std::get<Dwell>(d[3].kind).s, 0.5);
  EXPECT_EQ(end_of(d[4]), (Vec3{10, 0, 2}));  // fed out to R
  EXPECT_TRUE(std::holds_alternative<Feed>(d[4].kind));
  EXPECT_EQ(end_of(d[5]), (Vec3{10, 0, 5}));
  h.cycle = HoleCycle::BoreStop;
  const Op stop{h, {}, Origin::Program};
  const auto s = bare_hole_moves(stop, h, {10, 0, 5}, {}, Feed{}, Spindle{900, SpindleDir::Cw});
  ASSERT_EQ(s.size(), 6u);
  EXPECT_EQ(std::get<Spindle>(s[3].kind).dir, SpindleDir::Off);  // stopped at the bottom
  EXPECT_TRUE(std::holds_alternative<Traverse>(s[4].kind));      // out at rapid
  EXPECT_EQ(end_of(s[4]), (Vec3{10, 0, 5}));
  EXPECT_EQ(std::get<Spindle>(s[5].kind).rpm, 900);  // started again
}

TEST(BareHole, ACyclesHoleOrOneOfNoDepthHasNoMoves) {
  const Op cycle{Hole{{10, 0, 2}, 5, 4}, {}, Origin::Cycle};
  EXPECT_TRUE(bare_hole_moves(cycle, std::get<Hole>(cycle.kind), {}, {}, Feed{}).empty());
  const Op flat{Hole{{10, 0, 2}, 5, 0}, {}, Origin::Program};
  EXPECT_TRUE(bare_hole_moves(flat, std::get<Hole>(flat.kind), {}, {}, Feed{}).empty());
}

}  // namespace
}  // namespace usina::canon
