// `usina trace --dialect grbl` as a user runs it: Grbl's error numbers on
// standard error, the trace of the accepted lines, the exit status.
#include <string>

#include <gtest/gtest.h>

#include "support/usina_process.hpp"

namespace {

using usina::test::usina;
using Result = usina::test::Run;

const std::string kDir = std::string(USINA_TEST_DIR) + "/programs/grbl/";

TEST(CliGrbl, TracesACamFileWithoutEndWarning) {
  const Result r = usina("trace --dialect grbl '" + kDir + "cncjs_g2_arc.gcode'");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("{\"op\":\"arc\",\"src\":[7,1],\"to\":[50,40,0]"), std::string::npos)
      << r.out;
  EXPECT_EQ(r.err.find("W_NO_PROGRAM_END"), std::string::npos) << r.err;
}

TEST(CliGrbl, ErrorsCarryGrblsNumberAndTheRunGoesOn) {
  const Result r = usina("trace --dialect grbl -", "G1 X1\nG81 X1\nG0 X2\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("<stdin>:1:1: error: grbl error:22 (Undefined feed rate)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("grbl error:20 (Unsupported command): G81"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[E_GRBL]"), std::string::npos);
  EXPECT_NE(r.out.find("\"to\":[2,0,0]"), std::string::npos) << r.out;
}

TEST(CliGrbl, StopOptionAndBadOption) {
  const Result r =
      usina("trace --dialect grbl --dialect-option after_error=stop -", "G1 X1\nG0 X2\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out.find("\"to\":[2,0,0]"), std::string::npos) << r.out;
  const Result bad = usina("trace --dialect grbl --dialect-option after_error=maybe -", "G0 X1\n");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("continue|stop"), std::string::npos) << bad.err;
}

// Grbl reads N as a word like any other, wherever it stands (gcode.c,
// case 'N'); the interpreter gets Grbl's words, not RS274NGC's reading of
// the text, which wanted N first (a false error:20 before).
TEST(CliGrbl, ALineNumberAnywhereInTheBlockIsGrbls) {
  const Result r = usina("trace --dialect grbl -", "G1 X1 N10 F100\nM2\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("{\"op\":\"feed\",\"src\":[1,1],\"to\":[1,0,0],\"f\":100}"),
            std::string::npos)
      << r.out;
}

// A jog's move and the modes it keeps are words the front end makes: the
// next line moves in the program's own modes again.
TEST(CliGrbl, AJogKeepsTheProgramsModes) {
  const Result r = usina("trace --dialect grbl -", "G90 G1 F100\n$J=G91 X5 F500\nX1\nM2\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"to\":[5,0,0]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("{\"op\":\"feed\",\"src\":[3,1],\"to\":[1,0,0],\"f\":100}"),
            std::string::npos)
      << r.out;
}

}  // namespace
