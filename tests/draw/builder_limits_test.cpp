// A DrawingBuilder's memory is bounded by what the picture can show
// (builder.hpp): a retraced segment, arc or circle is drawn once, the window
// of remembered ones is finite, and past the entity limit moves are counted,
// not drawn.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "draw/builder.hpp"
#include "draw/layer_style.hpp"

namespace usina::draw {
namespace {

using core::Vec3;

canon::Op op(canon::OpKind kind, std::uint32_t line = 0) {
  return canon::Op{std::move(kind), {1, line, 1, 0, 0}, canon::Origin::Program};
}

canon::Feed feed(Vec3 to) {
  return canon::Feed{to, std::nullopt, {}, {}};
}

canon::Op arc(Vec3 to, Vec3 center, int turn) {
  return op(canon::Arc{to, center, {0, 0, 1}, turn, std::nullopt});
}

TEST(BuilderLimits, ALoopRetracingOnePathDrawsItOnce) {
  // The runaway loop of issue 11: G0 X1, G0 X0, over and over.
  Drawing d;
  DrawingBuilder b(d, View::Toolpath);
  for (int i = 0; i < 100'000; ++i) {
    b.on(op(canon::Traverse{{1, 0, 0}}));
    b.on(op(canon::Traverse{{0, 0, 0}}));
  }
  b.finish();
  EXPECT_EQ(d.entity_count(), 1u);
  EXPECT_EQ(b.moves_not_drawn(), 0u);
  EXPECT_FALSE(b.limit_note("usina trace lists them").has_value());
}

TEST(BuilderLimits, RetracingAtAnotherDepthOrOnAnotherLayerCounts) {
  // Passes at two depths are one line in plan; a rapid over a feed is not.
  Drawing d;
  DrawingBuilder b(d, View::Toolpath);
  b.on(op(feed({10, 0, -1})));
  b.on(op(canon::Traverse{{10, 0, 5}}));
  b.on(op(canon::Traverse{{0, 0, 5}}));
  b.on(op(feed({0, 0, -2})));
  b.on(op(feed({10, 0, -2})));
  b.finish();
  EXPECT_EQ(d.layer(kRapidLayer).entities.size(), 1u);
  EXPECT_EQ(d.layer(toolpath_layer(0)).entities.size(), 1u);
}

TEST(BuilderLimits, AClockwiseArcRetracesItsCounterClockwiseTwin) {
  Drawing d;
  DrawingBuilder b(d, View::Toolpath, {10, 0, 0});
  for (int i = 0; i < 1000; ++i) {
    b.on(arc({0, 10, 0}, {0, 0, 0}, 1));    // a quarter, counter-clockwise
    b.on(arc({10, 0, 0}, {0, 0, 0}, -1));   // and back, clockwise
    b.on(arc({10, 0, -1}, {0, 0, 0}, -1));  // a full circle down
  }
  b.finish();
  const auto e = d.layer(toolpath_layer(0)).entities.to_vector();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_TRUE(std::holds_alternative<Arc>(e[0]));
  EXPECT_TRUE(std::holds_alternative<Circle>(e[1]));
}

TEST(BuilderLimits, TheWindowRemembersOnlyTheLastSegments) {
  // A hexagon traced twice: with a window of 4 the second lap is drawn
  // again, with a window of 64 it is not.
  auto laps = [](std::size_t window) {
    Drawing d;
    DrawingBuilder b(d, View::Toolpath, {10, 0, 0}, DrawLimits{100, 100, window});
    for (int lap = 0; lap < 2; ++lap)
      for (int k = 1; k <= 6; ++k) {
        const double a = k * 3.14159265358979 / 3.0;
        b.on(op(feed({10 * std::cos(a), 10 * std::sin(a), 0})));
      }
    b.finish();
    return d.entity_count();
  };
  EXPECT_EQ(laps(64), 6u);
  EXPECT_EQ(laps(4), 12u);
}

TEST(BuilderLimits, PastTheEntityLimitMovesAreCountedNotDrawn) {
  Drawing d;
  DrawingBuilder b(d, View::Toolpath, {}, DrawLimits{10, 100, 64});
  for (int i = 1; i <= 25; ++i)
    b.on(op(feed({static_cast<double>(i), static_cast<double>(i % 2), 0}),
            static_cast<std::uint32_t>(i)));
  b.finish();
  EXPECT_EQ(d.entity_count(), 10u);
  EXPECT_EQ(b.moves_not_drawn(), 15u);
  const auto note = b.limit_note("usina trace lists them");
  ASSERT_TRUE(note.has_value());
  EXPECT_NE(note->find("10 entities"), std::string::npos) << *note;
  EXPECT_NE(note->find("15 moves from line 11"), std::string::npos) << *note;
  EXPECT_NE(note->find("are not drawn (usina trace lists them)"), std::string::npos) << *note;
}

TEST(BuilderLimits, PolylinePointsCountTowardsTheLimit) {
  Drawing d;
  DrawingBuilder b(d, View::Toolpath, {}, DrawLimits{100, 10, 64});
  std::vector<Vec3> points;
  for (int i = 0; i < 20; ++i)
    points.push_back({static_cast<double>(i), static_cast<double>(i * i), 0});
  b.on(op(canon::Spline{{20, 400, 0}, points, std::nullopt, {}}));
  b.on(op(canon::Spline{{0, 0, 0}, points, std::nullopt, {}}));
  b.finish();
  EXPECT_EQ(d.entity_count(), 1u);
  EXPECT_EQ(b.moves_not_drawn(), 1u);
}

TEST(BuilderLimits, HugeCoordinatesAreNeverTakenForARetrace) {
  // A key needs numbers on the grid: one beyond 1e12 mm is never remembered.
  Drawing d;
  DrawingBuilder b(d, View::Toolpath);
  b.on(op(feed({1e13, 0, 0})));
  b.on(op(feed({0, 0, 0})));
  b.finish();
  EXPECT_EQ(d.entity_count(), 2u);
}

}  // namespace
}  // namespace usina::draw
