// The posts on a small canon program that uses every op they write. The
// expected texts were checked by hand against each control's rules
// (docs/post.md): modal words only on change, I J from the start point
// (romi: absolute), G2/G3 from the sign of turn × normal, the helix's extra
// turn as P (rs274ngc) or as a full circle first (the others), F rounded.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "round_trip.hpp"

namespace usina {
namespace {

using test::op;
using testing::HasSubstr;
using testing::Not;

std::vector<canon::Op> sample() {
  return {
      op(canon::Comment{"sample (with parentheses)"}),
      op(canon::ToolChange{2, 6.0}),
      op(canon::Spindle{1200, canon::SpindleDir::Cw}),
      op(canon::Coolant{false, true}),
      op(canon::Traverse{{10, 0, 5}}),
      op(canon::Feed{{10, 0, -1}, 100.0}),
      op(canon::Feed{{20, 0, -1}, 200.0}),
      op(canon::Feed{{20, 0, -1}, 200.0}),  // no move: no block
      // From (20,0) about (20,10) counter-clockwise to (30,10): G3.
      op(canon::Arc{{30, 10, -1}, {20, 10, -1}, {0, 0, 1}, 1, 200.0}),
      // Seen from −Z a counter-clockwise arc is clockwise from +Z: G2.
      op(canon::Arc{{40, 0, -1}, {30, 0, -1}, {0, 0, -1}, 1, 200.0}),
      // Two turns of a helix down 3 mm about (30,0) back to (40,0).
      op(canon::Arc{{40, 0, -4}, {30, 0, -1}, {0, 0, 1}, 2, 200.0}),
      op(canon::Dwell{0.5}),
      op(canon::Traverse{{40, 0, 5}}),
      op(canon::Coolant{}),
      op(canon::Spindle{0, canon::SpindleDir::Off}),
      op(canon::ProgramEnd{}),
  };
}

TEST(Post, Rs274ngcGolden) {
  core::DiagnosticList diags;
  const std::string text = test::post_text(sample(), "rs274ngc", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_EQ(text,
            "(program 1000)\n"
            "G21 G17 G90 G94 G40 G49 G80 G98\n"
            "(sample with parentheses)\n"
            "(tool 2 d6)\n"
            "T2 M6\n"
            "S1200 M3\n"
            "M8\n"
            "G0 X10 Y0 Z5\n"
            "G1 Z-1 F100\n"
            "X20 F200\n"
            "G3 X30 Y10 I0 J10\n"
            "G2 X40 Y0 I0 J-10\n"
            "G3 Z-4 I-10 J0 P2\n"
            "G4 P0.5\n"
            "G0 Z5\n"
            "M9\n"
            "M5\n"
            "M30\n");
}

TEST(Post, FanucWritesPointsPercentAndONumber) {
  core::DiagnosticList diags;
  const std::string text = test::post_text(sample(), "fanuc", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_THAT(text, testing::StartsWith("%\nO1000\n"));
  EXPECT_THAT(text, testing::EndsWith("M30\n%\n"));
  EXPECT_THAT(text, HasSubstr("G00 X10. Y0. Z5.\n"));
  EXPECT_THAT(text, HasSubstr("S1200 M03\n"));
  EXPECT_THAT(text, HasSubstr("G04 X0.5\n"));
  // The two-turn helix: one full circle down to half the drop, then the rest.
  EXPECT_THAT(text, HasSubstr("G03 Z-2.5 I-10. J0.\nZ-4. I-10. J0.\n"));
}

TEST(Post, GrblPausesForTheToolAndHasNoONumber) {
  core::DiagnosticList diags;
  const std::string text = test::post_text(sample(), "grbl", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_THAT(text, HasSubstr("(change to tool 2)\nM0\n"));
  EXPECT_THAT(text, Not(HasSubstr("M6")));
  EXPECT_THAT(text, Not(HasSubstr("O1000")));
  post::PostOptions o;
  o.tool_change = true;
  EXPECT_THAT(test::post_text(sample(), "grbl", diags, o), HasSubstr("T2 M6\n"));
}

TEST(Post, RomiNumbersBlocksAndWritesAbsoluteCentres) {
  core::DiagnosticList diags;
  // Romi has no dwell but its drilling cycle's (ADwellForRomiIsRefused...).
  std::vector<canon::Op> ops = sample();
  std::erase_if(ops,
                [](const canon::Op& o) { return std::holds_alternative<canon::Dwell>(o.kind); });
  const std::string text = test::post_text(ops, "romi", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_THAT(text, testing::StartsWith("N0010 ;program 1000#\nN0020 G90#\nN0030 G71#\n"));
  EXPECT_THAT(text, HasSubstr(" T2 M06;tool 2 d6#\n"));
  EXPECT_THAT(text, HasSubstr(" G03 X30 Y10 I20 J10#\n"));  // centre (20,10) absolute
  EXPECT_THAT(text, HasSubstr(" G02 X40 Y0 I30 J0#\n"));
  EXPECT_THAT(text, testing::EndsWith("M02#\n"));
}

std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
    ++n;
  return n;
}

// A program ends with one spindle stop and one coolant off: its own when it
// stopped them last (a generator's program does), the footer's otherwise.
TEST(Post, ProgramEndsWithOneSpindleStopAndOneCoolantOff) {
  struct Case {
    const char* post;
    const char* stop;  // M5 as a whole block of this control
    const char* off;   // M9 likewise
  };

  constexpr Case kPosts[] = {{"rs274ngc", "\nM5\n", "\nM9\n"},
                             {"grbl", "\nM5\n", "\nM9\n"},
                             {"fanuc", "\nM05\n", "\nM09\n"},
                             {"romi", " M05#", " M09#"}};
  const auto on = op(canon::Spindle{1000, canon::SpindleDir::Cw});
  const auto stop = op(canon::Spindle{0, canon::SpindleDir::Off});
  const auto flood = op(canon::Coolant{false, true});
  const auto dry = op(canon::Coolant{});
  const auto move = op(canon::Traverse{{1, 2, 3}});
  const auto end = op(canon::ProgramEnd{});
  for (const Case& c : kPosts) {
    SCOPED_TRACE(c.post);
    core::DiagnosticList diags;
    const std::string stopped = test::post_text({on, flood, move, dry, stop, end}, c.post, diags);
    EXPECT_EQ(occurrences(stopped, c.stop), 1u) << stopped;
    EXPECT_EQ(occurrences(stopped, c.off), 1u) << stopped;
    const std::string left_on = test::post_text({on, flood, move, end}, c.post, diags);
    EXPECT_EQ(occurrences(left_on, c.stop), 1u) << left_on;
    EXPECT_EQ(occurrences(left_on, c.off), 1u) << left_on;
    EXPECT_LT(left_on.rfind(c.stop), left_on.rfind(c.off)) << left_on;  // M5 M9, then the end
    // Stopped and started again: a second stop at the end.
    const std::string restarted = test::post_text({on, move, stop, on, move, end}, c.post, diags);
    EXPECT_EQ(occurrences(restarted, c.stop), 2u) << restarted;
    EXPECT_FALSE(diags.has_errors());
  }
}

TEST(Post, NumbersUseTheControlsDecimals) {
  core::DiagnosticList diags;
  const std::vector<canon::Op> ops{op(canon::Traverse{{1.23456, -0.00001, 2.5}})};
  EXPECT_THAT(test::post_text(ops, "rs274ngc", diags), HasSubstr("G0 X1.2346 Y0 Z2.5\n"));
  EXPECT_THAT(test::post_text(ops, "fanuc", diags), HasSubstr("G00 X1.235 Y0. Z2.5\n"));
  post::PostOptions o;
  o.decimals = 1;
  EXPECT_THAT(test::post_text(ops, "grbl", diags, o), HasSubstr("G0 X1.2 Y0 Z2.5\n"));
  o.decimals = 0;
  EXPECT_THAT(test::post_text(ops, "fanuc", diags, o), HasSubstr("G00 X1. Y0. Z3.\n"));
  EXPECT_THAT(test::post_text(ops, "rs274ngc", diags, o), HasSubstr("G0 X1 Y0 Z3\n"));
}

TEST(Post, FullCircles) {
  core::DiagnosticList diags;
  const std::vector<canon::Op> ops{op(canon::Traverse{{10, 0, 0}}),
                                   op(canon::Arc{{10, 0, -2}, {0, 0, 0}, {0, 0, 1}, 1, 100.0})};
  EXPECT_THAT(test::post_text(ops, "rs274ngc", diags), HasSubstr("G3 Z-2 I-10 J0 F100\n"));
  // romi: two halves through the opposite point, the centre absolute.
  EXPECT_THAT(test::post_text(ops, "romi", diags),
              HasSubstr(" G03 X-10 Z-1 I0 J0 F100#\nN0080 X10 Z-2 I0 J0#\n"));
  EXPECT_FALSE(diags.has_errors());
  test::expect_same_path(test::interpret(test::post_text(ops, "rs274ngc", diags)),
                         test::interpret(test::post_text(ops, "grbl", diags)), 1e-3);
}

TEST(Post, LineNumbersOnRequest) {
  core::DiagnosticList diags;
  post::PostOptions o;
  o.line_numbers = true;
  const std::string text = test::post_text({op(canon::Traverse{{1, 2, 3}})}, "rs274ngc", diags, o);
  EXPECT_THAT(text, HasSubstr("N20 G21"));
  EXPECT_THAT(text, HasSubstr("N30 G0 X1 Y2 Z3\n"));
}

TEST(Post, UnknownControlIsNull) {
  core::DiagnosticList diags;
  std::ostringstream out;
  EXPECT_EQ(post::make_post("heidenhain", out, {}, diags), nullptr);
}

TEST(Post, WhatAControlCannotExpressIsAnError) {
  core::DiagnosticList diags;
  test::post_text({op(canon::Traverse{{0, 0, 0}}), op(canon::Probe{{0, 0, -5}})}, "romi", diags);
  ASSERT_EQ(diags.error_count(), 1);
  EXPECT_THAT(diags.all()[0].message, HasSubstr("probing"));
  diags.clear();
  test::post_text({op(canon::Traverse{{0, 0, 0}, {90, 0, 0}})}, "grbl", diags);
  EXPECT_EQ(diags.error_count(), 1);
  diags.clear();
  test::post_text({op(canon::Traverse{{0, 0, 0}}), op(canon::Feed{{1, 0, 0}, std::nullopt})},
                  "rs274ngc", diags);
  EXPECT_EQ(diags.error_count(), 1);
  diags.clear();
  test::post_text({op(canon::Arc{{1, 1, 0}, {0, 0, 0}, {0.6, 0.8, 0}, 1, 100.0})}, "fanuc", diags);
  EXPECT_EQ(diags.error_count(), 1);
  diags.clear();
  test::post_text({op(canon::Hole{{0, 0, 0}, 5, 3})}, "rs274ngc", diags);  // no position yet
  EXPECT_EQ(diags.error_count(), 1);
}

TEST(Post, RotaryAxesAreWrittenWhenTheyMove) {
  core::DiagnosticList diags;
  const std::string text =
      test::post_text({op(canon::Traverse{{0, 0, 0}}), op(canon::Traverse{{0, 0, 0}, {90, 0, 0}})},
                      "rs274ngc", diags);
  EXPECT_THAT(text, HasSubstr("G0 X0 Y0 Z0\nA90\n"));
}

TEST(Post, RoundTripThroughTheInterpreter) {
  core::DiagnosticList diags;
  const std::vector<canon::Op> ops = sample();
  const std::string text = test::post_text(ops, "rs274ngc", diags);
  test::expect_same_path(ops, test::interpret(text), 1e-4);
}

TEST(Post, ARotaryMoveIsReportedOnceNotForEveryLaterMove) {
  core::DiagnosticList diags;
  test::post_text({op(canon::Traverse{{0, 0, 5}}), op(canon::Feed{{10, 0, 0}, 100.0, {90, 0, 0}}),
                   op(canon::Feed{{20, 0, 0}, 100.0, {90, 0, 0}}),
                   op(canon::Arc{{30, 0, 0}, {25, 0, 0}, {0, 0, 1}, 1, 100.0, {90, 0, 0}}),
                   op(canon::Feed{{40, 0, 0}, 100.0, {0, 0, 0}})},
                  "grbl", diags);
  // Two moves of A: to 90, and back to 0.
  EXPECT_EQ(diags.all().size(), 2u);
  for (const core::Diagnostic& d : diags.all())
    EXPECT_EQ(d.code, core::Code::Unsupported);
}

// spec/romi.md has no G04: its only dwell is G81's D, so a program's dwell
// is refused, not written as a block romi's own reader rejects.
TEST(Post, ADwellForRomiIsRefusedAndWrittenForTheOthers) {
  const std::vector<canon::Op> ops = {op(canon::Traverse{{0, 0, 5}}), op(canon::Dwell{1.5}),
                                      op(canon::Traverse{{10, 0, 5}})};
  core::DiagnosticList romi;
  const std::string text = test::post_text(ops, "romi", romi);
  ASSERT_EQ(romi.all().size(), 1u);
  EXPECT_EQ(romi.all()[0].code, core::Code::Unsupported);
  EXPECT_NE(romi.all()[0].message.find("dwell"), std::string::npos) << romi.all()[0].message;
  EXPECT_EQ(text.find("G04"), std::string::npos) << text;
  core::DiagnosticList fanuc;
  EXPECT_NE(test::post_text(ops, "fanuc", fanuc).find("G04"), std::string::npos);
  EXPECT_TRUE(fanuc.all().empty());
}

}  // namespace
}  // namespace usina
