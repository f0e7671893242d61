// The entry below the text (interp/evaluated_block.hpp): blocks of
// evaluated words handed to the interpreter by a front end, without program
// text; words marked as increments (romi's lower-case words) on moves to a
// point, and refused where the interpreter reads axis words another way.
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "support/interp_run.hpp"

namespace usina::gcode::interp_test {
namespace {

// An interpreter fed block by block, as a dialect's front end feeds it.
struct Fed {
  explicit Fed(const InterpOptions& options = {}) : interp{sources, options, path, diags} {}

  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  Interpreter interp;
  std::uint32_t line = 0;

  bool block(std::vector<EvaluatedWord> words) {
    ++line;
    return interp.run_evaluated({{0, line, 1, 0, 0}, words, {}, {}});
  }

  std::vector<Vec3> ends() const { return motion_ends(path); }

  const core::Diagnostic* first() const {
    return diags.all().empty() ? nullptr : &diags.all().front();
  }
};

EvaluatedWord inc(char letter, double value, std::uint32_t col) {
  return {letter, value, col, true};
}

TEST(EvaluatedEntry, AMarkedAxisWordCountsFromTheStartUnderG90) {
  Fed f;
  ASSERT_TRUE(f.block({{'G', 90, 1}, {'G', 0, 4}, {'X', 10, 7}, {'Y', 5, 11}}));
  // X written as an increment, Y absolute, in one G90 block.
  ASSERT_TRUE(f.block({{'G', 1, 1}, inc('X', 2.5, 5), {'Y', 1, 10}, {'F', 100, 13}}));
  ASSERT_TRUE(f.interp.finish());
  const auto e = f.ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[1], 12.5, 1, 0);
}

TEST(EvaluatedEntry, AMarkedWordIsForItsBlockAlone) {
  Fed f;
  ASSERT_TRUE(f.block({{'G', 0, 1}, {'X', 10, 4}}));
  ASSERT_TRUE(f.block({{'G', 0, 1}, inc('X', 1, 4)}));
  ASSERT_TRUE(f.block({{'G', 0, 1}, {'X', 1, 4}}));
  const auto e = f.ends();
  ASSERT_EQ(e.size(), 3u);
  EXPECT_VEC(e[1], 11, 0, 0);
  EXPECT_VEC(e[2], 1, 0, 0);
}

TEST(EvaluatedEntry, AMarkedArcEndCountsFromTheArcsStart) {
  Fed f;
  ASSERT_TRUE(f.block({{'G', 0, 1}, {'X', 10, 4}, {'Y', 0, 8}}));
  // A half circle of radius 5 about (15, 0): I is relative as always.
  ASSERT_TRUE(f.block({{'G', 3, 1}, inc('X', 10, 5), {'I', 5, 10}, {'J', 0, 13}, {'F', 100, 16}}));
  const auto e = f.ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[1], 20, 0, 0);
}

TEST(EvaluatedEntry, AMarkedWordUnderG91IsStillOneIncrement) {
  Fed f;
  ASSERT_TRUE(f.block({{'G', 91, 1}, {'G', 0, 5}, {'X', 3, 8}}));
  ASSERT_TRUE(f.block({{'G', 0, 1}, inc('X', 3, 4)}));
  const auto e = f.ends();
  ASSERT_EQ(e.size(), 2u);
  EXPECT_VEC(e[1], 6, 0, 0);
}

TEST(EvaluatedEntry, AMarkedWordThatIsNoAxisIsRefusedAtItsColumn) {
  Fed f;
  EXPECT_FALSE(f.block({{'G', 1, 1}, {'X', 1, 5}, inc('F', 100, 9)}));
  ASSERT_NE(f.first(), nullptr);
  EXPECT_EQ(f.first()->code, Code::NotAllowedInMode);
  EXPECT_EQ(f.first()->loc.col, 9u);
  EXPECT_TRUE(f.ends().empty());
}

TEST(EvaluatedEntry, AMarkedWordOfACannedCycleIsRefused) {
  Fed f;
  EXPECT_FALSE(f.block({{'G', 81, 1}, inc('X', 5, 5), {'Z', -2, 9}, {'R', 1, 13}, {'F', 50, 16}}));
  ASSERT_NE(f.first(), nullptr);
  EXPECT_EQ(f.first()->code, Code::NotAllowedInMode);
  EXPECT_EQ(f.first()->loc.col, 5u);
  EXPECT_TRUE(f.ends().empty());
}

TEST(EvaluatedEntry, AMarkedWordOfG92OrG53IsRefused) {
  {
    Fed f;
    EXPECT_FALSE(f.block({{'G', 92, 1}, inc('X', 5, 5)}));
    ASSERT_NE(f.first(), nullptr);
    EXPECT_EQ(f.first()->code, Code::NotAllowedInMode);
  }
  {
    Fed f;
    EXPECT_FALSE(f.block({{'G', 53, 1}, {'G', 0, 5}, inc('Z', 5, 8)}));
    ASSERT_NE(f.first(), nullptr);
    EXPECT_EQ(f.first()->code, Code::NotAllowedInMode);
    EXPECT_EQ(f.first()->loc.col, 8u);
  }
}

TEST(EvaluatedEntry, G28TakesAMarkedIntermediatePoint) {
  Fed f;
  ASSERT_TRUE(f.block({{'G', 0, 1}, {'X', 10, 4}}));
  ASSERT_TRUE(f.block({{'G', 28, 1}, inc('X', 5, 5)}));
  const auto e = f.ends();
  ASSERT_GE(e.size(), 2u);
  EXPECT_VEC(e[1], 15, 0, 0);  // the intermediate point, then home
}

TEST(EvaluatedEntry, ARefusedBlockLeavesTheModesAsTheyWere) {
  Fed f;
  EXPECT_FALSE(f.block({{'G', 91, 1}, {'G', 81, 5}, inc('X', 5, 9), {'Z', -2, 12}, {'R', 1, 15}}));
  EXPECT_FALSE(f.interp.state().incremental);
}

// A checkpoint just before a block holds the state the block puts back
// when it fails (Grbl's lines take no second copy); a later block without
// a checkpoint of its own puts back its own start, not the checkpoint's.
TEST(EvaluatedEntry, ABlockRefusedAfterACheckpointPutsBackItsOwnStart) {
  Fed f;
  f.interp.checkpoint();
  // G91 is in force when the move finds no feed rate, inside the block.
  EXPECT_FALSE(f.block({{'G', 91, 1}, {'G', 1, 5}, {'X', 10, 8}}));
  EXPECT_FALSE(f.interp.state().incremental);
  f.interp.roll_back();
  f.interp.checkpoint();
  ASSERT_TRUE(f.block({{'G', 91, 1}}));
  EXPECT_FALSE(f.block({{'G', 90, 1}, {'G', 1, 5}, {'X', 10, 8}}));
  EXPECT_TRUE(f.interp.state().incremental);
}

// Every op but those of block `skip`: its kind, end point and feed rate.
std::vector<std::string> moves_but(const canon::Toolpath& path, std::uint32_t skip) {
  std::vector<std::string> out;
  for (const canon::Op& op : path.ops()) {
    if (op.src.line == skip) continue;
    std::string move = canon::op_name(op.kind);
    if (const auto* t = std::get_if<canon::Traverse>(&op.kind))
      move += fmt::format(" {} {} {}", t->to.x, t->to.y, t->to.z);
    if (const auto* f = std::get_if<canon::Feed>(&op.kind))
      move += fmt::format(" {} {} {} F{}", f->to.x, f->to.y, f->to.z, f->f.value_or(-1));
    out.push_back(move);
  }
  return out;
}

// A plain move the interpreter took, then refused by the front end (as
// Grbl's soft limits refuse a line), leaves nothing behind once rolled
// back: the motion mode, the feed rate, the position, the cycle's initial
// level and the canonical machine are as if it never ran. By the plain
// move's road (run_plain_move, its own putting back) and the whole road.
TEST(EvaluatedEntry, ARolledBackPlainMoveLeavesNothingBehind) {
  for (const bool shortcut : {true, false}) {
    InterpOptions options;
    options.plain_move_shortcut = shortcut;
    Fed refused(options), never(options);
    for (Fed* f : {&refused, &never}) {
      ASSERT_TRUE(f->block({{'G', 21, 1}, {'G', 94, 5}, {'G', 0, 9}, {'Z', 5, 12}}));
      ASSERT_TRUE(f->block({{'F', 500, 1}}));
      // G99: the tool stays at R, the initial level Z5 kept for the next hole.
      ASSERT_TRUE(f->block(
          {{'G', 99, 1}, {'G', 81, 5}, {'X', 1, 9}, {'Y', 1, 12}, {'Z', -2, 15}, {'R', 1, 19}}));
    }
    refused.interp.checkpoint();
    const core::SourceLoc at{0, 99, 1, 0, 0};
    const PlainMove move{0, 7u | PlainMove::kF, 900, {7, 8, 9}};
    const std::optional<bool> ran = refused.interp.run_plain_move(at, move);
    EXPECT_EQ(ran.has_value(), shortcut);
    if (!ran) {
      const std::vector<EvaluatedWord> words{
          {'G', 0, 1}, {'X', 7, 4}, {'Y', 8, 7}, {'Z', 9, 10}, {'F', 900, 13}};
      ASSERT_TRUE(refused.interp.run_evaluated({at, words, {}, {}}));
    }
    refused.interp.roll_back();
    // What the ops below do not show: the feed rate of the modal state
    // (#<_feed>, a feed move's check that F is set).
    EXPECT_EQ(refused.interp.state().feed, never.interp.state().feed) << shortcut;
    for (Fed* f : {&refused, &never}) {
      // The cycle goes on from its initial level; then a feed at F500.
      ASSERT_TRUE(f->block({{'G', 98, 1}, {'X', 2, 5}, {'Y', 2, 8}}));
      ASSERT_TRUE(f->block({{'G', 80, 1}}));
      ASSERT_TRUE(f->block({{'G', 1, 1}, {'X', 3, 4}}));
    }
    EXPECT_EQ(moves_but(refused.path, 99), moves_but(never.path, 99)) << shortcut;
    EXPECT_GT(refused.path.ops().size(), moves_but(refused.path, 99).size()) << shortcut;
  }
}

}  // namespace
}  // namespace usina::gcode::interp_test
