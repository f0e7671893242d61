// Every generator of this module through every post, then read back by
// usina in that post's dialect: the same tool path (issue 5, "the round
// trip"). A dialect usina does not read yet is skipped, and says so.
#include <gtest/gtest.h>

#include "../post/round_trip.hpp"
#include "cam/chain.hpp"
#include "cam/drill.hpp"
#include "cam/dxf_import.hpp"
#include "cam/engrave.hpp"
#include "cam/from_dxf.hpp"
#include "cam/pocket.hpp"
#include "cam/profile.hpp"

namespace usina::cam {
namespace {

// fanuc and grbl round every axis to 3 decimals, so a point moves by up to
// 0.0005 mm on each axis, 0.0005·√3 in space.
constexpr double kTol = 1e-3;

constexpr const char* kPosts[] = {"rs274ngc", "fanuc", "grbl", "romi"};

// The dialects that are not read yet, for GTEST_SKIP.
std::string unread_dialects() {
  std::string out;
  for (const char* post : kPosts) {
    if (gcode::find_dialect(post) == nullptr) out += std::string(out.empty() ? "" : ", ") + post;
  }
  return out;
}

void round_trip(const canon::Toolpath& tp) {
  ASSERT_GT(tp.size(), 3u);
  for (const char* post : kPosts) {
    SCOPED_TRACE(post);
    core::DiagnosticList diags;
    const std::string text = test::post_text(tp.ops(), post, diags);
    EXPECT_FALSE(diags.has_errors());
    if (const auto back = test::interpret_in(text, post)) {
      test::expect_same_path(tp.ops(), *back, kTol);
    }
  }
  if (const std::string missing = unread_dialects(); !missing.empty())
    GTEST_SKIP() << "not read back yet: " << missing;
}

std::vector<Path> slot() {
  core::DiagnosticList d;
  DxfOptions o;
  o.layer = "SLOT";
  return chain(*read_dxf(std::string(USINA_TEST_DIR) + "/programs/dxf/arcs_bulges.dxf", o, d));
}

TEST(GenRoundTrip, FromDxfOnTheLineAndOffset) {
  for (const Side side : {Side::On, Side::Left}) {
    canon::Toolpath tp;
    core::DiagnosticList d;
    FromDxfOptions o;
    o.side = side;
    o.cut.tool_diameter = 3;
    ASSERT_TRUE(generate_from_paths(slot(), o, tp, d));
    round_trip(tp);
  }
}

TEST(GenRoundTrip, PocketWithAnIsland) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  PocketOptions o;
  o.depth = 4;
  o.step_down = 2;
  o.stepover = 3;
  ASSERT_TRUE(generate_pocket({rectangle({0, 0}, 60, 40, 5), {circle({10, 0}, 6)}}, o, tp, d));
  round_trip(tp);
}

TEST(GenRoundTrip, ProfileWithLeadsAndTabs) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  ProfileOptions o;
  o.depth = 6;
  o.step_down = 2;
  o.lead_radius = 4;
  o.tabs = {3, 4, 1.5};
  ASSERT_TRUE(generate_profile(slot(), o, tp, d));
  round_trip(tp);
}

TEST(GenRoundTrip, DrillMovesAndPecks) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  DrillOptions o;
  o.peck = 2.5;
  ASSERT_TRUE(generate_drill(bolt_circle({0, 0}, 25, 5, 10), o, tp, d));
  round_trip(tp);
}

TEST(GenRoundTrip, DrillFeaturesBecomeCyclesThatReachTheBottom) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  DrillOptions o;
  o.form = HoleForm::Features;
  const auto holes = grid({0, 0}, 3, 2, 10, 10);
  ASSERT_TRUE(generate_drill(holes, o, tp, d));
  for (const char* post : kPosts) {
    SCOPED_TRACE(post);
    core::DiagnosticList diags;
    const auto back = test::interpret_in(test::post_text(tp.ops(), post, diags), post);
    if (!back) continue;
    const auto ends = test::motion_ends(*back, kTol);
    for (const Vec2& h : holes) {
      const bool reached = std::any_of(ends.begin(), ends.end(), [&](const Vec3& e) {
        return core::distance(e, Vec3{h.x, h.y, -o.depth}) < kTol;
      });
      EXPECT_TRUE(reached) << h.x << ", " << h.y;
    }
  }
  if (const std::string missing = unread_dialects(); !missing.empty())
    GTEST_SKIP() << "not read back yet: " << missing;
}

TEST(GenRoundTrip, Engrave) {
  canon::Toolpath tp;
  core::DiagnosticList d;
  const auto font = read_hershey(hershey_file("rowmans"), d);
  ASSERT_TRUE(font);
  EngraveOptions o;
  o.text = "CNC 7.5";
  ASSERT_TRUE(generate_engrave(*font, o, tp, d));
  round_trip(tp);
}

}  // namespace
}  // namespace usina::cam
