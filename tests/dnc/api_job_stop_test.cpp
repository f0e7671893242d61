// POST /api/jobs/{job}/stop: a running job stops interrupted where it was;
// a queued one leaves the queue with nothing sent, and the machine goes on
// with the job that runs; a job that has ended cannot be stopped.
#include <chrono>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "api_control.hpp"

namespace usina::dnc {
namespace {

using test::ApiClient;
using test::RunningServer;

// 300 blocks: at 1,200 baud a drip feed of it lasts about 40 s.
std::string long_program() {
  std::string text;
  for (int n = 1; n <= 300; ++n)
    text += "N" + std::to_string(n * 10) + " G1 X" + std::to_string(n % 50) + " F500\n";
  return text + "M2\n";
}

nlohmann::json job_of(const ApiClient& c, const std::string& token, std::int64_t id) {
  return c.get("/api/jobs/" + std::to_string(id), token).json();
}

std::int64_t submit(const ApiClient& c, const std::string& token, const std::string& rev) {
  const auto r = c.post("/api/machines/mill-1/jobs",
                        {{"program", "O750"}, {"revision", rev}, {"mode", "drip"}}, token);
  EXPECT_EQ(r.status, 201) << r.body;
  return r.json().value("job", std::int64_t{-1});
}

TEST(ApiJobStop, AQueuedJobLeavesTheQueueWithNothingSentAndTheRunningOneGoesOn) {
  RunningServer s;
  Control control = start_with_control(s, 1200);
  const ApiClient c = s.client();
  const std::string rev = released(c, "O750", long_program());
  const std::string oper = c.log_in("oper", test::kPassword);
  const std::int64_t first = submit(c, oper, rev);
  for (int i = 0; i < 600 && job_of(c, oper, first)["state"] != "running"; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_EQ(job_of(c, oper, first)["state"], "running");
  const std::int64_t second = submit(c, oper, rev);
  ASSERT_EQ(job_of(c, oper, second)["state"], "queued");

  const test::Reply stopped = c.post("/api/jobs/" + std::to_string(second) + "/stop", {}, oper);
  ASSERT_EQ(stopped.status, 200) << stopped.body;
  const auto cancelled = job_of(c, oper, second);
  EXPECT_EQ(cancelled["state"], "interrupted");
  EXPECT_EQ(cancelled["bytes_sent"], 0);
  EXPECT_NE(cancelled["reason"].get<std::string>().find("stopped by oper before it started"),
            std::string::npos)
      << cancelled.dump();
  EXPECT_EQ(job_of(c, oper, first)["state"], "running");

  // The running one stopped too: the machine is idle, the cancelled job never started.
  EXPECT_EQ(c.post("/api/jobs/" + std::to_string(first) + "/stop", {}, oper).status, 202);
  EXPECT_EQ(wait_for_end(c, oper, first)["state"], "interrupted");
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(c.get("/api/machines/mill-1", oper).json()["state"], "idle");
  EXPECT_TRUE(job_of(c, oper, second)["started_at_us"].is_null());

  const test::Reply again = c.post("/api/jobs/" + std::to_string(second) + "/stop", {}, oper);
  EXPECT_EQ(again.status, 409);
  EXPECT_NE(again.body.find("not running or queued"), std::string::npos) << again.body;
}

}  // namespace
}  // namespace usina::dnc
