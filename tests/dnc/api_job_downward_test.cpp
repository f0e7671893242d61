// What goes down to the machine with a job and what comes back as its
// state (seed 004 table 7.3): a job's answer carries the time its
// revision's check expects, its tools and its setup sheets; a machine
// whose last job ended in an alarm says so until another job runs.
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/link_serial.hpp"
#include "dnc/sim_cnc.hpp"

namespace usina::dnc {
namespace {

using test::ApiClient;
using test::RunningServer;

const std::string kTwoTools = "G21 G90\nT1 M6\nG1 X10 F100\nT2 M6\nG1 X-10 F100\nM2\n";

TEST(ApiJobDownward, AJobCarriesTheExpectedTimeItsToolsAndItsSheets) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string rev = released(c, "O720", kTwoTools);
  const std::string oper = c.log_in("oper", test::kPassword);
  const std::string boss = c.log_in("boss", test::kPassword);
  const auto sheet = c.post("/api/programs/O720/revisions/" + rev + "/sheet",
                            {{"format", "html"}, {"text", "<p>vise, zero front left</p>"}}, boss);
  ASSERT_EQ(sheet.status / 100, 2) << sheet.body;
  const auto r = c.post("/api/machines/mill-1/jobs",
                        {{"program", "O720"}, {"revision", rev}, {"mode", "send"}}, oper);
  ASSERT_EQ(r.status, 201) << r.body;
  const auto done = wait_for_end(c, oper, r.json()["job"].get<std::int64_t>());
  ASSERT_EQ(done["state"], "done");
  const auto job = c.get("/api/jobs/" + std::to_string(r.json()["job"].get<std::int64_t>()), oper);
  ASSERT_EQ(job.status, 200) << job.body;
  const auto j = job.json();
  // 2 × 10 mm at 100 mm/min is 12 s of cutting; the check's estimate holds it.
  ASSERT_TRUE(j["expected_cycle_s"].is_number()) << j.dump();
  EXPECT_GE(j["expected_cycle_s"].get<double>(), 12.0);
  ASSERT_EQ(j["tools"].size(), 2u) << j.dump();
  EXPECT_EQ(j["tools"][0]["tool"], 1);
  EXPECT_EQ(j["tools"][1]["tool"], 2);
  EXPECT_GT(j["tools"][1]["total_s"].get<double>(), 5.9);
  ASSERT_EQ(j["sheets"].size(), 1u);
  EXPECT_EQ(j["sheets"][0]["format"], "html");
}

TEST(ApiJobDownward, AMachineWhoseLastJobEndedInAnAlarmSaysSo) {
  RunningServer s;
  auto pair = open_pty_pair(s.io());
  ASSERT_TRUE(pair) << pair.error();
  Control control;
  control.link = std::move(pair->master);
  SimCncConfig sc;
  sc.lose_xon = true;       // an XOFF never released
  sc.execute_rate = 200.0;  // bytes a second: the buffer fills
  control.sim = std::make_shared<SimCnc>(s.io(), *control.link, sc);
  control.sim->start();
  ServerConfig config;
  config.machines.push_back(pty_machine("mill-1", pair->slave_path, 115200));
  config.machines.back().link.xon_timeout = 0.3;
  s.start(config);
  const ApiClient c = s.client();
  std::string program = "G21 G90\n";
  for (int i = 0; i < 100; ++i)
    program += "G1 X" + std::to_string(i) + " F300\n";  // past the control's high water
  program += "M2\n";
  const std::string rev = released(c, "O730", program);
  const std::string oper = c.log_in("oper", test::kPassword);
  EXPECT_TRUE(c.get("/api/machines/mill-1", oper).json()["alarm"].is_null());
  const auto r = c.post("/api/machines/mill-1/jobs",
                        {{"program", "O730"}, {"revision", rev}, {"mode", "drip"}}, oper);
  ASSERT_EQ(r.status, 201) << r.body;
  const auto id = r.json()["job"].get<std::int64_t>();
  const auto ended = wait_for_end(c, oper, id);
  ASSERT_TRUE(ended["alarm"].get<bool>()) << ended.dump();
  const auto machine = c.get("/api/machines/mill-1", oper).json();
  ASSERT_TRUE(machine["alarm"].is_object()) << machine.dump();
  EXPECT_EQ(machine["alarm"]["job"], id);
  EXPECT_EQ(machine["alarm"]["reason"], ended["reason"]);
  EXPECT_EQ(machine["state"], "idle");  // the link is there; the alarm is the job's
}

}  // namespace
}  // namespace usina::dnc
