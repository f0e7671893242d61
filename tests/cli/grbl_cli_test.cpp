// `usina trace --dialect grbl` as a user runs it: Grbl's error numbers on
// standard error, the trace of the accepted lines, the exit status.
#include <stdio.h>

#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>

namespace {

struct Result {
  int status = -1;
  std::string out;
};

// Runs `usina <args>` with standard error joined to standard output and
// `input` (no quotes in it) on standard input.
Result usina(const std::string& args, const std::string& input = "") {
  const std::string cmd =
      "printf '%b' '" + input + "' | '" + std::string(USINA_BINARY) + "' " + args + " 2>&1";
  Result r;
  FILE* p = popen(cmd.c_str(), "r");
  EXPECT_NE(p, nullptr);
  if (p == nullptr) return r;
  char buf[4096];
  std::size_t n = 0;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0)
    r.out.append(buf, n);
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

const std::string kDir = std::string(USINA_TEST_DIR) + "/programs/grbl/";

TEST(CliGrbl, TracesACamFileWithoutEndWarning) {
  const Result r = usina("trace --dialect grbl '" + kDir + "cncjs_g2_arc.gcode'");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("{\"op\":\"arc\",\"src\":[7,1],\"to\":[50,40,0]"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("W_NO_PROGRAM_END"), std::string::npos) << r.out;
}

TEST(CliGrbl, ErrorsCarryGrblsNumberAndTheRunGoesOn) {
  const Result r = usina("trace --dialect grbl -", "G1 X1\\nG81 X1\\nG0 X2\\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("<stdin>:1:1: error: grbl error:22 (Undefined feed rate)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("grbl error:20 (Unsupported command): G81"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("[E_GRBL]"), std::string::npos);
  EXPECT_NE(r.out.find("\"to\":[2,0,0]"), std::string::npos) << r.out;
}

TEST(CliGrbl, StopOptionAndBadOption) {
  const Result r =
      usina("trace --dialect grbl --dialect-option after_error=stop -", "G1 X1\\nG0 X2\\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out.find("\"to\":[2,0,0]"), std::string::npos) << r.out;
  const Result bad = usina("trace --dialect grbl --dialect-option after_error=maybe -", "G0 X1\\n");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("continue|stop"), std::string::npos) << bad.out;
}

}  // namespace
