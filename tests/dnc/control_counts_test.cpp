// The control's part counts, cycle times and last message are kept in the
// store (store_parts.hpp): a server stopped and started again on the same
// store (SQLite and PostgreSQL) shows the same counts, and counts on.
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/store_parts.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

class ControlCountsOnBothStores : public test::StoreTest {};

nlohmann::json mill_when_parts(const ApiClient& c, const std::string& token, int parts) {
  return machine_when(c, token, [parts](const nlohmann::json& m) {
    return m.value("part_count", -1) == parts && m.value("state", "") == "idle";
  });
}

TEST_P(ControlCountsOnBothStores, PartCountAndCycleTimeSurviveARestart) {
  RunningServer first;
  first.use_store(where());
  Control control = start_punching_mill(first);
  {
    const ApiClient c = first.client();
    const std::string oper = c.log_in("oper", usina::test::kPassword);
    ASSERT_EQ(mill_when_parts(c, oper, 0)["state"], "idle");
    punch(first, control, "CYCLE TIME 83.5\r\nPART COUNT 41\r\n(MSG, SPINDLE WARM)\r\n");
    const auto m = mill_when_parts(c, oper, 1);
    ASSERT_EQ(m["part_count"], 1) << m.dump();
    EXPECT_EQ(m["last_message"], "SPINDLE WARM");
  }
  first.stop();

  RunningServer second;
  second.use_store(where());
  Control again = start_punching_mill(second);
  const ApiClient c = second.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  auto m = mill_when_parts(c, oper, 1);
  EXPECT_EQ(m["part_count"], 1) << m.dump();
  EXPECT_EQ(m["control_part_count"], 41);
  ASSERT_TRUE(m["last_cycle_seconds"].is_number()) << m.dump();
  EXPECT_DOUBLE_EQ(m["last_cycle_seconds"].get<double>(), 83.5);
  EXPECT_EQ(m["last_message"], "SPINDLE WARM");
  EXPECT_GT(m["last_run_at_us"].get<std::int64_t>(), 0);
  // And it counts on from there.
  punch(second, again, "CYCLE TIME 80\nPART COUNT 42\n");
  m = mill_when_parts(c, oper, 2);
  EXPECT_EQ(m["part_count"], 2) << m.dump();
  EXPECT_EQ(m["control_part_count"], 42);
  EXPECT_DOUBLE_EQ(m["last_cycle_seconds"].get<double>(), 80.0);
}

TEST_P(ControlCountsOnBothStores, TheStoreKeepsEachPartItsCycleAndTheLastMessage) {
  {
    auto store = open();
    ASSERT_TRUE(store);
    ASSERT_TRUE(record_control_part(*store, {"m1", 1000, std::nullopt, 7, "", ""}));
    ASSERT_TRUE(record_control_part(*store, {"m1", 2000, 900, std::nullopt, "O1", "ab"}));
    ASSERT_TRUE(record_control_part(*store, {"m2", 2500, 5, 1, "", ""}));
    ASSERT_TRUE(set_last_control_cycle(*store, "m1", 1500));
    ASSERT_TRUE(record_control_message(*store, "m1", "FIRST", 2100));
    ASSERT_TRUE(record_control_message(*store, "m1", "SECOND", 2200));
  }
  auto store = open();
  ASSERT_TRUE(store);
  const auto t = control_totals(*store, "m1");
  ASSERT_TRUE(t) << t.error().message;
  EXPECT_EQ(t->parts, 2);
  EXPECT_EQ(t->control_count, 7);  // the last one the control printed
  EXPECT_EQ(t->last_cycle_us, 1500);
  EXPECT_EQ(t->last_part_at_us, 2000);
  EXPECT_EQ(t->last_message, "SECOND");
  const auto none = control_totals(*store, "m3");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->parts, 0);
  EXPECT_FALSE(none->control_count);
  const auto parts = control_parts(*store, "m1", 1500, 3000);
  ASSERT_TRUE(parts);
  ASSERT_EQ(parts->size(), 1u);
  EXPECT_EQ((*parts)[0].program, "O1");
}

USINA_STORE_BACKENDS(ControlCountsOnBothStores);

}  // namespace
}  // namespace usina::dnc
