// The readers of NX CLSF and APT CL text: statements into CL records into
// the canon stream, the arc direction of each dialect, and every error at
// its line and column.
#include "apt/cl_text.hpp"

#include "apt/canon_out.hpp"
#include "apt_run.hpp"
#include "canon/trace_writer.hpp"

namespace usina::apt::test {
namespace {

struct ClRun {
  std::vector<std::string> ops;  // jsonl without "src"
  core::DiagnosticList diags;

  std::string first_error() const {
    for (const core::Diagnostic& d : diags.all())
      return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.col) + " " +
             std::string(core::code_name(d.code)) + " " + d.message;
    return "";
  }
};

class Collect final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    std::string l = canon::to_jsonl(op);
    const std::size_t s = l.find(",\"src\"");
    l.erase(s, l.find(']', s) + 1 - s);
    lines.push_back(l);
  }

  std::vector<std::string> lines;
};

ClRun read(const std::string& text, ClDialect d = ClDialect::Clsf) {
  ClRun r;
  Collect c;
  ClToCanon canon(1.0, c);
  ClConsumer out{[&canon](ClRecord&& rec) {
                   canon.record(rec);
                   return true;
                 },
                 [&canon](double s) { canon.set_scale(s); }};
  read_cl_text(text, 0, d, r.diags, out);
  r.ops = c.lines;
  return r;
}

const char* kNxArc =
    "TOOL PATH/OUTLINE,TOOL,D20\n"
    "TLDATA/MILL,20.0000,0.0000,75.0000,0.0000,0.0000\n"
    "MSYS/0,0,0,1,0,0,0,1,0\n"
    "$$ centerline data\n"
    "PAINT/PATH\n"
    "LOAD/TOOL,1,ADJUST,1\n"
    "RAPID\n"
    "GOTO/-10.0000,20.0000,70.0000,0.0000000,0.0000000,1.0000000\n"
    "FEDRAT/MMPM,1000.0000\n"
    "CIRCLE/0.0000,20.0000,70.0000,0.0000000,0.0000000,-1.0000000,10.0000,0.0600,0.5000\n"
    "GOTO/0.0000,10.0000,70.0000\n"
    "END-OF-PATH\n";

TEST(AptClText, NxArcWithMinusKRunsCounterClockwise) {
  const ClRun r = read(kNxArc);
  EXPECT_FALSE(r.diags.has_errors()) << r.first_error();
  EXPECT_EQ(
      r.ops,
      (std::vector<std::string>{
          R"({"op":"comment","text":"TOOL PATH/OUTLINE,TOOL,D20"})",
          R"({"op":"tool","tool":1,"diameter":20})", R"({"op":"traverse","to":[-10,20,70]})",
          R"({"op":"arc","to":[0,10,70],"center":[0,20,70],"normal":[0,0,1],"turn":1,"f":1000})"}));
}

TEST(AptClText, AptClArcWithPlusKRunsCounterClockwise) {
  // SolidWorks CAM: the right-hand rule, no radius (the start gives it).
  const ClRun r = read(
      "UNIT/MM\nFEDRAT/1143.,MMPM\nGOTO/107.058579,205.294336,-1.\n"
      "CIRCLE/107.2,205.152915,-1.,0,0,1.\nGOTO/107.,205.152915,-1.\nFINI\n",
      ClDialect::AptCl);
  EXPECT_FALSE(r.diags.has_errors()) << r.first_error();
  ASSERT_EQ(r.ops.size(), 2u);
  EXPECT_NE(r.ops[1].find(R"("normal":[0,0,1],"turn":1)"), std::string::npos) << r.ops[1];
  // The same text read as NX turns the other way.
  const ClRun nx = read(
      "GOTO/107.058579,205.294336,-1.\nCIRCLE/107.2,205.152915,-1.,0,0,1.\n"
      "GOTO/107.,205.152915,-1.\n");
  EXPECT_NE(nx.ops[1].find(R"("normal":[0,0,-1],"turn":1)"), std::string::npos) << nx.ops[1];
}

TEST(AptClText, PostWordsInEitherOrderAndDrillCycles) {
  const ClRun r = read(
      "UNIT/MM\nCUTTER/10.1,0,5.05\nLOAD/TOOL,20\nCOOLNT/FLOOD\nSPINDL/3500,RPM,CLW\n"
      "RAPID/\nGOTO/20.,125.,25.\nCYCLE/INIT\n"
      "CYCLE/DEEP2,FEDTO,5.,1STPECK,5.,SUBPECK,2.,MMPM,382.,RAPTO,3.,RTRCTO,25.\n"
      "GOTO/20.,125.,0\nCYCLE/OFF\nSPINDL/OFF\nFINI\nGOTO/9,9,9\n",
      ClDialect::AptCl);
  EXPECT_FALSE(r.diags.has_errors()) << r.first_error();
  EXPECT_EQ(
      r.ops,
      (std::vector<std::string>{
          R"({"op":"tool","tool":20,"diameter":10.1})",
          R"({"op":"coolant","mist":false,"flood":true})",
          R"({"op":"spindle","rpm":3500,"dir":"cw"})", R"({"op":"traverse","to":[20,125,25]})",
          R"({"op":"comment","text":"APT CYCLE/INIT"})", R"({"op":"traverse","to":[20,125,3]})",
          R"({"op":"feed","to":[20,125,-5],"f":382})", R"({"op":"traverse","to":[20,125,3]})",
          R"({"op":"hole","at":[20,125,0],"diameter":10.1,"depth":5})",
          R"({"op":"spindle","rpm":3500,"dir":"off"})"}));
}

TEST(AptClText, NxCycleTakesTheLastFeedAndANegativeDepth) {
  const ClRun r =
      read("FEDRAT/MMPM,250\nGOTO/0,0,80\nCYCLE/DRILL,RAPTO,3,FEDTO,-12\nGOTO/1,2,0\nCYCLE/OFF\n");
  EXPECT_FALSE(r.diags.has_errors()) << r.first_error();
  ASSERT_EQ(r.ops.size(), 5u);
  EXPECT_EQ(r.ops[2], R"({"op":"feed","to":[1,2,-12],"f":250})");
}

TEST(AptClText, AFeedRateEndsACycleThatAToolChangeDoesNot) {
  // SolidWorks CAM: the cycle lasts across LOAD/TOOL; a RAPID GOTO positions
  // above the next holes; a milling operation after it sets its FEDRAT with
  // no CYCLE/OFF before.
  const ClRun r = read(
      "GOTO/0,0,50\nCYCLE/DRILL,FEDTO,5.,MMPM,100.,RAPTO,3.\nGOTO/0,0,0\nLOAD/TOOL,2\n"
      "GOTO/1,0,0\nRAPID/\nGOTO/2,0,50\nFEDRAT/300.,MMPM\nGOTO/2,0,0\n",
      ClDialect::AptCl);
  EXPECT_FALSE(r.diags.has_errors()) << r.first_error();
  int holes = 0;
  for (const std::string& op : r.ops)
    holes += op.find("\"hole\"") != std::string::npos ? 1 : 0;
  EXPECT_EQ(holes, 2);  // a RAPID motion in a cycle positions, drills nothing
  EXPECT_EQ(r.ops.back(), R"({"op":"feed","to":[2,0,0],"f":300})");
}

TEST(AptClText, UnitsInchesScaleWhatFollows) {
  const ClRun r =
      read("GOTO/1,0,0\nUNITS/INCHES\nGOTO/1,0,0\nFEDRAT/10,IPM\nGOTO/2,0,0\n", ClDialect::AptCl);
  EXPECT_FALSE(r.diags.has_errors()) << r.first_error();
  EXPECT_EQ(r.ops[0], R"({"op":"feed","to":[1,0,0],"f":null})");
  EXPECT_EQ(r.ops[1], R"({"op":"feed","to":[25.4,0,0],"f":null})");
  EXPECT_EQ(r.ops[2], R"({"op":"feed","to":[50.8,0,0],"f":254})");
}

TEST(AptClText, ContinuationsCommentsBlanksAndText) {
  const ClRun r = read(
      "PARTNO 'BRACKET, REV 2'\n  GOTO  / 1, $\n  2,3 $$ a comment\n"
      "PPRINT/ONE, TWO $$ three\n$$ GOTO/9,9,9\nGODLTA/-1\n",
      ClDialect::AptCl);
  EXPECT_FALSE(r.diags.has_errors()) << r.first_error();
  EXPECT_EQ(r.ops, (std::vector<std::string>{R"({"op":"comment","text":"BRACKET, REV 2"})",
                                             R"({"op":"feed","to":[1,2,3],"f":null})",
                                             R"({"op":"comment","text":"ONE, TWO"})",
                                             R"({"op":"feed","to":[1,2,2],"f":null})"}));
}

void expect_error(const std::string& text, const std::string& want) {
  const ClRun r = read(text);
  EXPECT_NE(r.first_error().find(want), std::string::npos) << r.first_error();
}

TEST(AptClText, EveryErrorAtItsLineAndColumn) {
  expect_error("GOTO/1,2\n", "1:1 E_CL_BAD_ARGUMENT GOTO/ takes x,y,z or x,y,z,i,j,k (2");
  expect_error("GOTO/1,2,A\n", "1:1 E_CL_BAD_ARGUMENT");
  expect_error("GOTO/0,0,0\nGOTO/1,2,3,0,0.7071,0.7071\n", "2:1 E_CL_NOT_SUPPORTED a tool axis");
  expect_error("GOTO/0,0,0,0,1,0\nGOTO/1,1,1\n", "1:1 E_CL_NOT_SUPPORTED");
  expect_error("GOTO/0,0,0\nCIRCLE/5,0,0,0,0,1,5\nGOTO/5,6,0\n", "3:1 E_CL_BAD_ARC the arc");
  expect_error("GOTO/0,0,0\nCIRCLE/5,0,0,0,0,1,4\nGOTO/5,5,0\n", "3:1 E_CL_BAD_ARC");
  expect_error("CIRCLE/5,0,0,0,0,1,5\nGOTO/5,5,0\n", "1:1 E_CL_BAD_ARC CIRCLE/ before any");
  expect_error("GOTO/0,0,0\nCIRCLE/5,0,0,0,0,1\nGOTO/1,1,1\n", "3:1 E_CL_BAD_ARC");
  expect_error("GOTO/0,0,0\nCIRCLE/5,0,0,0,0,1\nFROM/1,1,1\n",
               "2:1 E_CL_BAD_ARC CIRCLE/ is left out: another motion");
  expect_error("GOTO/0,0,0\nCIRCLE/5,0,0,0,0,1\n",
               "2:1 E_CL_BAD_ARC CIRCLE/ is left out: the file");
  expect_error("CIRCLE/5,0,0,0,0\n", "1:1 E_CL_BAD_ARGUMENT CIRCLE/ takes");
  expect_error("CIRCLE/5,0,0,0,0,0\n", "1:1 E_CL_BAD_ARGUMENT CIRCLE/'s axis");
  expect_error("GODLTA/1\n", "1:1 E_CL_BAD_ARGUMENT GODLTA/ moves from where");
  expect_error("GOTO/0,0,0\nGODLTA/1,2\n", "2:1 E_CL_BAD_ARGUMENT GODLTA/ takes");
  expect_error("NURBS/\nKNOT/0,1\nCNTRL/1,2,3\n", "1:1 E_CL_NOT_SUPPORTED NURBS/");
  expect_error("CYCLE/DRILL,FEDTO,-5\n", "1:1 E_CL_BAD_ARGUMENT CYCLE/ gives no feed");
  expect_error("UNITS/FEET\n", "1:1 E_CL_BAD_ARGUMENT UNITS/ takes MM or INCHES");
  expect_error("CUTTER/D\n", "1:1 E_CL_BAD_ARGUMENT CUTTER has no number");
  expect_error("LOAD/TOOL,1e12\n", "1:1 E_CL_BAD_ARGUMENT LOAD/ takes a tool number");
  expect_error("LOADTL/2.5\n", "1:1 E_CL_BAD_ARGUMENT LOADTL/ takes a tool number");
  expect_error("LOAD/TOOL\n", "1:1 E_CL_BAD_ARGUMENT LOAD/ takes a tool number");
  expect_error("GOTO/1,2,1e13\n", "1:10 E_CL_TOO_LARGE the number 1e13 is beyond 1e+12");
  expect_error("GOTO/1,2,1e999\n", "1:10 E_CL_TOO_LARGE the number 1e999 is out of range");
  expect_error("GOTO/0,0,1e12\nGODLTA/5\n", "2:1 E_CL_TOO_LARGE GODLTA/ goes to (0, 0, 1e+12)");
  expect_error("GOTO/-1e12,0,0\nCIRCLE/1e12,0,0,0,0,1\nGOTO/1e12,1e12,0\n", "3:1 E_CL_BAD_ARC");
  expect_error("GOTO/" + std::string(70000, '1') + "\n", "1:1 E_CL_TOO_LARGE the statement");
  std::string many = "SPINDL/";
  for (int i = 0; i < 1100; ++i)
    many += "1,";
  expect_error(many + "1\n", "E_CL_TOO_LARGE more than 1024 arguments");
}

TEST(AptClText, AStatementNotReadIsAWarningAndWhatIsSilentIsSilent) {
  const ClRun r = read("FOO/1,2\nPAINT/COLOR,31\nMSYS/0,0,0\nCSI_SET_FLUTE_LENGTH/16.\n");
  ASSERT_EQ(r.diags.all().size(), 1u);
  EXPECT_EQ(r.diags.all()[0].code, core::Code::ClIgnored);
  EXPECT_EQ(r.diags.all()[0].severity, core::Severity::Warning);
  EXPECT_TRUE(r.ops.empty());
}

TEST(AptClText, AStatementWithAnErrorIsLeftOutAndReadingGoesOn) {
  const ClRun r = read("GOTO/1\nGOTO/1,2,3\nGOTO/4\n");
  EXPECT_EQ(r.diags.error_count(), 2);
  EXPECT_EQ(r.ops, (std::vector<std::string>{R"({"op":"feed","to":[1,2,3],"f":null})"}));
}

// A text longer than a CLDATA record holds (found by fuzz_cl: written as
// CLDATA it did not read back) is an error at its line; reading goes on.
TEST(AptClText, ATextLongerThanARecordHoldsIsRefused) {
  const std::string text = "PARTNO/'" + std::string(6 * 4096 + 1, 'c') + "'\nGOTO/1,2,3\n";
  const ClRun r = read(text, ClDialect::AptCl);
  EXPECT_EQ(r.diags.error_count(), 1);
  EXPECT_EQ(r.first_error().substr(0, 20), "1:1 E_CL_BAD_RECORD ") << r.first_error();
  EXPECT_EQ(r.ops, (std::vector<std::string>{R"({"op":"feed","to":[1,2,3],"f":null})"}));
  // The longest text a record holds is read.
  const ClRun fits = read("PARTNO/'" + std::string(6 * 4096, 'c') + "'\n", ClDialect::AptCl);
  EXPECT_FALSE(fits.diags.has_errors()) << fits.first_error();
}

TEST(AptClText, EachStatementIsPrecededByItsSourceRecord) {
  core::DiagnosticList diags;
  const auto recs = read_cl_text("RAPID\nGOTO/1,2,3\n", 4, ClDialect::Clsf, diags);
  ASSERT_EQ(recs.size(), 4u);
  EXPECT_EQ(recs[0].cls, cls::kSource);
  EXPECT_EQ(recs[0].sub, 1);
  EXPECT_EQ(recs[2].sub, 2);
  EXPECT_EQ(recs[3].src.line, 2u);
  EXPECT_EQ(recs[3].src.file, 4u);
}

}  // namespace
}  // namespace usina::apt::test
