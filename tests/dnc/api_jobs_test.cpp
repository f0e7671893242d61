// Jobs over HTTP to a simulated control on a pty: what reaches the control
// is what the job's hash says; only a revision the machine may take goes;
// (a start inside the program: api_resume_test.cpp); a job cut off by the
// server stopping (or dying) is interrupted, never resent.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/link_serial.hpp"
#include "dnc/sim_cnc.hpp"
#include "dnc/store_jobs.hpp"

namespace usina::dnc {
namespace {

using test::ApiClient;
using test::RunningServer;

const std::string kProgram = "G21 G90\nN10 G0 X1 Y1\nN20 G1 X5 F300\nN30 M2\n";

TEST(ApiJobs, ASendReachesTheControlAndTheJobCarriesTheHashOfWhatWentOut) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string rev = released(c, "O700", kProgram);
  const std::string oper = c.log_in("oper", test::kPassword);
  const test::Reply r = c.post("/api/machines/mill-1/jobs",
                               {{"program", "O700"}, {"revision", rev}, {"mode", "send"}}, oper);
  ASSERT_EQ(r.status, 201) << r.body;
  const auto job = wait_for_end(c, oper, r.json()["job"].get<std::int64_t>());
  ASSERT_EQ(job["state"], "done") << job.dump();
  const std::string wire = "%\nG21 G90\nN10 G0 X1 Y1\nN20 G1 X5 F300\nN30 M2\n%";
  EXPECT_EQ(job["bytes_sent"], wire.size());
  EXPECT_EQ(job["bytes_total"], wire.size());
  EXPECT_EQ(job["block"], 30);
  EXPECT_EQ(job["sha256"], sha256_hex(std::string_view(wire)));
  const std::string got = s.on_loop(
      [&] { return std::string(control.sim->data().begin(), control.sim->data().end()); });
  EXPECT_EQ(got, wire);
  const auto machine = c.get("/api/machines/mill-1", oper).json();
  EXPECT_EQ(machine["state"], "idle");
  EXPECT_EQ(machine["part_count"], 0);  // a send stores the program; it runs no part
}

TEST(ApiJobs, ADripFeedIsAPartWithItsCycleTime) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string rev = released(c, "O710", kProgram);
  const std::string oper = c.log_in("oper", test::kPassword);
  const auto r = c.post("/api/machines/mill-1/jobs",
                        {{"program", "O710"}, {"revision", rev}, {"mode", "drip"}}, oper);
  ASSERT_EQ(r.status, 201) << r.body;
  EXPECT_EQ(wait_for_end(c, oper, r.json()["job"])["state"], "done");
  const auto machine = c.get("/api/machines/mill-1", oper).json();
  EXPECT_EQ(machine["part_count"], 1);
  EXPECT_GE(machine["last_cycle_seconds"].get<double>(), 0.0);
  EXPECT_EQ(machine["last_program"], "O710");
}

TEST(ApiJobs, OnlyTheReleasedRevisionGoesToAProductionMachine) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string prog = c.log_in("prog", test::kPassword);
  const std::string draft =
      c.post("/api/programs", {{"name", "O720"}, {"text", kProgram}}, prog).json()["revision"];
  const auto order = [&](const std::string& rev) {
    return c.post("/api/machines/mill-1/jobs",
                  {{"program", "O720"}, {"revision", rev}, {"mode", "send"}}, prog);
  };
  const test::Reply refused = order(draft);
  EXPECT_EQ(refused.status, 409);
  EXPECT_NE(refused.body.find("draft"), std::string::npos) << refused.body;
  EXPECT_EQ(order(std::string(64, 'e')).status, 404);
  EXPECT_EQ(c.post("/api/machines/mill-9/jobs",
                   {{"program", "O720"}, {"revision", draft}, {"mode", "send"}}, prog)
                .status,
            404);
  EXPECT_EQ(c.post("/api/machines/mill-1/jobs",
                   {{"program", "O720"}, {"revision", draft}, {"mode", "punch"}}, prog)
                .status,
            400);
}

TEST(ApiJobs, AJobCutOffByTheServerStoppingIsInterruptedAndStaysSo) {
  RunningServer s;
  Control control = start_with_control(s, 1200);  // 109 bytes a second: it runs for a while
  const ApiClient c = s.client();
  std::string text;
  for (int n = 1; n <= 300; ++n)
    text += "N" + std::to_string(n * 10) + " G1 X" + std::to_string(n % 50) + " F500\n";
  text += "M2\n";
  const std::string rev = released(c, "O740", text);
  const std::string oper = c.log_in("oper", test::kPassword);
  const auto r = c.post("/api/machines/mill-1/jobs",
                        {{"program", "O740"}, {"revision", rev}, {"mode", "drip"}}, oper);
  ASSERT_EQ(r.status, 201) << r.body;
  const std::int64_t id = r.json()["job"];
  // Queued until the port is open (it opens as the server starts), then running.
  for (int i = 0;
       i < 600 && c.get("/api/jobs/" + std::to_string(id), oper).json()["state"] != "running"; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_EQ(c.get("/api/jobs/" + std::to_string(id), oper).json()["state"], "running");
  const auto machine = c.get("/api/machines/mill-1", oper).json();
  EXPECT_EQ(machine["state"], "sending");
  EXPECT_EQ(machine["job"]["job"], id);
  EXPECT_EQ(machine["job"]["state"], "running");
  EXPECT_GT(machine["job"]["bytes_total"].get<std::uint64_t>(), text.size());
  EXPECT_LT(machine["job"]["bytes_sent"].get<std::uint64_t>(),
            machine["job"]["bytes_total"].get<std::uint64_t>());
  EXPECT_TRUE(machine["job"].contains("block"));
  s.stop();
  auto store = Store::open(s.dir(), test::fast_store());
  ASSERT_TRUE(store);
  auto job = find_job(**store, id);
  ASSERT_TRUE(job);
  EXPECT_EQ(job->state, "interrupted");
  EXPECT_NE(job->reason.find("the test stopped the server"), std::string::npos) << job->reason;
  EXPECT_LT(job->bytes_sent, job->bytes_total);
}

TEST(ApiJobs, AJobLeftRunningByADeadServerIsInterruptedWhenItStartsAgain) {
  RunningServer s;
  std::int64_t id = 0;
  {
    auto store = Store::open(s.dir(), test::fast_store());
    ASSERT_TRUE(store);
    JobRecord j;
    j.machine = "mill-1";
    j.program = "O750";
    j.revision = std::string(64, 'a');
    j.mode = "drip";
    j.state = "running";
    j.actor = "oper";
    auto made = create_job(**store, j, Actor{"oper", "test"});
    ASSERT_TRUE(made);
    id = made->id;
  }
  s.start();
  const ApiClient c = s.client();
  const auto job = c.get("/api/jobs/" + std::to_string(id), c.log_in("oper", test::kPassword));
  EXPECT_EQ(job.json()["state"], "interrupted") << job.body;
  EXPECT_EQ(c.get("/api/jobs/999999", c.log_in("oper", test::kPassword)).status, 404);
}

}  // namespace
}  // namespace usina::dnc
