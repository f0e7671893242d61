// The CL records of the point-to-point and post-processor statements, and
// the canon stream made from them.
#include "apt/canon_out.hpp"
#include "apt_run.hpp"
#include "canon/trace_writer.hpp"

namespace usina::apt::test {
namespace {

std::string print(const std::string& program) {
  const AptRun r = run(program);
  EXPECT_FALSE(r.diags.has_errors()) << (r.diags.all().empty() ? "" : r.diags.all()[0].message);
  return record_print(r.result.records);
}

class Collect final : public canon::Sink {
 public:
  // The trace line, and "|cycle" for a move a canned cycle made.
  void on(const canon::Op& op) override {
    lines.push_back(canon::to_jsonl(op) + (op.origin == canon::Origin::Cycle ? "|cycle" : ""));
  }

  std::vector<std::string> lines;
};

std::vector<std::string> trace(const std::string& program, double scale = 1.0) {
  const AptRun r = run(program);
  EXPECT_FALSE(r.diags.has_errors());
  Collect c;
  to_canon(r.result.records, scale, c);
  for (std::string& l : c.lines)  // drop "src", which says the line
    l.erase(l.find(",\"src\""), l.find(']', l.find(",\"src\"")) + 1 - l.find(",\"src\""));
  return c.lines;
}

TEST(AptCl, PartnoIsElevenTextWords) {
  EXPECT_EQ(print("PARTNO APT-1\nFINI\n"),
            "1 1000 1 2 0 ''\n2 2000 1045 11 ' APT-1' '' '' '' '' '' '' '' '' '' ''\n"
            "3 1000 2 2 0 ''\n4 14000 0 0 \n");
}

TEST(AptCl, TolerancesCutterAndPostWords) {
  EXPECT_EQ(print("INTOL/0\nOUTTOL/.005\nCUTTER/.25\nSPINDL/2000,CLW\nCOOLNT/ON\nFEDRAT/20\n"
                  "END\nFINI\n"),
            "1 1000 1 2 0 ''\n2 6000 4 4 0 0 0 0\n3 1000 2 2 0 ''\n"
            "4 6000 5 4 0.005 0.005 0.005 0.005\n5 1000 3 2 0 ''\n6 6000 6 1 0.25\n"
            "7 1000 4 2 0 ''\n8 2000 1031 2 2000 #60\n9 1000 5 2 0 ''\n10 2000 1030 1 #71\n"
            "11 1000 6 2 0 ''\n12 2000 1009 1 20\n13 1000 7 2 0 ''\n14 2000 1 0 \n"
            "15 1000 8 2 0 ''\n16 14000 0 0 \n");
}

TEST(AptCl, FromGotoGodlta) {
  EXPECT_EQ(print("SP=POINT/1,2,3\nFROM/SP\nRAPID,GOTO/4,5\nGODLTA/-1\nGODLTA/1,1,1\nFINI\n"),
            "1 1000 2 2 0 ''\n2 5000 3 5 '    SP' 0 1.0000000 2.0000000 3.0000000\n"
            "3 1000 3 2 0 ''\n4 2000 5 0 \n5 5000 5 5 0 0 4.0000000 5.0000000 0.0000000\n"
            "6 1000 4 2 0 ''\n7 5000 5 5 'TLAXIS' 0 4.0000000 5.0000000 -1.0000000\n"
            "8 1000 5 2 0 ''\n9 5000 5 5 0 0 5.0000000 6.0000000 0.0000000\n"
            "10 1000 6 2 0 ''\n11 14000 0 0 \n");
}

TEST(AptCl, MotionWithoutCheckSurfaceAtTheEndIsAnError) {
  // GOLFT/L1 takes its check surface from the next motion; there is none.
  const AptRun r = run("L1=LINE/0,0,1,0\nFROM/0,0,0\nTLLFT,GOLFT/L1\nGODLTA/1\nFINI\n");
  ASSERT_EQ(r.diags.error_count(), 2);
  EXPECT_EQ(r.diags.all()[0].code, core::Code::AptBadArgument);
  EXPECT_EQ(r.diags.all()[0].loc.line, 3u);
  EXPECT_NE(r.diags.all()[0].message.find("has no check surface"), std::string::npos);
  // GODLTA then moves from an unknown place.
  EXPECT_NE(r.diags.all()[1].message.find("start is unknown"), std::string::npos);
}

TEST(AptCl, BadArgumentsOfStatements) {
  EXPECT_TRUE(run("GOTO/1\nFINI\n").has(core::Code::AptBadArgument));
  EXPECT_TRUE(run("CUTTER/ON\nFINI\n").has(core::Code::AptBadArgument));
  EXPECT_TRUE(run("P=POINT/1,2\nFEDRAT/P\nFINI\n").has(core::Code::AptBadArgument));
  EXPECT_TRUE(run("GOTO/1,2,3,4\nFINI\n").has(core::Code::AptNotSupported));
  EXPECT_TRUE(run("LOOPST\nFINI\n").has(core::Code::AptNotSupported));
}

TEST(AptCl, FailedStatementWritesNoRecord) {
  EXPECT_EQ(record_print(run("GOTO/Q\nFINI\n").result.records), "1 1000 2 2 0 ''\n2 14000 0 0 \n");
}

TEST(AptCanon, PointToPointProgram) {
  const auto t = trace(
      "PARTNO DEMO\nCUTTER/10\nLOADTL/3\nSPINDL/1200,CCLW\nCOOLNT/FLOOD\nFEDRAT/250\n"
      "FROM/0,0,50\nRAPID,GOTO/10,10,5\nGOTO/10,10,-2\nGOTO/20,10,-2\nPPRINT HELLO\n"
      "DELAY/2\nCOOLNT/OFF\nSPINDL/OFF\nEND\nFINI\n");
  const std::vector<std::string> want = {R"({"op":"comment","text":"DEMO"})",
                                         R"({"op":"tool","tool":3,"diameter":10})",
                                         R"({"op":"spindle","rpm":1200,"dir":"ccw"})",
                                         R"({"op":"coolant","mist":false,"flood":true})",
                                         R"({"op":"traverse","to":[0,0,50]})",
                                         R"({"op":"traverse","to":[10,10,5]})",
                                         R"({"op":"feed","to":[10,10,-2],"f":250})",
                                         R"({"op":"feed","to":[20,10,-2],"f":250})",
                                         R"({"op":"comment","text":"HELLO"})",
                                         R"({"op":"dwell","s":2})",
                                         R"({"op":"coolant","mist":false,"flood":false})",
                                         R"({"op":"spindle","rpm":1200,"dir":"off"})",
                                         R"({"op":"end"})"};
  EXPECT_EQ(t, want);
}

TEST(AptCanon, InchProgramIsScaledToMm) {
  const auto t = trace("FEDRAT/10\nFROM/0,0,0\nGOTO/1,2,0\nFINI\n", 25.4);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[1], R"({"op":"feed","to":[25.4,50.8,0],"f":254})");
}

TEST(AptCanon, DrillCycleDrillsEachPoint) {
  const auto t = trace(
      "CUTTER/6\nFROM/0,0,10\nCYCLE/DRILL,5,MMPM,100,2\nGOTO/10,0,0\n"
      "CYCLE/OFF\nGOTO/0,0,10\nFINI\n");
  ASSERT_EQ(t.size(), 6u);
  EXPECT_EQ(t[1], R"({"op":"traverse","to":[10,0,2]}|cycle)");
  EXPECT_EQ(t[2], R"({"op":"feed","to":[10,0,-5],"f":100}|cycle)");
  EXPECT_EQ(t[3], R"({"op":"traverse","to":[10,0,2]}|cycle)");
  EXPECT_EQ(t[4].substr(0, 24), R"({"op":"hole","at":[10,0,)");
}

}  // namespace
}  // namespace usina::apt::test
