// Issue 11: every generator parameter within a documented range, the work
// bounded before a generator starts, and no silent material left standing.
#include "cam/limits.hpp"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "cam/drill.hpp"
#include "cam/engrave.hpp"
#include "cam/from_dxf.hpp"
#include "cam/pocket.hpp"
#include "cam/profile.hpp"
#include "cam_test_util.hpp"
#include "canon/toolpath.hpp"

namespace usina::cam {
namespace {

using testing::count_code;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Counts the ops a generator emits without keeping them.
class CountingSink final : public canon::Sink {
 public:
  void on(const canon::Op&) override { ++ops; }

  double ops = 0;
};

std::string first_message(const core::DiagnosticList& d) {
  return d.all().empty() ? std::string() : d.all().front().message;
}

TEST(Limits, RangeMessageGivesTheValueAndTheRange) {
  core::DiagnosticList d;
  EXPECT_FALSE(check_range("the feed (--feed)", 0, kFeed, d));
  EXPECT_EQ(first_message(d),
            "the feed (--feed) is 0 mm/min; give a number above 0 and at most 1000000 mm/min");
  d.clear();
  EXPECT_FALSE(check_range("the tool diameter", 1e-300, kToolDiameter, d));
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("is 1e-300 mm; give a number from 0.001 to "
                                                     "1000 mm"));
  EXPECT_TRUE(check_range("x", 0, kLengthOrZero, d));
  EXPECT_TRUE(check_range("x", kMaxCoordinate, kLength, d));
}

TEST(Limits, NanInfinityNegativeAndAbsurdValuesAreOutOfEveryRange) {
  for (const Range& r : {kLength, kLengthOrZero, kToolDiameter, kFeed, kSpindle, kTolerance}) {
    for (const double v : {kNan, kInf, -kInf, -1.0, 1e300}) {
      core::DiagnosticList d;
      EXPECT_FALSE(check_range("v", v, r, d)) << v << " " << r.unit;
      EXPECT_EQ(count_code(d, core::Code::GenBadValue), 1);
    }
  }
}

TEST(Limits, WorkMessageGivesTheEstimateTheSizeAndTheLimit) {
  core::DiagnosticList d;
  EXPECT_TRUE(check_work("the pocket", 20e6, kDefaultMaxMoves, "less", d));
  EXPECT_FALSE(check_work("the pocket", 3.2e9, kDefaultMaxMoves, "give a larger stepover", d));
  ASSERT_EQ(count_code(d, core::Code::GenTooMuchWork), 1);
  EXPECT_EQ(first_message(d),
            "the pocket would be about 3,200,000,000 moves (about 57.6 GB of G-code), more than "
            "the limit of 20,000,000; give a larger stepover, or raise the limit with "
            "--max-moves");
  EXPECT_EQ(count_text(1e20), "1e+20");
  EXPECT_EQ(count_text(999), "999");
}

PocketShape rect(double w, double h) {
  return {rectangle({0, 0}, w, h, 0), {}};
}

PocketOptions pocket_options() {
  PocketOptions o;
  o.depth = 3;
  o.step_down = 3;
  o.stepover = 2;
  return o;  // a 6 mm tool
}

// Issue 11: --finish-allowance 30 on a 60 × 40 pocket left the core standing.
TEST(PocketMaterialLeft, AnAllowanceThatKeepsTheRoughingOutOfTheCoreIsAnError) {
  PocketOptions o = pocket_options();
  o.finish_allowance = 30;
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_pocket(rect(60, 40), o, tp, d));
  ASSERT_EQ(count_code(d, core::Code::GenMaterialLeft), 1);
  // The core: deeper than the finishing pass's 6 mm from the walls.
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("from (-24, -14) to (24, 14)"));
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("at most 3 mm (the tool radius)"));
  EXPECT_TRUE(tp.ops().empty());
}

TEST(PocketMaterialLeft, AnAllowanceAboveTheToolDiameterLeavesABandAndIsAnError) {
  PocketOptions o = pocket_options();
  o.finish_allowance = 7;  // the roughing starts 10 mm in, the finishing pass clears 6
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_pocket(rect(60, 40), o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenMaterialLeft), 1);
}

TEST(PocketMaterialLeft, ANarrowPocketWithoutRoomForRoughingIsAnError) {
  // 14 mm wide: 7 mm from the walls at most, the finishing pass clears 6, the
  // roughing rings would start 8 mm in: a strip 2 mm wide stands.
  PocketOptions o = pocket_options();
  o.finish_allowance = 5;
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_pocket(rect(60, 14), o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenMaterialLeft), 1);
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("to (24, 0.99)"));
}

TEST(PocketMaterialLeft, AllowancesUpToTheToolRadiusOrWithRoomForRingsAreFine) {
  for (const auto& [w, h, allowance] :
       {std::tuple{60.0, 40.0, 3.0}, std::tuple{60.0, 40.0, 5.0}, std::tuple{60.0, 14.0, 3.0},
        std::tuple{60.0, 7.0, 0.2}, std::tuple{60.0, 40.0, 0.0}}) {
    PocketOptions o = pocket_options();
    o.finish_allowance = allowance;
    core::DiagnosticList d;
    canon::Toolpath tp;
    EXPECT_TRUE(generate_pocket(rect(w, h), o, tp, d))
        << w << "x" << h << " " << allowance << ": " << first_message(d);
  }
}

TEST(PocketLimits, EveryValueIsCheckedAgainstItsRange) {
  for (const auto& change : std::vector<std::function<void(PocketOptions&)>>{
           [](PocketOptions& o) { o.depth = kNan; }, [](PocketOptions& o) { o.step_down = kInf; },
           [](PocketOptions& o) { o.stepover = -1; },
           [](PocketOptions& o) { o.finish_allowance = -0.1; },
           [](PocketOptions& o) { o.cut.tool_diameter = 1e9; },
           [](PocketOptions& o) { o.cut.feed = 1e300; }, [](PocketOptions& o) { o.cut.rpm = kNan; },
           [](PocketOptions& o) { o.cut.safe_z = 1e6; },
           [](PocketOptions& o) { o.cut.max_moves = 0; }}) {
    PocketOptions o = pocket_options();
    change(o);
    core::DiagnosticList d;
    canon::Toolpath tp;
    EXPECT_FALSE(generate_pocket(rect(60, 40), o, tp, d));
    EXPECT_EQ(count_code(d, core::Code::GenBadValue), 1) << first_message(d);
  }
}

TEST(PocketLimits, MoreMovesThanTheLimitIsRefusedBeforeAnyIsEmitted) {
  PocketOptions o = pocket_options();
  o.stepover = 0.05;   // 340 rings
  o.step_down = 0.01;  // 300 levels: about 800,000 moves
  o.cut.max_moves = 1e5;
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_pocket(rect(60, 40), o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenTooMuchWork), 1) << first_message(d);
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("the pocket would be about"));
  EXPECT_TRUE(tp.ops().empty());
  o.cut.max_moves = kDefaultMaxMoves;
  d.clear();
  EXPECT_TRUE(generate_pocket(rect(60, 40), o, tp, d)) << first_message(d);
}

TEST(PocketLimits, RingsTooManyToMakeAreRefusedBeforeTheyAreMade) {
  // 10,000 rings deep on a 20 m square, each with about 7,000 points of a
  // round corner: about 70 million points for one level.
  PocketOptions o = pocket_options();
  o.stepover = 1;
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_pocket(rect(20000, 20000), o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenTooMuchWork), 1) << first_message(d);
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("one level of the pocket would be about"));
}

TEST(ProfileLimits, ALeadArcThatSwingsThroughTheFarWallIsAnError) {
  ProfileOptions o;
  o.side = ProfileSide::Inside;
  o.depth = 2;
  o.step_down = 2;
  o.lead_radius = 8;  // the tool centre runs 7 mm from the hole's centre
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_profile({circle({0, 0}, 10)}, o, tp, d));
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("does not fit inside the contour"));
  o.lead_radius = 4;
  d.clear();
  EXPECT_TRUE(generate_profile({circle({0, 0}, 10)}, o, tp, d)) << first_message(d);
}

TEST(ProfileLimits, MoreMovesThanTheLimitIsRefused) {
  ProfileOptions o;
  o.depth = 9000;
  o.step_down = 1;
  o.cut.max_moves = 1e6;
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_profile({circle({0, 0}, 1000)}, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenTooMuchWork), 1) << first_message(d);
  EXPECT_TRUE(tp.ops().empty());
}

TEST(FromDxfLimits, MoreMovesThanTheLimitIsRefused) {
  FromDxfOptions o;
  o.cut.max_moves = 100;
  std::vector<Path> paths(40, circle({0, 0}, 10));
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_from_paths(paths, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenTooMuchWork), 1);
  o.cut.max_moves = kDefaultMaxMoves;
  d.clear();
  EXPECT_TRUE(generate_from_paths(paths, o, tp, d));
}

TEST(DrillLimits, APeckAsDeepAsTheHoleIsAWarningAndTheHoleIsDrilled) {
  DrillOptions o;
  o.depth = 5;
  o.retract = 1;
  o.peck = 6;  // the hole is 6 mm from the R plane
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_TRUE(generate_drill({{0, 0}}, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenNoEffect), 1);
  EXPECT_EQ(d.all().front().severity, core::Severity::Warning);
  o.peck = 5.9;
  d.clear();
  EXPECT_TRUE(generate_drill({{0, 0}}, o, tp, d));
  EXPECT_TRUE(d.all().empty());
}

TEST(DrillLimits, HolesTimesPecksBeyondTheLimitIsRefused) {
  DrillOptions o;
  o.depth = 50;
  o.peck = 0.01;  // 5100 pecks a hole
  std::vector<Vec2> holes;
  for (int i = 0; i < 2000; ++i)
    holes.push_back({static_cast<double>(i), 0});
  core::DiagnosticList d;
  canon::Toolpath tp;
  EXPECT_FALSE(generate_drill(holes, o, tp, d));
  EXPECT_EQ(count_code(d, core::Code::GenTooMuchWork), 1) << first_message(d);
  EXPECT_TRUE(tp.ops().empty());
}

TEST(EngraveLimits, TextOfSpacesOnlyIsAnErrorNotAnEmptyProgram) {
  core::DiagnosticList d;
  HersheyFont font;
  font.name = "blank";
  font.glyphs.resize(2);
  font.glyphs[1].strokes = {{{0, 0}, {0, 10}}};
  font.glyphs[1].right = 4;
  EngraveOptions o;
  o.text = "   ";
  canon::Toolpath tp;
  EXPECT_FALSE(generate_engrave(font, o, tp, d));
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("nothing to engrave"));
  o.text = "!";
  o.height = 0;
  d.clear();
  EXPECT_FALSE(generate_engrave(font, o, tp, d));
  EXPECT_THAT(first_message(d), ::testing::HasSubstr("the text height (--height) is 0 mm"));
  EXPECT_TRUE(tp.ops().empty());
}

}  // namespace
}  // namespace usina::cam
