// A server killed without stopping (kill -9, a power cut) cannot write
// "off" as it dies: its heartbeat (schema version 5) is where the next start
// ends its machines' activity and its unfinished jobs (store_utilisation.hpp,
// store_jobs.hpp), on SQLite and PostgreSQL, on a test clock.
#include <gtest/gtest.h>

#include "dnc/store_jobs.hpp"
#include "dnc/store_utilisation.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

constexpr std::int64_t kDay = 86'400'000'000;
constexpr std::int64_t kSecond = 1'000'000;
constexpr std::int64_t kMay28 = 20601;  // 2026-05-28 in days since 1970

class HeartbeatOnBothStores : public test::StoreTest {};

TEST_P(HeartbeatOnBothStores, TheNextStartEndsADeadServersActivityAtItsLastHeartbeat) {
  const std::int64_t t0 = kMay28 * kDay;
  now_us = t0 + 12 * 3600 * kSecond;  // restarted at 12:00
  auto store = open();
  ASSERT_TRUE(store);
  // 08:00 m1 feeding, m2 idle; 08:30 m3 stopped cleanly; heartbeats to 09:00.
  ASSERT_TRUE(record_activity(*store, "m1", "feeding", t0 + 8 * 3600 * kSecond));
  ASSERT_TRUE(record_activity(*store, "m2", "idle", t0 + 8 * 3600 * kSecond));
  ASSERT_TRUE(record_activity(*store, "m3", "idle", t0 + 8 * 3600 * kSecond));
  ASSERT_TRUE(record_activity(*store, "m3", "off", t0 + 8 * 3600 * kSecond + 1800 * kSecond));
  ASSERT_TRUE(record_heartbeat(*store, t0 + 8 * 3600 * kSecond + 1800 * kSecond));
  ASSERT_TRUE(record_heartbeat(*store, t0 + 9 * 3600 * kSecond));
  const auto beat = last_heartbeat(*store);
  ASSERT_TRUE(beat);
  EXPECT_EQ(*beat, t0 + 9 * 3600 * kSecond);  // the latest, not the first

  const auto closed = close_activity_of_dead_server(*store);
  ASSERT_TRUE(closed) << closed.error().message;
  EXPECT_EQ(*closed, 2);  // m1 and m2; m3 was off already
  const auto days = machine_days(*store, "m1", kMay28, kMay28);
  ASSERT_TRUE(days);
  const MachineDay& d = days->front();
  EXPECT_DOUBLE_EQ(d.seconds.at("feeding"), 3600.0);  // 08:00 to the 09:00 heartbeat
  EXPECT_DOUBLE_EQ(d.seconds.at("off"), 3 * 3600.0);  // 09:00 to now, not feeding
  const auto m3 = machine_days(*store, "m3", kMay28, kMay28);
  ASSERT_TRUE(m3);
  EXPECT_DOUBLE_EQ(m3->front().seconds.at("off"), 3.5 * 3600.0);  // its own off kept
  // A second start finds nothing more to close.
  const auto again = close_activity_of_dead_server(*store);
  ASSERT_TRUE(again);
  EXPECT_EQ(*again, 0);
}

TEST_P(HeartbeatOnBothStores, AnActivityAfterTheLastHeartbeatEndsWhereItBegan) {
  const std::int64_t t0 = kMay28 * kDay;
  now_us = t0 + 10 * 3600 * kSecond;
  auto store = open();
  ASSERT_TRUE(store);
  ASSERT_TRUE(record_heartbeat(*store, t0 + 8 * 3600 * kSecond));
  // The drip feed started 5 s after the heartbeat and the server died before the next.
  ASSERT_TRUE(record_activity(*store, "m1", "feeding", t0 + 8 * 3600 * kSecond + 5 * kSecond));
  ASSERT_TRUE(close_activity_of_dead_server(*store));
  const auto days = machine_days(*store, "m1", kMay28, kMay28);
  ASSERT_TRUE(days);
  EXPECT_EQ(days->front().seconds.count("feeding"), 0u);  // no second counted past the death
  EXPECT_DOUBLE_EQ(days->front().seconds.at("off"), 2 * 3600.0 - 5.0);
}

TEST_P(HeartbeatOnBothStores, AStoreWithoutAHeartbeatClosesAtTheLastActivity) {
  const std::int64_t t0 = kMay28 * kDay;
  now_us = t0 + 10 * 3600 * kSecond;
  auto store = open();
  ASSERT_TRUE(store);
  const auto none = last_heartbeat(*store);
  ASSERT_TRUE(none);
  EXPECT_FALSE(none->has_value());
  // A store written by a usina before version 5: no heartbeat to go by.
  ASSERT_TRUE(record_activity(*store, "m1", "idle", t0 + 9 * 3600 * kSecond));
  ASSERT_TRUE(close_activity_of_dead_server(*store));
  const auto days = machine_days(*store, "m1", kMay28, kMay28);
  ASSERT_TRUE(days);
  EXPECT_DOUBLE_EQ(days->front().seconds.at("off"), 3600.0);
}

TEST_P(HeartbeatOnBothStores, AJobCutByADeadServerEndsAtItsLastHeartbeat) {
  const std::int64_t t0 = kMay28 * kDay;
  now_us = t0 + 8 * 3600 * kSecond;
  auto store = open();
  ASSERT_TRUE(store);
  JobRecord job;
  job.machine = "m1";
  job.program = "O1";
  job.revision = std::string(64, 'a');
  job.mode = "drip";
  job.state = "running";
  job.started_at_us = now_us;
  auto made = create_job(*store, job, Actor{"boss", "test"});
  ASSERT_TRUE(made) << made.error().message;
  ASSERT_TRUE(record_heartbeat(*store, t0 + 8 * 3600 * kSecond + 40 * kSecond));
  now_us = t0 + 11 * 3600 * kSecond;  // the restart
  const auto beat = last_heartbeat(*store);
  ASSERT_TRUE(beat);
  ASSERT_TRUE(interrupt_unfinished_jobs(*store, "the server stopped", *beat));
  const auto after = find_job(*store, made->id);
  ASSERT_TRUE(after);
  EXPECT_EQ(after->state, "interrupted");
  EXPECT_EQ(after->ended_at_us, t0 + 8 * 3600 * kSecond + 40 * kSecond);
}

USINA_STORE_BACKENDS(HeartbeatOnBothStores);

}  // namespace
}  // namespace usina::dnc
