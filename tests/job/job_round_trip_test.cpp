// The example jobs (examples/jobs/) made into one program, posted for every
// control and read back by usina in that control's dialect: the same tool
// path (issue 16, extending GenRoundTrip), tool changes in order.
#include <gtest/gtest.h>

#include "../post/round_trip.hpp"
#include "canon/toolpath.hpp"
#include "job/make.hpp"
#include "job_test_util.hpp"

namespace usina::job {
namespace {

constexpr double kTol = 1e-3;  // fanuc and grbl write 3 decimals
constexpr const char* kPosts[] = {"rs274ngc", "fanuc", "grbl", "romi"};

canon::Toolpath made(const std::string& example, core::DiagnosticList& diags) {
  core::SourceManager sources;
  std::string io;
  const auto l = load_job(testing::repo("examples/jobs/" + example), sources, diags, io);
  EXPECT_TRUE(l) << io << (diags.all().empty() ? "" : diags.all()[0].message);
  canon::Toolpath tp;
  if (l) {
    EXPECT_TRUE(make_job(*l, tp, diags))
        << (diags.all().empty() ? "" : core::render(diags.all().back(), sources));
  }
  return tp;
}

std::vector<int> tool_changes(const canon::Toolpath& tp) {
  std::vector<int> out;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) out.push_back(t->tool);
  }
  return out;
}

// The bottoms of the bare holes (drilled holes: G81/G83 where the control
// has them, docs/post.md "Holes"), which the job's path holds as features.
std::vector<core::Vec3> hole_bottoms(const canon::Toolpath& tp) {
  std::vector<core::Vec3> out;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* h = std::get_if<canon::Hole>(&op.kind);
        h && op.origin == canon::Origin::Program)
      out.push_back({h->at.x, h->at.y, h->at.z - h->depth});
  }
  return out;
}

// `inner`'s points appear in `outer` in the same order (outer may have more).
void expect_in_order(const std::vector<core::Vec3>& inner, const std::vector<core::Vec3>& outer) {
  std::size_t j = 0;
  for (std::size_t i = 0; i < inner.size(); ++i) {
    while (j < outer.size() && core::distance(inner[i], outer[j]) >= kTol)
      ++j;
    ASSERT_LT(j, outer.size()) << "point " << i << " (" << inner[i].x << ", " << inner[i].y << ", "
                               << inner[i].z << ") is not on the path read back";
    ++j;
  }
}

// The job's path has its drilled holes as features, without moves: the
// reference is its rs274ngc program read back (the cycles expanded by
// LinuxCNC's rules), which must go through every move of the path and
// every hole's bottom; each control's program must read back to it.
void round_trip(const canon::Toolpath& tp) {
  core::DiagnosticList d0;
  const auto reference = test::interpret_in(test::post_text(tp.ops(), "rs274ngc", d0), "rs274ngc");
  ASSERT_TRUE(reference);
  const auto ref_ends = test::motion_ends(*reference, kTol);
  expect_in_order(test::motion_ends(tp.ops(), kTol), ref_ends);
  expect_in_order(hole_bottoms(tp), ref_ends);
  for (const char* post : kPosts) {
    SCOPED_TRACE(post);
    core::DiagnosticList diags;
    const std::string text = test::post_text(tp.ops(), post, diags);
    EXPECT_FALSE(diags.has_errors()) << (diags.all().empty() ? "" : diags.all()[0].message);
    if (const auto back = test::interpret_in(text, post)) {
      test::expect_same_path(*reference, *back, kTol);
    }
  }
}

TEST(JobRoundTrip, PlateHolesPocketProfile) {
  core::DiagnosticList diags;
  const canon::Toolpath tp = made("plate.toml", diags);
  // D5 drill, D6.8 drill (holes by diameter, smallest first), the D6 end
  // mill the R4 corners allow, the D10 named for the outline.
  EXPECT_EQ(tool_changes(tp), (std::vector<int>{6, 5, 2, 1}));
  // The D6's 12936 rev/min is above the machine's 10000: a note.
  EXPECT_NE(testing::find(diags, core::Code::JobCuttingLimited), nullptr);
  EXPECT_FALSE(diags.has_errors());
  round_trip(tp);
}

TEST(JobRoundTrip, EllipseCover) {
  core::DiagnosticList diags;
  const canon::Toolpath tp = made("ellipse_cover.toml", diags);
  // The ellipse's tightest curve is R7.5: the D10 fits, and the profile
  // names it too: one tool change.
  EXPECT_EQ(tool_changes(tp), (std::vector<int>{1}));
  EXPECT_FALSE(diags.has_errors());
  round_trip(tp);
}

TEST(JobRoundTrip, NameplateFacedEngravedDrilledCutOut) {
  core::DiagnosticList diags;
  const canon::Toolpath tp = made("nameplate.toml", diags);
  // The D50 face mill, the engraver (both lines: one change), the D5
  // drill, the D10 for the outline.
  EXPECT_EQ(tool_changes(tp), (std::vector<int>{10, 11, 6, 1}));
  EXPECT_FALSE(diags.has_errors());
  // The faced top: the deepest the face mill goes is -0.5.
  double deepest = 0;
  int tool = 0;
  for (const canon::Op& op : tp.ops()) {
    if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) tool = t->tool;
    if (const auto* f = std::get_if<canon::Feed>(&op.kind); f && tool == 10)
      deepest = std::min(deepest, f->to.z);
  }
  EXPECT_DOUBLE_EQ(deepest, -0.5);
  round_trip(tp);
}

TEST(JobRoundTrip, TappingReadsBackInEveryControl) {
  // The plate's M8 holes drilled, then tapped: the spindle reverses at each
  // bottom, and every post writes that back as the control reads it.
  const auto l = testing::load_text(testing::job_text(
      "[[operation]]\ntype = \"drill\"\nlayer = \"HOLES\"\ndiameter = 6.8\ndepth = 12.0\n"
      "tool = \"auto\"\n[[operation]]\ntype = \"tap\"\nlayer = \"HOLES\"\ndiameter = 6.8\n"
      "depth = 10.0\nrpm = 300\ntool = \"auto\"\n"));
  ASSERT_TRUE(l->job);
  core::DiagnosticList diags;
  canon::Toolpath tp;
  ASSERT_TRUE(make_job(*l->job, tp, diags)) << (diags.all().empty() ? "" : diags.all()[0].message);
  EXPECT_EQ(tool_changes(tp), (std::vector<int>{5, 9}));
  round_trip(tp);
}

TEST(JobRoundTrip, BearingPlatePilotsBoredCutOut) {
  core::DiagnosticList diags;
  const canon::Toolpath tp = made("bearing_plate.toml", diags);
  // The D8.5 drill for the pilots, the boring head set to D10, the bar set
  // to D12, the D10 end mill for the outline.
  EXPECT_EQ(tool_changes(tp), (std::vector<int>{7, 13, 14, 1}));
  EXPECT_FALSE(diags.has_errors());
  round_trip(tp);
}

TEST(JobRoundTrip, OneProgramEnd) {
  core::DiagnosticList diags;
  const canon::Toolpath tp = made("plate.toml", diags);
  int ends = 0;
  for (const canon::Op& op : tp.ops())
    ends += std::holds_alternative<canon::ProgramEnd>(op.kind) ? 1 : 0;
  EXPECT_EQ(ends, 1);
  ASSERT_FALSE(tp.ops().empty());
  EXPECT_TRUE(std::holds_alternative<canon::ProgramEnd>(tp.ops().back().kind));
}

}  // namespace
}  // namespace usina::job
