// The entry below the text (interp/evaluated_block.hpp): blocks of
// evaluated words handed to the interpreter by a front end, without program
// text; words marked as increments (romi's lower-case words) on moves to a
// point, and refused where the interpreter reads axis words another way.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/interp_run.hpp"

namespace usina::gcode::interp_test {
namespace {

// An interpreter fed block by block, as a dialect's front end feeds it.
struct Fed {
  core::SourceManager sources;
  core::DiagnosticList diags;
  canon::Toolpath path;
  Interpreter interp{sources, InterpOptions{}, path, diags};
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

}  // namespace
}  // namespace usina::gcode::interp_test
