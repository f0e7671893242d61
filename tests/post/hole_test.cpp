// Holes: a bare Hole (a generator's) is drilled by the post, as G81/G83 or
// as moves; a Hole with Origin::Cycle came with its moves and adds nothing.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "round_trip.hpp"

namespace usina {
namespace {

using test::op;
using testing::HasSubstr;

std::vector<canon::Op> bare_holes() {
  return {
      op(canon::Traverse{{0, 0, 10}}),
      op(canon::Feed{{0, 0, 5}, 120.0}),  // sets the feed the holes use
      op(canon::Hole{{20, 10, 2}, 6, 12}),
      op(canon::Hole{{40, 10, 2}, 6, 12}),
      op(canon::Traverse{{0, 0, 10}}),
      op(canon::ProgramEnd{}),
  };
}

TEST(PostHoles, CyclesWhereTheControlHasThem) {
  core::DiagnosticList diags;
  const std::string text = test::post_text(bare_holes(), "rs274ngc", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_THAT(text, HasSubstr("G81 X20 Y10 Z-10 R2\nX40 Y10\nG80\nG0 X0 Y0 Z10\n"));
  post::PostOptions o;
  o.peck = 3;
  EXPECT_THAT(test::post_text(bare_holes(), "fanuc", diags, o),
              HasSubstr("G83 X20. Y10. Z-10. R2. Q3.\nX40. Y10.\nG80\n"));
}

TEST(PostHoles, MovesWhereItHasNone) {
  core::DiagnosticList diags;
  const std::string text = test::post_text(bare_holes(), "grbl", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_THAT(text, HasSubstr("G0 X20 Y10\nZ2\nG1 Z-10\nG0 Z5\nX40\nZ2\nG1 Z-10\nG0 Z5\n"));
}

TEST(PostHoles, CycleAndMovesMakeTheSamePath) {
  core::DiagnosticList diags;
  for (const double peck : {0.0, 4.0}) {
    post::PostOptions o;
    o.peck = peck;
    const auto cycle = test::interpret(test::post_text(bare_holes(), "rs274ngc", diags, o));
    const auto moves = test::interpret(test::post_text(bare_holes(), "grbl", diags, o));
    test::expect_same_path(cycle, moves, 1e-6);
  }
  EXPECT_FALSE(diags.has_errors());
}

// A drilled hole, then a bored one of the same Z and R (a job's pilot and
// its bore, docs/post.md "Holes").
std::vector<canon::Op> drilled_then_bored() {
  return {
      op(canon::Traverse{{0, 0, 10}}),
      op(canon::Feed{{0, 0, 5}, 120.0}),
      op(canon::Hole{{20, 10, 2}, 6, 12}),
      op(canon::Hole{{40, 10, 2}, 10, 12, canon::HoleCycle::Bore}),
      op(canon::Hole{{60, 10, 2}, 10, 12, canon::HoleCycle::Bore}),
      op(canon::Traverse{{0, 0, 10}}),
      op(canon::ProgramEnd{}),
  };
}

TEST(PostHoles, ABoredHoleIsG85WithItsZAndRWrittenAgain) {
  core::DiagnosticList diags;
  post::PostOptions o;
  o.peck = 3;  // pecks a drilled hole, never a bore
  EXPECT_THAT(test::post_text(drilled_then_bored(), "rs274ngc", diags, o),
              HasSubstr("G83 X20 Y10 Z-10 R2 Q3\nG85 X40 Y10 Z-10 R2\nX60 Y10\nG80\n"));
  EXPECT_THAT(test::post_text(drilled_then_bored(), "grbl", diags),
              HasSubstr("X40\nZ2\nG1 Z-10\nZ2\nG0 Z5\nX60\n"));
  EXPECT_FALSE(diags.has_errors());
}

TEST(PostHoles, ABoreReadsBackTheSameInEveryControl) {
  core::DiagnosticList diags;
  const auto cycle = test::interpret(test::post_text(drilled_then_bored(), "rs274ngc", diags));
  for (const char* post : {"fanuc", "grbl", "romi"}) {
    const auto back = test::interpret_in(test::post_text(drilled_then_bored(), post, diags), post);
    ASSERT_TRUE(back) << post;
    test::expect_same_path(cycle, *back, 1e-3);
  }
  EXPECT_FALSE(diags.has_errors());
}

TEST(PostHoles, InterpreterHolesAreWrittenAsTheirMoves) {
  // A G81 read by the interpreter: its moves (Origin::Cycle) and its Hole.
  const auto ops = test::interpret("G0 X0 Y0 Z10\nG81 X5 Y5 Z-3 R1 F50\nG80\nM2\n");
  core::DiagnosticList diags;
  const std::string text = test::post_text(ops, "rs274ngc", diags);
  EXPECT_FALSE(diags.has_errors());
  EXPECT_THAT(text, testing::Not(HasSubstr("G81")));
  test::expect_same_path(ops, test::interpret(text), 1e-6);
}

TEST(PostHoles, NoFeedRateIsAnError) {
  core::DiagnosticList diags;
  test::post_text({op(canon::Traverse{{0, 0, 10}}), op(canon::Hole{{1, 1, 2}, 3, 4})}, "grbl",
                  diags);
  ASSERT_EQ(diags.error_count(), 1);
  EXPECT_THAT(diags.all()[0].message, HasSubstr("feed rate"));
}

}  // namespace
}  // namespace usina
