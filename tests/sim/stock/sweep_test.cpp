// The sweep against brute force: the lowest point of each tool over a cell
// along a straight move, closed form (or bisection) against the tool placed
// at 100,000 points of the move; and a sweep cuts only what it passes over.
#include "sim/stock/sweep.hpp"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace usina::sim::stock {
namespace {

using core::Vec3;

// The tool stamped at n + 1 points of the move: an upper bound of the exact
// envelope that tends to it as n grows.
double stamped(const ToolShape& t, const Vec3& a, const Vec3& b, double cx, double cy, int n) {
  double low = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= n; ++i) {
    const double s = static_cast<double>(i) / n;
    const Vec3 p = a + (b - a) * s;
    const double r = std::hypot(cx - p.x, cy - p.y);
    if (r <= t.radius()) low = std::min(low, p.z + t.lift(r));
  }
  return low;
}

void expect_exact(const ToolShape& t, std::uint32_t seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  for (int k = 0; k < 150; ++k) {
    const Vec3 a{u(gen), u(gen), u(gen) * 0.5};
    Vec3 b{u(gen), u(gen), u(gen) * 0.5};
    if (k % 10 == 0) b = {a.x, a.y, b.z};  // plunges
    if (k % 10 == 1) b.z = a.z;            // level moves
    const double cx = 0.5 * (a.x + b.x) + u(gen) * 0.4;
    const double cy = 0.5 * (a.y + b.y) + u(gen) * 0.4;
    const double exact = envelope(t, a, b, cx, cy);
    const double brute = stamped(t, a, b, cx, cy, 100000);
    if (std::isinf(brute)) {
      // Stamping can miss a sliver the tool only grazes; the exact one cannot be higher.
      continue;
    }
    ASSERT_FALSE(std::isinf(exact)) << shape_name(t) << " k=" << k;
    EXPECT_LE(exact, brute + 1e-9) << shape_name(t) << " k=" << k;
    // 100,000 stamps on a move of at most 30 mm are 0.3 µm apart: near the truth
    // (a wrong formula is off by tenths).
    EXPECT_GE(exact, brute - 1e-3) << shape_name(t) << " k=" << k;
  }
}

TEST(StockSweep, FlatEnvelopeIsExact) {
  expect_exact(*parse_shape("flat", 6.0), 1);
}

TEST(StockSweep, BallEnvelopeIsExact) {
  expect_exact(*parse_shape("ball", 8.0), 2);
}

TEST(StockSweep, BullNoseEnvelopeIsExact) {
  expect_exact(*parse_shape("bull:1.5", 10.0), 3);
}

TEST(StockSweep, DrillEnvelopeIsExact) {
  expect_exact(*parse_shape("drill", 10.0), 4);
}

TEST(StockSweep, VeeEnvelopeIsExact) {
  expect_exact(*parse_shape("vee:60", 12.0), 5);
}

TEST(StockSweep, AMoveAboveTheStockCutsNothing) {
  auto map = HeightMap::make({20, 20, 5, {}}, 0.5);
  ASSERT_TRUE(map);
  const Cut c = sweep(*map, *parse_shape("ball", 6.0), {-5, 3, 0.0}, {25, 17, 0.5}, 1);
  EXPECT_DOUBLE_EQ(c.removed_mm3, 0.0);
  EXPECT_DOUBLE_EQ(map->removed(), 0.0);
}

TEST(StockSweep, ACutLowersOnlyTheCellsUnderThePath) {
  auto map = HeightMap::make({20, 20, 5, {}}, 0.1);
  ASSERT_TRUE(map);
  const Cut c = sweep(*map, *parse_shape("flat", 4.0), {5, 10.03, -1}, {15, 10.03, -1}, 7);
  EXPECT_NEAR(map->z(100, 100), -1.0, 1e-6);  // on the path
  EXPECT_EQ(map->mark(100, 100), 7);
  EXPECT_DOUBLE_EQ(map->z(100, 130), 0.0);  // 2.97 mm beside it, beyond the radius
  EXPECT_EQ(map->mark(100, 130), kUncut);
  EXPECT_NEAR(c.removed_mm3, map->removed(), 1e-9);
  EXPECT_NEAR(c.deepest, 1.0, 1e-6);
  EXPECT_NEAR(c.lowest, -1.0, 1e-9);
  // 4 x 10 + pi 2² = 52.57 mm² one deep, to the grid's resolution.
  EXPECT_NEAR(c.removed_mm3, 40.0 + M_PI * 4.0, 0.5);
}

TEST(StockSweep, CuttingThroughStopsAtTheBottom) {
  auto map = HeightMap::make({20, 20, 5, {}}, 0.5);
  ASSERT_TRUE(map);
  const Cut c = sweep(*map, *parse_shape("flat", 2.0), {10, 10, 0}, {10, 10, -9}, 1);
  EXPECT_NEAR(map->z(20, 20), -5.0, 1e-6);
  EXPECT_NEAR(c.lowest, -9.0, 1e-9);  // the tool went below the bottom: a floor check sees it
  EXPECT_NEAR(c.deepest, 5.0, 1e-6);
}

}  // namespace
}  // namespace usina::sim::stock

namespace usina::sim::stock {
namespace {

double part_sum(const Cut& c, std::size_t from, std::size_t to) {
  double s = 0.0;
  for (std::size_t k = from; k < to; ++k)
    s += c.parts_mm3[k];
  return s;
}

TEST(StockSweepParts, ALineTellsItsVolumeWhereItsLeadingEdgeTookIt) {
  // A 2 mm end mill from X-10 to X10 at Z-1 through a stock that starts at
  // X0: the first 9 mm of the 20 (parts 0-6, to 8.75 mm) cut air; the rest,
  // 1.25 mm a part, takes 2 × 1 × 1.25 mm³ each.
  auto map = HeightMap::make({20, 20, 5, {}}, 0.05);
  ASSERT_TRUE(map);
  const Cut c = sweep(*map, *parse_shape("flat", 2.0), {-10, 10, -1}, {10, 10, -1}, 1);
  EXPECT_NEAR(part_sum(c, 0, kCutParts), c.removed_mm3, 1e-9);
  EXPECT_EQ(part_sum(c, 0, 7), 0.0);
  for (std::size_t k = 8; k < kCutParts; ++k)
    EXPECT_NEAR(c.parts_mm3[k], 2.5, 0.1) << k;
}

TEST(StockSweepParts, APlungeTellsItsVolumeByTheDepthItTookIt) {
  // From Z4 to Z-4 into a stock whose top is Z0: the first half of the drop
  // cuts air, the second takes the same each part.
  auto map = HeightMap::make({20, 20, 10, {}}, 0.05);
  ASSERT_TRUE(map);
  const Cut c = sweep(*map, *parse_shape("flat", 4.0), {10, 10, 4}, {10, 10, -4}, 1);
  EXPECT_NEAR(part_sum(c, 0, kCutParts), c.removed_mm3, 1e-9);
  EXPECT_EQ(part_sum(c, 0, kCutParts / 2), 0.0);
  for (std::size_t k = kCutParts / 2; k < kCutParts; ++k)
    EXPECT_NEAR(c.parts_mm3[k], c.removed_mm3 / (kCutParts / 2), 1e-6) << k;
  // Going up again takes nothing.
  const Cut up = sweep(*map, *parse_shape("flat", 4.0), {10, 10, -4}, {10, 10, 4}, 1);
  EXPECT_EQ(up.removed_mm3, 0.0);
}

}  // namespace
}  // namespace usina::sim::stock
