// canon/batch_sink.hpp: ops handed on a batch at a time, in their order,
// with an unbuilt op (pass) after the ops held before it.
#include "canon/batch_sink.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace usina::canon {
namespace {

Op move(double x, std::uint32_t line) {
  return Op{Traverse{{x, 0, 0}}, {1, line, 1, 0, 0}, Origin::Program};
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
