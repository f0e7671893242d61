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

// A generator's hole carries its feed rate: no feed move is needed before
// it, the cycle's F is the hole's, and the moves of a control without
// cycles feed at it; a hole without one takes the last feed move's.
std::vector<canon::Op> holes_with_feed() {
  canon::Hole own{{20, 10, 2}, 6, 12};
  own.f = 75.0;
  canon::Hole bored{{40, 10, 2}, 10, 12, canon::HoleCycle::Bore};
  bored.f = 9.5;
  return {
      op(canon::Traverse{{20, 10, 10}}),
      op(own),
      op(bored),
      op(canon::Hole{{60, 10, 2}, 10, 12}),
      op(canon::Traverse{{0, 0, 10}}),
      op(canon::ProgramEnd{}),
  };
}

TEST(PostHoles, AHoleCarriesItsFeedRate) {
  core::DiagnosticList diags;
  EXPECT_THAT(test::post_text(holes_with_feed(), "fanuc", diags),
              HasSubstr("G00 X20. Y10. Z10.\nG81 X20. Y10. Z-10. R2. F75.\n"
                        "G85 X40. Y10. Z-10. R2. F9.5\nG81 X60. Y10. Z-10. R2.\nG80\n"));
  EXPECT_THAT(test::post_text(holes_with_feed(), "grbl", diags),
              HasSubstr("Z2\nG1 Z-10 F75\nG0 Z10\nX40\nZ2\nG1 Z-10 F9.5\nZ2\nG0 Z10\nX60\nZ2\n"
                        "G1 Z-10\nG0 Z10\n"));
  EXPECT_FALSE(diags.has_errors());
  const auto cycle = test::interpret(test::post_text(holes_with_feed(), "rs274ngc", diags));
  for (const char* post : {"fanuc", "grbl", "romi"}) {
    const auto back = test::interpret_in(test::post_text(holes_with_feed(), post, diags), post);
    ASSERT_TRUE(back) << post;
    test::expect_same_path(cycle, *back, 1e-3);
  }
}

// After a G89 (written in G99) the next cycle is in G98 again; a G86 needs
// the spindle turning.
TEST(PostHoles, AfterAG89TheNextCycleIsG98Again) {
  canon::Hole dwell{{20, 10, 2}, 10, 12, canon::HoleCycle::BoreDwell, 9.5, 0.25};
  canon::Hole drill{{40, 10, 2}, 6, 12, canon::HoleCycle::Drill, 75.0};
  const std::vector<canon::Op> ops{op(canon::Spindle{800, canon::SpindleDir::Cw}),
                                   op(canon::Traverse{{20, 10, 10}}), op(dwell), op(drill),
                                   op(canon::ProgramEnd{})};
  core::DiagnosticList diags;
  EXPECT_THAT(test::post_text(ops, "rs274ngc", diags),
              HasSubstr("G99 G89 X20 Y10 Z-10 R2 P0.25 F9.5\nG80\nG0 Z10\n"
                        "G98 G81 X40 Y10 Z-10 R2 F75\nG80\n"));
  EXPECT_FALSE(diags.has_errors());
  const auto cycle = test::interpret(test::post_text(ops, "rs274ngc", diags));
  for (const char* post : {"fanuc", "grbl"}) {
    const auto back = test::interpret_in(test::post_text(ops, post, diags), post);
    ASSERT_TRUE(back) << post;
    test::expect_same_path(cycle, *back, 1e-3);
  }
  EXPECT_FALSE(diags.has_errors());
  // romi has no dwell but G81's, which rapids out: the bore is refused.
  test::post_text(ops, "romi", diags);
  ASSERT_EQ(diags.error_count(), 1);
  EXPECT_THAT(diags.all()[0].message, HasSubstr("romi post cannot write a bore's dwell"));
}

TEST(PostHoles, AG86WithTheSpindleStoppedIsAnError) {
  core::DiagnosticList diags;
  test::post_text({op(canon::Traverse{{0, 0, 10}}),
                   op(canon::Hole{{1, 1, 2}, 3, 4, canon::HoleCycle::BoreStop, 50.0})},
                  "rs274ngc", diags);
  ASSERT_EQ(diags.error_count(), 1);
  EXPECT_THAT(diags.all()[0].message, HasSubstr("spindle stopped"));
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
