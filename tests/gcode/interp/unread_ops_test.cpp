// `usina check` hands the interpreter a sink that reads no op
// (canon::Sink::reads_ops), and the canonical machine then builds no
// straight move, only checks its numbers and counts it. Whatever the sink,
// a program must say the same: each program below runs twice, once into a
// toolpath (every op built) and once as check runs it (an operation budget
// over a NullSink), and the diagnostics must match in every field.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "canon/sink.hpp"
#include "canon/toolpath.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"

namespace usina::gcode {
namespace {

struct Outcome {
  bool ok = false;
  std::vector<core::Diagnostic> diags;
  std::uint64_t ops = 0;
};

Outcome run_into(canon::Sink& inner, const std::string& text, std::uint64_t max_ops,
                 const char* dialect = "rs274ngc") {
  core::SourceManager sources;
  core::DiagnosticList diags;
  const std::uint32_t id = sources.add(core::SourceFile::from_string("test.nc", text));
  const Dialect* d = find_dialect(dialect);
  EXPECT_NE(d, nullptr);
  canon::OpBudget budget(inner, max_ops, diags);
  auto runner = d->make_runner(RunContext{sources, {}, default_options(*d), budget, diags});
  Outcome out;
  out.ok = runner->run(id);
  out.diags = diags.all();
  out.ops = budget.passed();
  return out;
}

void expect_same_either_way(const std::string& text, std::uint64_t max_ops = 1000,
                            const char* dialect = "rs274ngc") {
  SCOPED_TRACE(text);
  canon::Toolpath path;
  ASSERT_TRUE(path.reads_ops());
  const Outcome built = run_into(path, text, max_ops, dialect);
  canon::NullSink null;
  ASSERT_FALSE(null.reads_ops());
  const Outcome counted = run_into(null, text, max_ops, dialect);
  EXPECT_EQ(built.ok, counted.ok);
  EXPECT_EQ(built.ops, counted.ops);
  ASSERT_EQ(built.diags.size(), counted.diags.size());
  for (std::size_t i = 0; i < built.diags.size(); ++i) {
    const core::Diagnostic& a = built.diags[i];
    const core::Diagnostic& b = counted.diags[i];
    EXPECT_EQ(core::code_name(a.code), core::code_name(b.code));
    EXPECT_EQ(a.severity, b.severity);
    EXPECT_EQ(a.loc.line, b.loc.line);
    EXPECT_EQ(a.loc.col, b.loc.col);
    EXPECT_EQ(a.loc.length, b.loc.length);
    EXPECT_EQ(a.message, b.message);
  }
}

TEST(UnreadOps, AGoodProgramCountsTheSameOps) {
  expect_same_either_way("G21 G90 G17\nG0 X0 Y0 Z5\nG1 Z-1 F600\nX10 Y5\nG2 X20 Y5 I5 J0\nM30\n");
}

TEST(UnreadOps, TraverseBeyondTheRangeSaysTheSame) {
  expect_same_either_way("G91 G0 X900000000\nX900000000\nM2\n");
}

TEST(UnreadOps, FeedBeyondTheRangeSaysTheSame) {
  expect_same_either_way("G1 F100 X1\nG91 G1 Y900000000\nY900000000\nM2\n");
}

TEST(UnreadOps, RotaryAxisBeyondTheRangeSaysTheSame) {
  expect_same_either_way("G91 G1 F100 A900000000\nA900000000\nM2\n");
}

TEST(UnreadOps, FeedRateBelowTheSmallestSaysTheSame) {
  expect_same_either_way("G1 X1 F0.0000001\nM2\n");
}

TEST(UnreadOps, InverseTimeFeedSaysTheSame) {
  expect_same_either_way("G93 G1 X1 F2\nX2 F0.00000001\nM2\n");
}

TEST(UnreadOps, TheBudgetRunsOutAtTheSameBlock) {
  expect_same_either_way("G0 X1\nG1 X2 F100\nG0 X3\nG1 X4\nG0 X5\nM2\n", 3);
}

// Fanuc's G22 checks where the tool is when it arms an area, after moves
// that went by unbuilt; armed, it reads every move (docs/fanuc.md §7).
TEST(UnreadOps, FanucStrokeCheckSaysTheSame) {
  const std::string box = "G22 X10. Y10. Z10. I-10. J-10. K-10.\n";
  for (const std::string& text : std::vector<std::string>{
           "G0 X5. Y5. Z50.\nG1 Z5. F100.\n" + box + "M30\n",  // armed around the tool
           "G0 X5. Y5. Z50.\nG1 Z5. F100.\nG0 Z50.\n" + box + "M30\n",
           "G0 X15. Y0 Z0\nG1 X12. Y-5. F100.\n" + box + "G2 X12. Y5. I4. J5.\nM30\n",
           "G0 X15. Y0 Z0\nG1 X12. Y-5. F100.\n" + box + "G3 X12. Y5. I4. J5.\nM30\n",
           "G0 Z50.\n" + box + "G0 X0 Y0\nG1 Z0 F100.\nG0 X50.\nM30\n",
           "G0 Z50.\n" + box + "G23\nG1 X5. Y5. F100.\nZ5.\n" + box + "M30\n",
           "G0 X-20. Y0 Z0\nG2 X20. I20. F100.\n" + box + "G0 X-5.\nM30\n",
           std::string("G22 X100. Y100. Z100. I-100. J-100. K-100.\nG0 X50.\nG0 X150.\nM30\n"),
       }) {
    expect_same_either_way(text, 1000, "fanuc");
  }
  canon::NullSink null;
  const std::string around = "G0 X5. Y5. Z50.\nG1 Z5. F100.\n" + box + "M30\n";
  const Outcome counted = run_into(null, around, 1000, "fanuc");
  EXPECT_FALSE(counted.ok);
  ASSERT_FALSE(counted.diags.empty());
  EXPECT_EQ(counted.diags.front().code, core::Code::ForbiddenArea);
  EXPECT_EQ(counted.diags.front().loc.line, 3u);
}

// Grbl checks a line's moves from where the tool is (soft limits, an arc's
// radius, a probe's target) before it passes them on, and a refused line
// sends nothing: moves that go by unbuilt are checked the same.
TEST(UnreadOps, GrblLineChecksSayTheSame) {
  const std::string soft = "$22=1\n$20=1\n";
  for (const std::string& text : std::vector<std::string>{
           soft + "G0 X-5\nG0 X1\nG0 X-10\nG1 X\nM2\n",
           soft + "G1 X-50 Y-50 F500\nG2 X-60 Y-50 R4\nG1 X-10 F100\nM2\n",
           soft + "G1 X-50 Y-50 F500\nG2 X-150 Y-50 I-50 J0\nG3 X-50 Y-50 I55 J0\nM2\n",
           soft + "G0 X-10 Y-10 Z-1\n$J=G91 X-250 F1000\nG91 G1 X-5 F100\nG90 G38.2 Z-1\nM2\n",
           "G0 X-10\nG28\nG1 X\nG1 X5 F100\nG38.2 Z-5 F50\nG0 Z5\nM2\n",
           "G1 X1 F100\nG1 X2\nG0 X3\nG1 X4\nG0 X5\nM2\n",
       }) {
    expect_same_either_way(text, 1000, "grbl");
  }
  expect_same_either_way("G0 X1\nG1 X2 F100\nG0 X3\nG1 X4\nG0 X5\nM2\n", 3, "grbl");
}

TEST(UnreadOps, NothingIsSentAfterAFault) {
  canon::NullSink null;
  const Outcome counted = run_into(null, "G0 X1\nG91 G0 X2000000000\nG0 X1\nM2\n", 1000);
  EXPECT_FALSE(counted.ok);
  EXPECT_EQ(counted.ops, 1u);
}

}  // namespace
}  // namespace usina::gcode
