// Issue 15: `usina trace PROG --format cldata|iso4343|cldump [-o FILE]`, the
// CL data of a G-code program (docs/apt.md, "CL data of a G-code program").
// Round trip: the program's trace and the trace of its CL data read back
// have the same moves (within 1e-6), arc centres and directions, feeds,
// tools and plain drillings' holes; and `convert` posts the CL data.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/usina_process.hpp"

namespace usina::test {
namespace {

using nlohmann::json;

std::string program(const std::string& name) {
  return std::string(USINA_TEST_DIR) + "/programs/" + name;
}

std::vector<json> ops(const std::string& trace, const std::vector<std::string>& kinds) {
  std::vector<json> out;
  std::istringstream in(trace);
  std::string line;
  while (std::getline(in, line)) {
    json j = json::parse(line);
    if (std::find(kinds.begin(), kinds.end(), j["op"]) != kinds.end()) out.push_back(std::move(j));
  }
  return out;
}

void expect_near(const json& a, const json& b, const char* key, std::size_t i) {
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_NEAR(a[key][k].get<double>(), b[key][k].get<double>(), 1e-6)
        << i << " " << key << ": " << a << " vs " << b;
}

// The axis an arc turns counter-clockwise about (CL's form of a direction).
std::vector<double> sense(const json& arc) {
  const double s = arc["turn"].get<int>() > 0 ? 1.0 : -1.0;
  return {s * arc["normal"][0].get<double>(), s * arc["normal"][1].get<double>(),
          s * arc["normal"][2].get<double>()};
}

void expect_same_moves(const std::string& a, const std::string& b) {
  const auto ma = ops(a, {"traverse", "feed", "arc", "tool", "spindle", "coolant", "dwell"});
  const auto mb = ops(b, {"traverse", "feed", "arc", "tool", "spindle", "coolant", "dwell"});
  ASSERT_EQ(ma.size(), mb.size());
  for (std::size_t i = 0; i < ma.size(); ++i) {
    ASSERT_EQ(ma[i]["op"], mb[i]["op"]) << i << ": " << ma[i] << " vs " << mb[i];
    const std::string op = ma[i]["op"];
    if (op == "traverse" || op == "feed" || op == "arc") expect_near(ma[i], mb[i], "to", i);
    if (op == "feed" || op == "arc") {
      EXPECT_EQ(ma[i]["f"], mb[i]["f"]) << i;
    }
    if (op == "arc") {
      expect_near(ma[i], mb[i], "center", i);
      EXPECT_EQ(sense(ma[i]), sense(mb[i])) << i;
      EXPECT_EQ(std::abs(ma[i]["turn"].get<int>()), std::abs(mb[i]["turn"].get<int>())) << i;
    }
    if (op == "tool") {
      EXPECT_EQ(ma[i]["tool"], mb[i]["tool"]) << i;
    }
    if (op == "spindle" || op == "coolant" || op == "dwell") {
      json x = ma[i], y = mb[i];
      x.erase("src");
      y.erase("src");
      EXPECT_EQ(x, y) << i;
    }
  }
}

// The holes, each without where it came from.
std::vector<json> holes(const std::string& trace) {
  std::vector<json> out = ops(trace, {"hole"});
  for (json& h : out)
    h.erase("src");
  return out;
}

struct RoundTrip {
  test::Run direct, cl, back;
};

RoundTrip round_trip(const TempDir& dir, const std::string& args, const std::string& format) {
  const std::string file = dir.path("p." + std::string(format == "cldata" ? "cldata" : "ncl"));
  RoundTrip r;
  r.direct = usina("trace " + args);
  r.cl = usina("trace " + args + " --format " + format + " -o " + quote(file));
  r.back = usina("trace " + quote(file));
  return r;
}

TEST(TraceCl, SeedZeroExampleComesBackFromCldataAndIso4343) {
  const TempDir dir;
  const std::string args = quote(program("romi/seed-000-example.nc")) + " --dialect romi";
  for (const std::string format : {"cldata", "iso4343"}) {
    const RoundTrip r = round_trip(dir, args, format);
    ASSERT_EQ(r.direct.status, 0) << r.direct.err;
    ASSERT_EQ(r.cl.status, 0) << r.cl.err;
    ASSERT_EQ(r.back.status, 0) << r.back.err;
    EXPECT_TRUE(r.cl.out.empty());
    expect_same_moves(r.direct.out, r.back.out);
    EXPECT_EQ(holes(r.direct.out).size(), 12u);
    EXPECT_EQ(holes(r.direct.out), holes(r.back.out)) << format;
  }
}

TEST(TraceCl, ArcsAndDrillingComeBack) {
  const TempDir dir;
  const std::string args = quote(program("apt/gcode_arcs_drill.ngc"));
  const RoundTrip r = round_trip(dir, args, "cldata");
  ASSERT_EQ(r.back.status, 0) << r.back.err;
  expect_same_moves(r.direct.out, r.back.out);
  EXPECT_EQ(ops(r.direct.out, {"arc"}).size(), 5u);
  // The three G81 holes come back; the G83 peck is its moves.
  std::vector<json> want = holes(r.direct.out);
  ASSERT_EQ(want.size(), 4u);
  want.pop_back();
  EXPECT_EQ(want, holes(r.back.out));
}

TEST(TraceCl, Iso4343WritesIbmsCircleAndTheCycle) {
  const test::Run r =
      usina("trace " + quote(program("apt/gcode_arcs_drill.ngc")) + " --format iso4343");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "UNITS/MM\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "CIRCLE/40,10,-1,0,0,-1,10\nGOTO/40,20,-1\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "CYCLE/DRILL,10,MMPM,120,0,3\nGOTO/10,40,2\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "CYCLE/OFF\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "LOADTL/1\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "SPINDL/2000,CLW\n")) << r.out;
  EXPECT_TRUE(contains(r.out, "END\nFINI\n")) << r.out;
}

TEST(TraceCl, CldumpIsTheRecordPrint) {
  const test::Run r = usina("trace - --format cldump", "G0 X1 Y2 Z3\nG1 X4 F100\nM2\n");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out,
            "1 1000 1 2 0 ''\n"
            "2 2000 5 0 \n"
            "3 5000 5 5 0 0 1.0000000 2.0000000 3.0000000\n"
            "4 1000 2 2 0 ''\n"
            "5 2000 1009 1 100\n"
            "6 1000 2 2 0 ''\n"
            "7 5000 5 5 0 0 4.0000000 2.0000000 3.0000000\n"
            "8 1000 3 2 0 ''\n"
            "9 2000 1 0 \n"
            "10 14000 0 0 \n");
}

// The CL data posted: the same moves as the program posted directly.
TEST(TraceCl, ConvertPostsTheCldata) {
  const TempDir dir;
  const std::string cl = dir.path("p.cldata");
  const std::string p = quote(program("apt/gcode_arcs_drill.ngc"));
  ASSERT_EQ(usina("trace " + p + " --format cldata -o " + quote(cl)).status, 0);
  const test::Run posted = usina("convert " + quote(cl) + " --from cldata --post rs274ngc");
  ASSERT_EQ(posted.status, 0) << posted.err;
  const std::string ngc = dir.write("back.ngc", posted.out);
  const test::Run direct = usina("trace " + p);
  const test::Run again = usina("trace " + quote(ngc));
  ASSERT_EQ(again.status, 0) << again.err;
  // The post writes 4 decimals; the G81 holes come back as G81.
  expect_same_motion(direct.out, again.out, 1e-4);
  EXPECT_TRUE(contains(posted.out, "G81")) << posted.out;
}

TEST(TraceCl, ErrorPaths) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", "G0 X1\nG1 X2 F100\nM2\n");
  // An unknown format: a usage error.
  test::Run r = usina("trace " + quote(p) + " --format clsf");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  // -o to a directory, onto its own input: nothing run, nothing written.
  r = usina("trace " + quote(p) + " --format cldata -o " + quote(dir.path("")));
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(r.err.empty());
  r = usina("trace " + quote(p) + " --format iso4343 -o " + quote(p));
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "also an input")) << r.err;
  EXPECT_EQ(slurp(p), "G0 X1\nG1 X2 F100\nM2\n");
  // A program with an error: no cldata or iso4343 (a machine would take it), status 1.
  const std::string bad = dir.write("bad.ngc", "G0 X1\nG1 X2\nM2\n");  // no feed rate
  const std::string out = dir.path("bad.cldata");
  r = usina("trace " + quote(bad) + " --format cldata -o " + quote(out));
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_FALSE(std::ifstream(out).good());
  r = usina("trace " + quote(bad) + " --format iso4343");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(r.out.empty());
  // ... but the record print shows what was read.
  r = usina("trace " + quote(bad) + " --format cldump");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.out, "14000 0 0")) << r.out;
  // A file that is not there: status 2, and -o left alone.
  const std::string kept = dir.write("kept.ncl", "old");
  r = usina("trace " + quote(dir.path("none.ngc")) + " --format iso4343 -o " + quote(kept));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(slurp(kept), "old");
}

// CL data held for standard output that cannot be written whole (a file
// size limit stands for a full temporary folder): an error, and nothing on
// standard output rather than a short CL a post would take.
TEST(TraceCl, HeldDataThatCannotBeWrittenIsAnErrorNotAShortFile) {
  const TempDir dir;
  std::string text = "G21 G90 G0 X0 Y0 Z5\nG1 Z0 F300\n";
  for (int i = 0; i < 3000; ++i)
    text += "G1 X" + std::to_string(i % 100) + " Y" + std::to_string(i / 100) + "\n";
  const std::string p = dir.write("long.ngc", text + "M2\n");
  const std::string err = dir.path("err");
  const std::string trace = quote(USINA_BINARY) + " trace " + quote(p) + " --format cldata";
  // SIGXFSZ ignored: the write past the limit fails (EFBIG) instead of
  // killing the process.
  const test::Run r = shell("trap '' XFSZ; ulimit -f 64; " + trace + " 2>" + quote(err), err);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out.size() << " bytes";
  EXPECT_TRUE(contains(r.err, "could not be written or read back")) << r.err;
  // Without the limit the same command writes it whole.
  const test::Run whole = shell(trace + " 2>" + quote(err), err);
  EXPECT_EQ(whole.status, 0) << whole.err;
  EXPECT_GT(whole.out.size(), 64u * 1024u);
}

TEST(TraceCl, CldataIsNeverWrittenToATerminal) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", "G0 X1\nM2\n");
  // script(1) gives usina a terminal for its standard output.
  const std::string cmd = "script -qec " +
                          quote(quote(USINA_BINARY) + " trace " + quote(p) + " --format cldata") +
                          " /dev/null";
  const test::Run r = shell(cmd + " 2>/dev/null", dir.write("err", ""));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--format cldata is binary; give -o FILE")) << r.out;
  const test::Run piped = usina("trace " + quote(p) + " --format cldata");
  EXPECT_EQ(piped.status, 0);
  EXPECT_EQ(piped.out.substr(0, 4), std::string("\x01\x00\x00\x00", 4));
}

// -o with the trace formats too, replacing the file only when whole.
TEST(TraceCl, OutputFileForJsonl) {
  const TempDir dir;
  const std::string p = dir.write("p.ngc", "G0 X1\nG1 X2 F100\nM2\n");
  const std::string out = dir.path("t.jsonl");
  const test::Run r = usina("trace " + quote(p) + " -o " + quote(out));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out.empty());
  EXPECT_EQ(slurp(out), usina("trace " + quote(p)).out);
}

}  // namespace
}  // namespace usina::test
