// IBM's segmented circles (a circle's record, then a motion of several
// points) as arcs in the canon stream, worked by hand; Circles::Chords
// keeps the chords.
#include <cmath>
#include <numbers>

#include "apt/canon_out.hpp"
#include "apt_run.hpp"

namespace usina::apt::test {
namespace {

class Ops final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    if (const auto* a = std::get_if<canon::Arc>(&op.kind)) arcs.push_back(*a);
    if (const auto* f = std::get_if<canon::Feed>(&op.kind)) feeds.push_back(f->to);
  }

  std::vector<canon::Arc> arcs;
  std::vector<canon::Vec3> feeds;
};

ClRecord circle(double xc, double yc, double r) {
  std::vector<ClWord> w{ClWord::number(0), ClWord::vocabulary(4), ClWord::vocabulary(9),
                        ClWord::chars("     C"), ClWord::number(0)};
  for (double v : {xc, yc, 0.0, 0.0, 0.0, 1.0, r})
    w.push_back(ClWord::number(v));
  return {cls::kSurface, 2, w, {}};
}

ClRecord points(int sub, const std::vector<canon::Vec3>& ps) {
  std::vector<ClWord> w{ClWord::chars("     C"), ClWord::number(0)};
  for (const canon::Vec3& p : ps)
    for (double v : {p.x, p.y, p.z})
      w.push_back(ClWord::number(v));
  return {cls::kMotion, sub, w, {}};
}

// A point at `deg` on the circle of radius r about the origin.
canon::Vec3 at(double r, double deg) {
  const double t = deg * std::numbers::pi / 180.0;
  return {r * std::cos(t), r * std::sin(t), 0.0};
}

TEST(AptCircleArcs, ClockwiseChordsAreOneClockwiseArc) {
  // From (10,0) down to (0,-10) about the origin: a quarter turn clockwise;
  // the middle point lies out on the tolerance band (10.01), as IBM's do.
  Ops o;
  to_canon({points(3, {{10, 0, 0}}), circle(0, 0, 10), points(5, {at(10.01, -45), at(10, -90)})},
           1.0, o);
  ASSERT_EQ(o.arcs.size(), 1u);
  EXPECT_NEAR(o.arcs[0].to.x, 0, 1e-9);
  EXPECT_NEAR(o.arcs[0].to.y, -10, 1e-9);
  EXPECT_EQ(o.arcs[0].center, (canon::Vec3{0, 0, 0}));
  EXPECT_EQ(o.arcs[0].turn, -1);
  EXPECT_TRUE(o.feeds.empty());
}

TEST(AptCircleArcs, ContinuationRecordIsAnotherArcAndTheCircleEndsThere) {
  // 5000 5 to 90°, its 5000 6 continuation on to 180°: two arcs, the first
  // ending brought to the start's radius; the next statement's point is a feed.
  Ops o;
  to_canon({points(3, {{10, 0, 0}}), circle(0, 0, 10), points(5, {at(10.01, 45), at(10.01, 90)}),
            points(6, {at(10.01, 135), at(10, 180)}), points(5, {{-10, -5, 0}})},
           1.0, o);
  ASSERT_EQ(o.arcs.size(), 2u);
  EXPECT_NEAR(o.arcs[0].to.y, 10, 1e-9);  // 10.01 brought to 10
  EXPECT_NEAR(o.arcs[1].to.x, -10, 1e-9);
  EXPECT_EQ(o.arcs[1].turn, 1);
  ASSERT_EQ(o.feeds.size(), 1u);
  EXPECT_EQ(o.feeds[0], (canon::Vec3{-10, -5, 0}));
}

TEST(AptCircleArcs, MoreThanATurnCountsTheTurns) {
  // 0° → 120° → 240° → 360° → 90°: a turn and a quarter counter-clockwise.
  Ops o;
  to_canon({points(3, {{10, 0, 0}}), circle(0, 0, 10),
            points(5, {at(10, 120), at(10, 240), at(10, 0), at(10, 90)})},
           1.0, o);
  ASSERT_EQ(o.arcs.size(), 1u);
  EXPECT_EQ(o.arcs[0].turn, 2);
}

TEST(AptCircleArcs, PointsOffTheCircleOrItsPlaneStayChords) {
  Ops o;
  to_canon({points(3, {{10, 0, 0}}), circle(0, 0, 10), points(5, {at(10, 45), {0, 10, 1}})}, 1.0,
           o);
  to_canon({points(3, {{10, 0, 0}}), circle(0, 0, 10), points(5, {at(12, 45), at(10, 90)})}, 1.0,
           o);
  EXPECT_TRUE(o.arcs.empty());
  EXPECT_EQ(o.feeds.size(), 4u);
}

TEST(AptCircleArcs, ChordsKeepTheCl) {
  Ops o;
  to_canon({points(3, {{10, 0, 0}}), circle(0, 0, 10), points(5, {at(10.01, 45), at(10, 90)})}, 1.0,
           o, Circles::Chords);
  EXPECT_TRUE(o.arcs.empty());
  EXPECT_EQ(o.feeds.size(), 2u);
}

}  // namespace
}  // namespace usina::apt::test
