// Facing (cam/face.hpp): every point of the area under the tool at the
// final depth, the rows entered from off the stock, and what is refused.
#include "cam/face.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "cam_test_util.hpp"

namespace usina::cam {
namespace {

using testing::count_code;
using testing::ops_of;

FaceOptions options() {
  FaceOptions o;
  o.cut.tool_diameter = 50;
  o.lo = {-2, -2};
  o.hi = {102, 42};
  o.depth = 0.5;
  return o;
}

canon::Toolpath faced(const FaceOptions& o, core::DiagnosticList& diags) {
  canon::Toolpath tp;
  EXPECT_TRUE(generate_face(o, tp, diags)) << (diags.all().empty() ? "" : diags.all()[0].message);
  return tp;
}

// The distance from p to the segment ab.
double to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 e = b - a;
  const double t = std::clamp(core::dot(p - a, e) / core::dot(e, e), 0.0, 1.0);
  return core::distance(p, a + e * t);
}

TEST(Face, EveryPointOfTheAreaIsUnderTheToolAtTheDepth) {
  core::DiagnosticList diags;
  const canon::Toolpath tp = faced(options(), diags);
  std::vector<std::pair<Vec2, Vec2>> cuts;  // feed moves at the final depth
  Vec3 at{};
  for (const canon::Op& op : tp.ops()) {
    const auto end = testing::end_of(op);
    if (!end) continue;
    if (std::holds_alternative<canon::Feed>(op.kind) && std::abs(end->z + 0.5) < 1e-9 &&
        std::abs(at.z + 0.5) < 1e-9)
      cuts.push_back({{at.x, at.y}, {end->x, end->y}});
    at = *end;
  }
  ASSERT_FALSE(cuts.empty());
  // A 1 mm grid over the area, its edges included.
  for (double x = -2; x <= 102; x += 1) {
    for (double y = -2; y <= 42; y += 1) {
      double nearest = 1e300;
      for (const auto& [a, b] : cuts)
        nearest = std::min(nearest, to_segment({x, y}, a, b));
      EXPECT_LE(nearest, 25.0 + 1e-9) << x << " " << y;
    }
  }
}

TEST(Face, RowsAreAStepoverApartAndThePlungeIsOffTheStock) {
  core::DiagnosticList diags;
  const canon::Toolpath tp = faced(options(), diags);
  const auto feeds = ops_of<canon::Feed>(tp);
  ASSERT_GE(feeds.size(), 3u);
  // The plunge: straight down at the first row's start, left of the stock
  // by the tool's radius and the clearance.
  EXPECT_DOUBLE_EQ(feeds[0].to.x, -2 - 25 - 2);
  EXPECT_DOUBLE_EQ(feeds[0].to.z, -0.5);
  // Rows 35 mm (70 % of D50) apart, the first taking 35 mm off the front.
  std::vector<double> ys;
  for (const auto& f : feeds)
    if (ys.empty() || std::abs(f.to.y - ys.back()) > 1e-9) ys.push_back(f.to.y);
  ASSERT_EQ(ys.size(), 2u);  // 44 mm deep: two rows
  EXPECT_DOUBLE_EQ(ys[0], -2 - 25 + 35);
  EXPECT_DOUBLE_EQ(ys[1] - ys[0], 35);
  // Every step between rows is made beside the stock, not across it.
  for (std::size_t i = 1; i < feeds.size(); ++i) {
    if (std::abs(feeds[i].to.y - feeds[i - 1].to.y) > 1e-9) {
      EXPECT_GT(std::abs(feeds[i].to.x - 50), 52 + 25) << i;
    }
  }
}

TEST(Face, StepDownMakesEqualPasses) {
  FaceOptions o = options();
  o.depth = 3;
  o.step_down = 1.2;
  core::DiagnosticList diags;
  const canon::Toolpath tp = faced(o, diags);
  std::vector<double> levels;
  for (const auto& f : ops_of<canon::Feed>(tp))
    if (levels.empty() || std::abs(f.to.z - levels.back()) > 1e-9) levels.push_back(f.to.z);
  EXPECT_EQ(levels, (std::vector<double>{-1, -2, -3}));
}

TEST(Face, AStepoverWiderThanTheToolIsRefused) {
  FaceOptions o = options();
  o.stepover = 51;
  core::DiagnosticList diags;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_face(o, tp, diags));
  EXPECT_EQ(count_code(diags, core::Code::GenBadValue), 1);
  EXPECT_NE(diags.all()[0].message.find("ribs"), std::string::npos);
  EXPECT_TRUE(tp.ops().empty());
}

TEST(Face, AnEmptyAreaOrANonFiniteValueIsRefused) {
  for (int k = 0; k < 3; ++k) {
    FaceOptions o = options();
    if (k == 0) o.hi = o.lo;
    if (k == 1) o.depth = std::nan("");
    if (k == 2) o.hi.y = std::numeric_limits<double>::infinity();
    core::DiagnosticList diags;
    canon::Toolpath tp;
    EXPECT_FALSE(generate_face(o, tp, diags)) << k;
    EXPECT_TRUE(diags.has_errors()) << k;
  }
}

TEST(Face, TheWorkIsBoundedBeforeItIsMade) {
  FaceOptions o = options();
  o.hi = {102, 1000};
  o.stepover = 1e-5;  // 10^8 rows
  o.cut.tool_diameter = 1;
  core::DiagnosticList diags;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_face(o, tp, diags));
  EXPECT_EQ(count_code(diags, core::Code::GenTooMuchWork), 1);
}

}  // namespace
}  // namespace usina::cam
