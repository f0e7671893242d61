// The sinks that wrap sinks (canon/sink.hpp, canon/batch_sink.hpp): the
// operation budget of a run, the progress a long run shows, and the ops
// handed on a batch at a time, in their order.
#include "canon/sink.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "canon/batch_sink.hpp"
#include "canon/toolpath.hpp"

namespace usina::canon {
namespace {

Op move(double x, std::uint32_t line) {
  return Op{Traverse{{x, 0, 0}}, {1, line, 1, 0, 0}, Origin::Program};
}

class Finishes final : public Sink {
 public:
  void on(const Op&) override { ++ops; }

  void finish() override { finished = true; }

  int ops = 0;
  bool finished = false;
};

TEST(OpBudget, PassesTheBudgetThenReportsOnceAndStops) {
  Finishes out;
  core::DiagnosticList diags;
  OpBudget budget(out, 3, diags);
  for (std::uint32_t i = 1; i <= 10; ++i) {
    EXPECT_EQ(budget.stopped(), i > 4) << i;
    budget.on(move(i, i));
  }
  budget.finish();
  EXPECT_EQ(out.ops, 3);
  EXPECT_TRUE(out.finished);
  EXPECT_TRUE(budget.stopped());
  EXPECT_EQ(budget.passed(), 3u);
  ASSERT_EQ(diags.all().size(), 1u);
  const core::Diagnostic& d = diags.all()[0];
  EXPECT_EQ(d.code, core::Code::TooManyOperations);
  EXPECT_EQ(d.severity, core::Severity::Error);
  EXPECT_EQ(d.loc.line, 4u);  // the block of the first op beyond
  EXPECT_NE(d.message.find("3 operations"), std::string::npos) << d.message;
  EXPECT_NE(d.message.find("--max-ops"), std::string::npos) << d.message;
}

TEST(OpBudget, ARunWithinItReportsNothing) {
  Toolpath out;
  core::DiagnosticList diags;
  OpBudget budget(out, 2, diags);
  budget.on(move(1, 1));
  budget.on(move(2, 2));
  EXPECT_FALSE(budget.stopped());
  EXPECT_TRUE(diags.all().empty());
  EXPECT_EQ(out.ops().size(), 2u);
}

TEST(OpBudget, WrappingSinksAnswerForTheOneInside) {
  NullSink null;
  core::DiagnosticList diags;
  OpBudget budget(null, 0, diags);
  Toolpath other;
  TeeSink tee({&other, &budget});
  EXPECT_FALSE(tee.stopped());
  tee.on(move(1, 1));
  EXPECT_TRUE(tee.stopped());
  ProgressSink progress(
      budget, [](std::string_view) {}, 0);
  EXPECT_TRUE(progress.stopped());
}

// usina check's road: ops that go by unbuilt (Sink::pass) count as ops.
TEST(OpBudget, UnbuiltOpsCountAgainstTheBudgetAndTheLastIsNamed) {
  NullSink null;
  EXPECT_FALSE(null.reads_ops());
  core::DiagnosticList diags;
  OpBudget budget(null, 2, diags);
  EXPECT_FALSE(budget.reads_ops());
  budget.pass({1, 1, 1, 0, 0});
  budget.on(move(2, 2));
  EXPECT_FALSE(budget.stopped());
  budget.pass({1, 3, 1, 0, 0});
  budget.pass({1, 4, 1, 0, 0});
  EXPECT_TRUE(budget.stopped());
  EXPECT_EQ(budget.passed(), 2u);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].code, core::Code::TooManyOperations);
  EXPECT_EQ(diags.all()[0].loc.line, 3u);
}

TEST(OpBudget, ASinkThatReadsOpsIsAskedForThemThroughEveryWrapper) {
  Toolpath path;
  NullSink null;
  core::DiagnosticList diags;
  OpBudget reading(path, 10, diags);
  EXPECT_TRUE(reading.reads_ops());
  EXPECT_TRUE(TeeSink({&null, &reading}).reads_ops());
  EXPECT_FALSE(TeeSink({&null, &null}).reads_ops());
  ProgressSink progress(
      reading, [](std::string_view) {}, 10);
  EXPECT_TRUE(progress.reads_ops());
  OpBudget counting(null, 10, diags);
  ProgressSink quiet(
      counting, [](std::string_view) {}, 10);
  EXPECT_FALSE(quiet.reads_ops());
}

// A clock the test moves by hand.
struct FakeClock {
  double now = 100.0;
};

TEST(ProgressSink, SilentForTheDelayThenAtMostOnceAPeriodThenErased) {
  Toolpath out;
  FakeClock clock;
  std::vector<std::string> shown;
  ProgressSink progress(
      out, [&](std::string_view s) { shown.emplace_back(s); }, 1000, ProgressTiming{1.0, 0.5, 1},
      [&] { return clock.now; });
  progress.on(move(1, 7));  // 0 s: too soon
  EXPECT_TRUE(shown.empty());
  EXPECT_FALSE(progress.showing());
  clock.now += 1.2;
  progress.on(move(2, 8));
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_EQ(shown[0], "usina: 2 operations of at most 1,000 (--max-ops), line 8, 1 s");
  EXPECT_TRUE(progress.showing());
  clock.now += 0.1;  // within the period
  progress.on(move(3, 9));
  EXPECT_EQ(shown.size(), 1u);
  clock.now += 0.5;
  progress.on(move(4, 9));
  EXPECT_EQ(shown.size(), 2u);
  progress.finish();
  ASSERT_EQ(shown.size(), 3u);
  EXPECT_EQ(shown[2], "");  // erased at the end
  EXPECT_FALSE(progress.showing());
  EXPECT_EQ(out.ops().size(), 4u);  // every op passed on
}

TEST(ProgressSink, ReadsTheClockOnlyEveryFewOps) {
  Toolpath out;
  int reads = 0;
  ProgressSink progress(
      out, [](std::string_view) {}, 10, ProgressTiming{0.0, 0.0, 100},
      [&] {
        ++reads;
        return 0.0;
      });
  const int at_start = reads;
  for (std::uint32_t i = 0; i < 1000; ++i)
    progress.on(move(i, 1));
  EXPECT_EQ(reads - at_start, 10);
}

TEST(ProgressSink, UnbuiltOpsShowTheirLine) {
  NullSink null;
  FakeClock clock;
  std::vector<std::string> shown;
  ProgressSink progress(
      null, [&](std::string_view s) { shown.emplace_back(s); }, 1000, ProgressTiming{1.0, 0.5, 1},
      [&] { return clock.now; });
  progress.pass({1, 7, 1, 0, 0});
  EXPECT_TRUE(shown.empty());
  clock.now += 1.2;
  progress.pass({1, 8, 1, 0, 0});
  ASSERT_EQ(shown.size(), 1u);
  EXPECT_EQ(shown[0], "usina: 2 operations of at most 1,000 (--max-ops), line 8, 1 s");
}

TEST(ProgressSink, NothingToEraseWhenNothingWasShown) {
  Toolpath out;
  int calls = 0;
  ProgressSink progress(
      out, [&](std::string_view) { ++calls; }, 10);
  progress.on(move(1, 1));
  progress.erase();
  progress.finish();
  EXPECT_EQ(calls, 0);
}

TEST(ProgressLine, GroupsThousandsAndLeavesOutAnUnknownLine) {
  EXPECT_EQ(progress_line(12'345'678, 100'000'000, 4, 12.7),
            "usina: 12,345,678 operations of at most 100,000,000 (--max-ops), line 4, 12 s");
  EXPECT_EQ(progress_line(999, 1000, 0, 0.2),
            "usina: 999 operations of at most 1,000 (--max-ops), 0 s");
}

// What reached it, in order: "on 3" for an op of line 3, "pass 3", "finish".
class Log final : public Sink {
 public:
  void on(const Op& op) override { seen.push_back("on " + std::to_string(op.src.line)); }

  void pass(const core::SourceLoc& src) override {
    seen.push_back("pass " + std::to_string(src.line));
  }

  void finish() override { seen.emplace_back("finish"); }

  bool stopped() const override { return stop; }

  bool reads_ops() const override { return reads; }

  std::vector<std::string> seen;
  bool stop = false;
  bool reads = true;
};

TEST(BatchSink, HandsOnAFullBatchAtOnceAndTheRestAtTheFinish) {
  Log out;
  BatchSink batch(out, 3);
  batch.on(move(1, 1));
  batch.on(move(2, 2));
  EXPECT_TRUE(out.seen.empty());
  batch.on(move(3, 3));
  EXPECT_EQ(out.seen, (std::vector<std::string>{"on 1", "on 2", "on 3"}));
  batch.on(move(4, 4));
  batch.on(move(5, 5));
  EXPECT_EQ(out.seen.size(), 3u);
  batch.finish();
  EXPECT_EQ(out.seen, (std::vector<std::string>{"on 1", "on 2", "on 3", "on 4", "on 5", "finish"}));
}

TEST(BatchSink, FlushHandsOnWhatIsHeldInOrder) {
  Log out;
  BatchSink batch(out, 100);
  batch.on(move(1, 7));
  batch.on(move(2, 8));
  batch.flush();
  EXPECT_EQ(out.seen, (std::vector<std::string>{"on 7", "on 8"}));
  batch.flush();  // nothing held: nothing again
  EXPECT_EQ(out.seen.size(), 2u);
}

TEST(BatchSink, APassComesAfterTheOpsHeldBeforeIt) {
  Log out;
  BatchSink batch(out, 100);
  batch.on(move(1, 1));
  batch.pass({1, 2, 1, 0, 0});
  batch.on(move(3, 3));
  batch.finish();
  EXPECT_EQ(out.seen, (std::vector<std::string>{"on 1", "pass 2", "on 3", "finish"}));
}

// A sink that has the batch flushed while it takes the batch, as a
// diagnostic it reports through the runner's does (cli::RunGuard).
class FlushesBack final : public Sink {
 public:
  void on(const Op& op) override {
    lines.push_back(op.src.line);
    if (batch != nullptr) batch->flush();
  }

  BatchSink* batch = nullptr;
  std::vector<std::uint32_t> lines;
};

TEST(BatchSink, AFlushAskedForWhileFlushingHandsNothingOnTwice) {
  FlushesBack out;
  BatchSink batch(out, 3);
  out.batch = &batch;
  for (std::uint32_t i = 1; i <= 7; ++i)
    batch.on(move(i, i));
  batch.finish();
  EXPECT_EQ(out.lines, (std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6, 7}));
}

TEST(BatchSink, AnswersForTheNextSink) {
  Log out;
  BatchSink batch(out);
  EXPECT_TRUE(batch.reads_ops());
  EXPECT_FALSE(batch.stopped());
  out.reads = false;
  out.stop = true;
  EXPECT_FALSE(batch.reads_ops());
  EXPECT_TRUE(batch.stopped());
}

TEST(BatchSink, ABatchOfNoneHoldsOne) {
  Log out;
  BatchSink batch(out, 0);
  batch.on(move(1, 1));
  EXPECT_EQ(out.seen, (std::vector<std::string>{"on 1"}));
}

}  // namespace
}  // namespace usina::canon
