// RemovalTimeline: the volume each op cut laid on the time the planner gave
// it (docs/simulate.md, "Removal rate").
#include "sim/stock/removal_rate.hpp"

#include <numeric>

#include <gtest/gtest.h>

namespace usina::sim::stock {
namespace {

double sum(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0);
}

TEST(RemovalTimeline, AnOpsVolumeIsSpreadEvenlyOverItsTime) {
  RemovalTimeline t;
  t.cut(1, 60.0);
  t.timed(1, 1.0);  // 0..1 s: 60 mm³, 0.6 mm³ in each 10 ms bin
  t.timed(2, 1.0);  // 1..2 s: nothing cut
  t.finish();
  EXPECT_DOUBLE_EQ(t.total_s(), 2.0);
  EXPECT_DOUBLE_EQ(t.cutting_s(), 1.0);
  EXPECT_DOUBLE_EQ(t.bin_s(), RemovalTimeline::kFirstBinSeconds);
  ASSERT_GE(t.bins().size(), 100u);
  EXPECT_NEAR(t.bins()[0], 0.6, 1e-9);
  EXPECT_NEAR(t.bins()[99], 0.6, 1e-9);
  for (std::size_t i = 100; i < t.bins().size(); ++i)
    EXPECT_EQ(t.bins()[i], 0.0) << i;
  EXPECT_NEAR(sum(t.bins()), 60.0, 1e-9);
}

TEST(RemovalTimeline, AnOpToldInPiecesGetsItsVolumeOverAllOfThem) {
  // An arc run as chords: the volume is the whole arc's, over the whole arc.
  RemovalTimeline t;
  t.cut(1, 10.0);
  t.timed(1, 0.25);
  t.timed(1, 0.25);
  t.timed(1, 0.5);
  t.timed(2, 1.0);
  t.finish();
  EXPECT_DOUBLE_EQ(t.cutting_s(), 1.0);
  EXPECT_NEAR(t.bins()[0], 0.1, 1e-9);   // 10 mm³ over 100 bins
  EXPECT_NEAR(t.bins()[90], 0.1, 1e-9);  // the last piece too
  EXPECT_NEAR(sum(t.bins()), 10.0, 1e-9);
}

TEST(RemovalTimeline, OpsThePlannerMergedShareTheTimeOfTheLast) {
  // A merged chain is told as its last op: the ops before it share its time.
  RemovalTimeline t;
  t.cut(1, 5.0);
  t.cut(2, 5.0);
  t.cut(3, 10.0);
  t.timed(3, 2.0);
  t.finish();
  EXPECT_DOUBLE_EQ(t.cutting_s(), 2.0);
  EXPECT_NEAR(t.bins()[0], 0.1, 1e-9);  // 20 mm³ over 200 bins
  EXPECT_NEAR(t.bins()[199], 0.1, 1e-9);
}

TEST(RemovalTimeline, AVolumeWaitsForItsOpsTime) {
  // The planner runs behind the simulator: op 2's volume is told long
  // before its time, and must not land on op 1's.
  RemovalTimeline t;
  t.cut(1, 1.0);
  t.cut(2, 100.0);
  t.timed(1, 1.0);
  t.timed(2, 1.0);
  t.finish();
  EXPECT_NEAR(sum(std::vector<double>(t.bins().begin(), t.bins().begin() + 100)), 1.0, 1e-9);
  EXPECT_NEAR(sum(std::vector<double>(t.bins().begin() + 100, t.bins().end())), 100.0, 1e-9);
}

TEST(RemovalTimeline, AWaitIsTimeWithNothingCut) {
  RemovalTimeline t;
  t.cut(1, 1.0);
  t.timed(1, 1.0);
  t.timed(2, 3.0);  // a dwell
  t.cut(3, 1.0);
  t.timed(3, 1.0);
  t.finish();
  EXPECT_DOUBLE_EQ(t.total_s(), 5.0);
  EXPECT_DOUBLE_EQ(t.cutting_s(), 2.0);
  EXPECT_EQ(t.bins()[250], 0.0);
  EXPECT_NEAR(t.bins()[450], 0.01, 1e-9);
}

TEST(RemovalTimeline, BinsWidenAndKeepTheirVolume) {
  // An hour at 1 mm³/s: the bins double until 1,000 hold it.
  RemovalTimeline t;
  for (std::uint64_t op = 1; op <= 3600; ++op) {
    t.cut(op, 1.0);
    t.timed(op, 1.0);
  }
  t.finish();
  EXPECT_LE(t.bins().size(), RemovalTimeline::kBins);
  EXPECT_GE(t.bin_s() * RemovalTimeline::kBins, 3600.0);
  EXPECT_LT(t.bin_s() * RemovalTimeline::kBins / 2, 3600.0);
  EXPECT_NEAR(sum(t.bins()), 3600.0, 1e-6);
  // Every whole bin holds its width's worth.
  EXPECT_NEAR(t.bins()[10], t.bin_s(), 1e-6);
}

TEST(RemovalTimeline, VolumeNeverTimedIsLaidAtTheEnd) {
  RemovalTimeline t;
  t.cut(1, 2.0);
  t.timed(1, 1.0);
  t.cut(2, 3.0);  // the planner never timed op 2 (no length)
  t.finish();
  EXPECT_NEAR(sum(t.bins()), 5.0, 1e-9);
  EXPECT_NEAR(t.bins().back(), 3.0, 1e-9);
}

TEST(RemovalTimeline, OpsNeverTimedDoNotPileUp) {
  // A planner that times nothing: the volume waits in a bounded queue and
  // is all laid at the end.
  RemovalTimeline t;
  for (std::uint64_t op = 1; op <= 3 * RemovalTimeline::kMaxPending; ++op)
    t.cut(op, 1.0);
  EXPECT_LE(t.waiting(), RemovalTimeline::kMaxPending);
  t.finish();
  EXPECT_NEAR(sum(t.bins()), 3.0 * RemovalTimeline::kMaxPending, 1e-6);
}

TEST(RemovalTimeline, EachOperationGetsItsOpsTime) {
  RemovalTimeline t;
  t.timed(1, 0.5);  // before the first operation: counted with it
  t.operation_begins(2);
  t.timed(2, 1.0);
  t.timed(3, 2.0);
  t.operation_begins(4);  // a tool change: its wait is the new operation's
  t.timed(4, 5.0);
  t.timed(5, 1.0);
  t.finish();
  ASSERT_EQ(t.operation_s().size(), 2u);
  EXPECT_DOUBLE_EQ(t.operation_s()[0], 3.5);
  EXPECT_DOUBLE_EQ(t.operation_s()[1], 6.0);
}

TEST(RemovalTimeline, TheTimeOfNothingIsNotARate) {
  RemovalTimeline t;
  t.cut(1, -1.0);    // never a volume
  t.timed(1, -2.0);  // never a time
  t.finish();
  EXPECT_EQ(t.total_s(), 0.0);
  EXPECT_EQ(t.peak_bin(), 0u);
  EXPECT_TRUE(t.bins().empty());
}

}  // namespace
}  // namespace usina::sim::stock
