// A job started at a block or a tool (docs/resume.md): the simulated
// control gets the restart's preamble and the program's rest, framed and
// hashed like any job; a start usina cannot restore is 400 with the reason.
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/resume.hpp"
#include "dnc/sha256.hpp"

namespace usina::dnc {
namespace {

using test::ApiClient;
using test::RunningServer;

const std::string kProgram =
    "G21 G90\nN10 T1 M6\nN20 S900 M3\nN30 G0 X1 Y1 Z5\nN40 G1 Z-1 F300\nN50 G1 X5\nN60 M2\n";

TEST(ApiResume, AJobStartedAtBlockNSendsThePreambleAndTheRest) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string rev = released(c, "O760", kProgram);
  const std::string oper = c.log_in("oper", test::kPassword);
  const test::Reply r = c.post(
      "/api/machines/mill-1/jobs",
      {{"program", "O760"}, {"revision", rev}, {"mode", "drip"}, {"start_block", "N50"}}, oper);
  ASSERT_EQ(r.status, 201) << r.body;
  const auto job = wait_for_end(c, oper, r.json()["job"].get<std::int64_t>());
  ASSERT_EQ(job["state"], "done") << job.dump();
  const auto restart = resume_program(kProgram, "rs274ngc", {gcode::ResumeStart::Kind::NWord, 50});
  ASSERT_TRUE(restart) << restart.error();
  const std::string wire = "%\n" + *restart + "%";
  const std::string got = s.on_loop(
      [&] { return std::string(control.sim->data().begin(), control.sim->data().end()); });
  EXPECT_EQ(got, wire);
  EXPECT_EQ(job["sha256"], sha256_hex(std::string_view(wire)));
  // Checked by hand: the tool, the spindle, up to Z5, over X1 Y1, down to
  // Z-1 at F300, then N50 on.
  EXPECT_NE(got.find("T1 M6\nS900 M3\nG0 Z5\nG0 X1 Y1\nG1 Z-1 F300\n"), std::string::npos) << got;
  EXPECT_EQ(got.substr(got.size() - 18), "N50 G1 X5\nN60 M2\n%");
  EXPECT_EQ(got.find("N40"), std::string::npos) << "nothing before the start is sent";
}

TEST(ApiResume, AStartThatCannotBeRestoredIs400WithTheReason) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string rev = released(c, "O770", kProgram);
  const std::string oper = c.log_in("oper", test::kPassword);
  const auto order = [&](const char* key, const nlohmann::json& v) {
    return c.post("/api/machines/mill-1/jobs",
                  {{"program", "O770"}, {"revision", rev}, {"mode", "drip"}, {key, v}}, oper);
  };
  const test::Reply past = order("start_block", 99);
  EXPECT_EQ(past.status, 400);
  EXPECT_NE(past.body.find("past the end"), std::string::npos) << past.body;
  const test::Reply tool = order("start_tool", 7);
  EXPECT_EQ(tool.status, 400);
  EXPECT_NE(tool.body.find("T7"), std::string::npos) << tool.body;
  EXPECT_EQ(order("start_block", "X12").status, 400);
}

TEST(ApiResume, ARemoteRequestWithAStartBlockGetsTheRestartProgram) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  released(c, "O1234", kProgram);
  punch(s, control, "%\nO9999\n(/REQ 1234 /BL 50)\n%");
  const auto restart = resume_program(kProgram, "rs274ngc", {gcode::ResumeStart::Kind::NWord, 50});
  ASSERT_TRUE(restart) << restart.error();
  const std::string wire = "%\n" + *restart + "%";
  EXPECT_EQ(received_once(s, control, wire), wire);
}

TEST(ApiResume, ARemoteRequestWithAToolNeverUsedGetsTheReason) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  released(c, "O1234", kProgram);
  punch(s, control, "%\nO9999\n(PRG=1234 TO=9)\n%");
  const std::string got = received_once(s, control, "NEVER");
  EXPECT_NE(got.find("T9 IS NEVER"), std::string::npos) << got;
  EXPECT_EQ(got.find("G21"), std::string::npos) << "no program is sent";
}

}  // namespace
}  // namespace usina::dnc
