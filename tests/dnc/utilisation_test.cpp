// Utilisation per day and tool-life counts: the store's sums over recorded
// activity (exact, on a test clock, across midnight, on SQLite and
// PostgreSQL), and the routes GET /api/machines/{m}/utilisation and
// /tools after drip feeds to a simulated control.
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/store_parts.hpp"
#include "dnc/store_utilisation.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

constexpr std::int64_t kDay = 86'400'000'000;
constexpr std::int64_t kSecond = 1'000'000;
// 2026-05-28 00:00 UTC in days since 1970.
constexpr std::int64_t kMay28 = 20601;

class UtilisationOnBothStores : public test::StoreTest {};

TEST_P(UtilisationOnBothStores, ActivitySecondsAreSummedPerDayAcrossMidnight) {
  now_us = (kMay28 + 2) * kDay;  // two days later: both days are whole
  auto store = open();
  ASSERT_TRUE(store);
  const std::int64_t t0 = kMay28 * kDay;
  // 06:00 idle, 08:00 feeding, 09:00 alarm, 09:30 idle, 23:00 down, next day 01:00 off.
  const std::pair<std::int64_t, const char*> log[] = {
      {t0 + 6 * 3600 * kSecond, "idle"},  {t0 + 8 * 3600 * kSecond, "feeding"},
      {t0 + 9 * 3600 * kSecond, "alarm"}, {t0 + 9 * 3600 * kSecond + 1800 * kSecond, "idle"},
      {t0 + 23 * 3600 * kSecond, "down"}, {t0 + 25 * 3600 * kSecond, "off"}};
  for (const auto& [at, what] : log)
    ASSERT_TRUE(record_activity(*store, "m1", what, at));
  ASSERT_TRUE(record_activity(*store, "m2", "feeding", t0));  // another machine's
  ASSERT_TRUE(
      record_control_part(*store, {"m1", t0 + 12 * 3600 * kSecond, 600 * kSecond, 1, "", ""}));
  const auto days = machine_days(*store, "m1", kMay28, kMay28 + 1);
  ASSERT_TRUE(days) << days.error().message;
  ASSERT_EQ(days->size(), 2u);
  const MachineDay& d = (*days)[0];
  EXPECT_EQ(d.day, kMay28);
  EXPECT_DOUBLE_EQ(d.seconds.at("feeding"), 3600.0);
  EXPECT_DOUBLE_EQ(d.seconds.at("alarm"), 1800.0);
  EXPECT_DOUBLE_EQ(d.seconds.at("idle"), 2 * 3600.0 + 13.5 * 3600.0);
  EXPECT_DOUBLE_EQ(d.seconds.at("down"), 3600.0);
  EXPECT_DOUBLE_EQ(d.known_seconds, 18 * 3600.0);  // nothing known before 06:00
  EXPECT_DOUBLE_EQ(d.control_cycle_seconds, 600.0);
  EXPECT_EQ(d.parts, 1);
  const MachineDay& next = (*days)[1];
  EXPECT_DOUBLE_EQ(next.seconds.at("down"), 3600.0);  // till 01:00
  EXPECT_DOUBLE_EQ(next.seconds.at("off"), 23 * 3600.0);
  EXPECT_DOUBLE_EQ(next.known_seconds, 3600.0);  // the server was off the rest
}

TEST_P(UtilisationOnBothStores, TodayEndsNowAndADayBeforeAnyRecordIsEmpty) {
  now_us = kMay28 * kDay + 10 * 3600 * kSecond;  // 10:00
  auto store = open();
  ASSERT_TRUE(store);
  ASSERT_TRUE(record_activity(*store, "m1", "idle", kMay28 * kDay + 9 * 3600 * kSecond));
  const auto days = machine_days(*store, "m1", kMay28 - 1, kMay28);
  ASSERT_TRUE(days);
  EXPECT_DOUBLE_EQ((*days)[0].known_seconds, 0.0);
  EXPECT_TRUE((*days)[0].seconds.empty());
  EXPECT_DOUBLE_EQ((*days)[1].seconds.at("idle"), 3600.0);  // 09:00 to now, not to midnight
}

USINA_STORE_BACKENDS(UtilisationOnBothStores);

// Two tools: 10 mm at F100 with T1 (6 s), 20 mm at F100 with T2 (12 s).
const std::string kTwoTools = "T1 M6\nG1 X10 F100\nT2 M6\nG1 X-10 F100\nM2\n";

std::int64_t drip(const ApiClient& c, const std::string& token, const std::string& rev) {
  const auto job = c.post("/api/machines/mill-1/jobs",
                          {{"program", "O777"}, {"revision", rev}, {"mode", "drip"}}, token);
  EXPECT_EQ(job.status, 201) << job.body;
  return job.json().value("job", std::int64_t{0});
}

TEST(ApiUtilisation, TwoDripFeedsAreTwoPartsForEachToolOfTheProgram) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string rev = released(c, "O777", kTwoTools);
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  for (int i = 0; i < 2; ++i)
    ASSERT_EQ(wait_for_end(c, oper, drip(c, oper, rev))["state"], "done");
  const auto tools = c.get("/api/machines/mill-1/tools", oper);
  ASSERT_EQ(tools.status, 200) << tools.body;
  const auto t = tools.json();
  EXPECT_EQ(t["parts"], 2);
  EXPECT_EQ(t["parts_without_tool_list"], 0);
  ASSERT_EQ(t["tools"].size(), 2u) << t.dump();
  EXPECT_EQ(t["tools"][0]["tool"], 1);
  EXPECT_EQ(t["tools"][0]["parts"], 2);
  EXPECT_NEAR(t["tools"][0]["cutting_seconds"].get<double>(), 2 * 6.0, 0.5);
  EXPECT_EQ(t["tools"][1]["tool"], 2);
  EXPECT_NEAR(t["tools"][1]["cutting_minutes"].get<double>(), 2 * 12.0 / 60.0, 0.01);

  const auto u = c.get("/api/machines/mill-1/utilisation", oper);
  ASSERT_EQ(u.status, 200) << u.body;
  const auto j = u.json();
  ASSERT_EQ(j["days"].size(), 1u);  // today by default
  const auto& today = j["days"][0];
  EXPECT_EQ(today["parts"], 2);
  EXPECT_EQ(j["from"], today["date"]);
  EXPECT_GT(today["idle_seconds"].get<double>(), 0.0);
  EXPECT_GT(today["feeding_seconds"].get<double>(), 0.0);
  EXPECT_EQ(today["transfer_seconds"].get<double>(), 0.0);  // drip feeds only
  EXPECT_EQ(today["alarm_seconds"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(today["utilisation"].get<double>(),
                   today["running_seconds"].get<double>() / 86400.0);
  EXPECT_TRUE(today["availability"].is_number());
}

TEST(ApiUtilisation, BadRangesAre400AndAnUnknownMachine404) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  const std::string u = "/api/machines/mill-1/utilisation";
  EXPECT_EQ(c.get(u + "?from=2026-02-30", oper).status, 400);
  EXPECT_EQ(c.get(u + "?from=26-01-01", oper).status, 400);
  EXPECT_EQ(c.get(u + "?from=2026-03-02&to=2026-03-01", oper).status, 400);
  EXPECT_EQ(c.get(u + "?from=2024-01-01&to=2026-01-01", oper).status, 400);  // past 366 days
  EXPECT_EQ(c.get("/api/machines/mill-1/tools?to=yesterday", oper).status, 400);
  EXPECT_EQ(c.get("/api/machines/lathe-9/utilisation", oper).status, 404);
  EXPECT_EQ(c.get("/api/machines/lathe-9/tools", oper).status, 404);
  const auto week = c.get(u + "?from=2026-02-27&to=2026-03-01", oper);
  ASSERT_EQ(week.status, 200);
  const auto j = week.json();
  ASSERT_EQ(j["days"].size(), 3u);  // 2026 is no leap year
  EXPECT_EQ(j["days"][2]["date"], "2026-03-01");
  EXPECT_EQ(j["days"][0]["parts"], 0);
}

}  // namespace
}  // namespace usina::dnc
