// Numbers out of range through the command line (issue 11): the issue's
// exact cases through check, trace, convert, stats and draw, in every
// dialect. check exits 1 with the code; trace's output stays JSON lines;
// convert writes no nan or inf; stats gives no negative or non-finite time;
// draw ends with a diagnostic instead of an abort inside cairo.
#include <cmath>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/usina_process.hpp"

namespace {

using nlohmann::json;
using usina::test::contains;
using usina::test::lines;
using usina::test::quote;
using usina::test::TempDir;
using usina::test::usina;
using Result = usina::test::Run;

// The issue's two programs.
const std::string kHugeArc = "G2 X1 Y0 R[10**200] F100\nM2\n";
const std::string kInfinity = "G91 G0 X[10**308]\nG0 X[10**308]\nM2\n";
// Values in range whose sum is not: the error is at the second move.
const std::string kSum = "G91 G0 X900000000\nG0 X900000000\nM2\n";

bool has_non_number(const std::string& s) {
  return contains(s, "nan") || contains(s, "inf") || contains(s, "NaN") || contains(s, "Inf");
}

void expect_json_lines(const std::string& out) {
  for (const std::string& l : lines(out)) {
    EXPECT_FALSE(json::parse(l, nullptr, false).is_discarded()) << l;
  }
  EXPECT_FALSE(has_non_number(out)) << out;
}

TEST(NumbersCli, CheckReportsTheIssueArcAtR) {
  const Result r = usina("check -", kHugeArc);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "<stdin>:1:10: error:")) << r.err;
  EXPECT_TRUE(contains(r.err, "[E_VALUE_OUT_OF_RANGE]")) << r.err;
}

TEST(NumbersCli, CheckReportsTheIssueInfinityAtTheWord) {
  const Result r = usina("check -", kInfinity);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(contains(r.err, "<stdin>:1:8: error:")) << r.err;
  EXPECT_TRUE(contains(r.err, "[E_VALUE_OUT_OF_RANGE]")) << r.err;
}

TEST(NumbersCli, TraceStaysJsonLines) {
  for (const std::string& program : {kHugeArc, kInfinity, kSum}) {
    const Result r = usina("trace -", program);
    EXPECT_EQ(r.status, 1) << program;
    expect_json_lines(r.out);
    EXPECT_TRUE(contains(r.err, "E_VALUE_OUT_OF_RANGE")) << r.err;
  }
  // The move in range is traced; the one beyond it is not.
  const Result sum = usina("trace -", kSum);
  EXPECT_TRUE(contains(sum.out, "\"to\":[900000000,0,0]")) << sum.out;
  EXPECT_FALSE(contains(sum.out, "1800000000")) << sum.out;
  EXPECT_TRUE(contains(sum.err, "<stdin>:2:1: error:")) << sum.err;
}

TEST(NumbersCli, ConvertWritesNoNonNumber) {
  for (const char* post : {"rs274ngc", "fanuc", "grbl", "romi"}) {
    for (const std::string& program : {kHugeArc, kInfinity, kSum}) {
      const Result r = usina(std::string("convert --post ") + post + " -", program);
      EXPECT_EQ(r.status, 1) << post << "\n" << program;
      EXPECT_FALSE(has_non_number(r.out)) << r.out;
      EXPECT_FALSE(contains(r.out, "1800000000")) << r.out;
    }
  }
}

TEST(NumbersCli, StatsGivesNoNegativeOrNonFiniteTime) {
  for (const std::string& program : {kHugeArc, kInfinity, kSum}) {
    const Result r = usina("stats --format json -", program);
    EXPECT_EQ(r.status, 1) << r.err;
    const json j = json::parse(r.out, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << r.out;
    for (const char* k : {"total_s", "cutting_s", "rapid_s", "other_s", "exact_stop_s"}) {
      ASSERT_TRUE(j["time"][k].is_number()) << k << " " << r.out;
      const double t = j["time"][k].get<double>();
      EXPECT_TRUE(std::isfinite(t) && t >= 0.0) << k << " = " << t;
    }
  }
  const Result text = usina("stats -", kHugeArc);
  EXPECT_FALSE(std::regex_search(text.out, std::regex("-[0-9]")))
      << text.out;  // no negative figure
  EXPECT_FALSE(has_non_number(text.out)) << text.out;
}

TEST(NumbersCli, DrawEndsWithADiagnosticNotAnAbort) {
  const TempDir dir;
  const std::string program = dir.write("arc.ngc", kHugeArc);
  for (const char* ext : {"png", "svg", "dxf", "pdf"}) {
    const std::string out = dir.path(std::string("arc.") + ext);
    const Result r = usina("draw " + quote(program) + " -o " + quote(out));
    EXPECT_EQ(r.status, 1) << ext << ": " << r.err;  // 134 was cairo's abort
    EXPECT_TRUE(contains(r.err, "E_VALUE_OUT_OF_RANGE")) << r.err;
    EXPECT_FALSE(contains(r.err, "Assertion")) << r.err;
  }
}

TEST(NumbersCli, EveryDialectStopsAtTheMoveBeyondTheRange) {
  struct Case {
    const char* dialect;
    std::string program;
  };

  for (const Case& c : {Case{"rs274ngc", kSum}, Case{"grbl", kSum},
                        Case{"fanuc", "G91 G0 X900000000.\nG0 X900000000.\nM30\n"},
                        Case{"romi", "G91\nG0 X900000000\nG0 X900000000\nM30\n"}}) {
    const Result check = usina(std::string("check --dialect ") + c.dialect + " -", c.program);
    EXPECT_EQ(check.status, 1) << c.dialect << ": " << check.err;
    EXPECT_TRUE(contains(check.err, "E_VALUE_OUT_OF_RANGE")) << c.dialect << ": " << check.err;
    const Result trace = usina(std::string("trace --dialect ") + c.dialect + " -", c.program);
    expect_json_lines(trace.out);
    EXPECT_FALSE(contains(trace.out, "1800000000")) << c.dialect << ": " << trace.out;
  }
}

TEST(NumbersCli, AnExponentBeyondADoubleSaysSo) {
  const Result r = usina("check -", "G0 X1e400\nM2\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "[E_NUMBER_OUT_OF_RANGE]")) << r.err;
  EXPECT_TRUE(contains(r.err, "number 1e400 is out of range")) << r.err;
  EXPECT_FALSE(contains(r.err, "E word with no code")) << r.err;
}

TEST(NumbersCli, ASlashInASubroutineNameSaysWhy) {
  const Result r = usina("check -", "o<a/b> call\nM2\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "[E_BAD_SUBROUTINE_NAME]")) << r.err;
  EXPECT_TRUE(contains(r.err, "contains '/'")) << r.err;
  EXPECT_FALSE(contains(r.err, "unknown subroutine")) << r.err;
}

TEST(NumbersCli, WarningsCarryWarningCodes) {
  // A missing offset register was a warning with E_UNKNOWN_TOOL.
  const Result r = usina("check --dialect fanuc -", "G43 H5 Z10.\nM30\n");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "warning:")) << r.err;
  EXPECT_TRUE(contains(r.err, "[W_UNKNOWN_OFFSET_REGISTER]")) << r.err;
  EXPECT_FALSE(contains(r.err, "[E_")) << r.err;
}

}  // namespace
