// Moves a program fed other than in mm/min (G93 inverse time, G95 per
// revolution) through the posts: what each control is given. The figures are
// worked by hand in the comments.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "round_trip.hpp"

namespace usina {
namespace {

using testing::HasSubstr;
using testing::Not;

std::string posted(const std::string& program, const std::string& post,
                   core::DiagnosticList& diags) {
  return test::post_text(test::interpret(program), post, diags);
}

std::vector<double> feeds_of(const std::vector<canon::Op>& ops) {
  std::vector<double> f;
  for (const canon::Op& op : ops) {
    if (const auto* m = std::get_if<canon::Feed>(&op.kind); m && m->f) f.push_back(*m->f);
    if (const auto* a = std::get_if<canon::Arc>(&op.kind); a && a->f) f.push_back(*a->f);
  }
  return f;
}

TEST(PostFeedMode, InverseTimeOfXyzBecomesTheMmPerMinuteOfTheSameTime) {
  // 50 mm (3-4-5) in 1/2 min: 100 mm/min. A half circle of radius 10
  // (31.4159 mm) in 1/3 min: 94.248 mm/min.
  const std::string program =
      "G21 G90 G0 X0 Y0 Z0\nG93 G1 X30 Y40 F2\nG2 X50 Y40 I10 J0 F3\nG94 G1 X0 F500\nM2\n";
  for (const char* post : {"rs274ngc", "fanuc", "grbl", "romi"}) {
    SCOPED_TRACE(post);
    core::DiagnosticList diags;
    const std::string text = posted(program, post, diags);
    EXPECT_FALSE(diags.has_errors());
    EXPECT_THAT(text, Not(HasSubstr("G93")));
    const auto back = test::interpret_in(text, post);
    ASSERT_TRUE(back.has_value());
    const std::vector<double> f = feeds_of(*back);
    ASSERT_EQ(f.size(), 3u);
    EXPECT_NEAR(f[0], 100.0, 1e-3);
    EXPECT_NEAR(f[1], 94.248, 1e-3);
    EXPECT_NEAR(f[2], 500.0, 1e-3);
  }
}

TEST(PostFeedMode, InverseTimeWithARotaryAxisStaysG93) {
  const std::string program = "G21 G90 G0 X0 A0\nG93 G1 X10 A90 F4\nG94 G1 X20 F300\nM2\n";
  core::DiagnosticList diags;
  const std::string text = posted(program, "rs274ngc", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_THAT(text, HasSubstr("G93 G1 X10 A90 F4\n"));
  EXPECT_THAT(text, HasSubstr("G94 X20 F300\n"));
}

TEST(PostFeedMode, InverseTimeRotaryOnAControlWithoutG93IsAnError) {
  core::DiagnosticList diags;
  posted("G21 G90 G0 X0 A0\nG93 G1 X10 A90 F4\nM2\n", "fanuc", diags);
  EXPECT_FALSE(diags.has_errors());  // Fanuc has G93
  core::DiagnosticList romi;
  posted("G21 G90 G0 X0\nG93 G1 X10 A90 F4\nM2\n", "romi", romi);
  EXPECT_TRUE(romi.has_errors());  // romi has neither G93 nor A
}

TEST(PostFeedMode, PerRevolutionStaysG95WhereTheControlHasIt) {
  const std::string program = "G21 G90 G0 X0 Y0\nS1000 M3\nG95 G1 X10 F0.1\nG94 X20 F300\nM2\n";
  core::DiagnosticList diags;
  const std::string text = posted(program, "fanuc", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_THAT(text, HasSubstr("G95 G01 X10. F0.1\n"));
  EXPECT_THAT(text, HasSubstr("G94 X20. F300.\n"));
}

TEST(PostFeedMode, PerRevolutionBecomesMmPerMinuteAtTheSpindleSpeed) {
  // Grbl has no G95: 0.1 mm/rev at 1000 rpm is 100 mm/min.
  const std::string program = "G21 G90 G0 X0 Y0\nS1000 M3\nG95 G1 X10 F0.1\nM2\n";
  core::DiagnosticList diags;
  const std::string text = posted(program, "grbl", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_THAT(text, Not(HasSubstr("G95")));
  EXPECT_THAT(text, HasSubstr("X10 F100\n"));
}

TEST(PostFeedMode, PerRevolutionWithTheSpindleStoppedIsAnErrorWithoutG95) {
  core::DiagnosticList diags;
  posted("G21 G90 G0 X0 Y0\nG95 G1 X10 F0.1\nM2\n", "grbl", diags);
  EXPECT_TRUE(diags.has_errors());
}

}  // namespace
}  // namespace usina
