// Round trips (issue 15): an APT program's records written as binary
// CLDATA and read back, and written as ISO 4343 text and read back by the
// APT CL reader, give the canon stream the records gave (within 1e-8, the
// text's 9 decimals; the programs of
// tests/programs/apt and the three of ../shared/conformance/apt). A CL
// file's exact arcs come back from CLDATA and ISO 4343 as arcs.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "apt/canon_out.hpp"
#include "apt/cl_text.hpp"
#include "apt/cldata.hpp"
#include "apt/iso4343.hpp"
#include "apt_run.hpp"
#include "canon/trace_writer.hpp"

namespace usina::apt::test {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The canon stream, without where each op came from (a record number in
// CLDATA, a line in the text: not the APT statement's).
class Stream final : public canon::Sink {
 public:
  void on(const canon::Op& op) override {
    std::string l = canon::to_jsonl(op);
    const std::size_t s = l.find(",\"src\"");
    l.erase(s, l.find(']', s) + 1 - s);
    ops.push_back(l);
  }

  std::vector<std::string> ops;
};

std::vector<std::string> stream(const std::vector<ClRecord>& records,
                                Circles circles = Circles::Arcs) {
  Stream s;
  to_canon(records, 1.0, s, circles);
  return s.ops;
}

std::vector<std::filesystem::path> programs() {
  std::vector<std::filesystem::path> out;
  for (const char* dir : {USINA_TEST_DIR "/programs/apt", USINA_SHARED_DIR "/conformance/apt"})
    if (std::filesystem::is_directory(dir))
      for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() == ".apt") out.push_back(e.path());
  return out;
}

TEST(AptRoundTrip, CanonCldataCanonGivesTheSameStream) {
  const auto files = programs();
  ASSERT_GE(files.size(), 3u);
  for (const auto& f : files) {
    const AptRun r = run(slurp(f));
    const std::vector<std::string> want = stream(r.result.records);
    ASSERT_FALSE(want.empty()) << f;
    core::DiagnosticList diags;
    const std::string bytes = write_cldata(r.result.records);
    const std::vector<ClRecord> back = read_cldata(bytes, 1, diags);
    EXPECT_FALSE(diags.has_errors()) << f;
    EXPECT_EQ(back.size(), r.result.records.size()) << f;
    EXPECT_EQ(record_print(back), record_print(r.result.records)) << f;
    EXPECT_EQ(stream(back), want) << f;
  }
}

// Whether two values of a trace agree, numbers within `tol` (ISO 4343
// writes 9 decimals).
bool near(const nlohmann::json& a, const nlohmann::json& b, double tol) {
  if (a.is_number() && b.is_number()) return std::fabs(a.get<double>() - b.get<double>()) <= tol;
  if (a.type() != b.type() || a.size() != b.size()) return false;
  if (a.is_array()) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!near(a[i], b[i], tol)) return false;
    return true;
  }
  if (a.is_object()) {
    for (auto it = a.begin(); it != a.end(); ++it)
      if (!b.contains(it.key()) || !near(it.value(), b[it.key()], tol)) return false;
    return true;
  }
  return a == b;
}

void expect_near(const std::vector<std::string>& got, const std::vector<std::string>& want,
                 const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_TRUE(near(nlohmann::json::parse(got[i]), nlohmann::json::parse(want[i]), 1e-8))
        << what << ": " << got[i] << " vs " << want[i];
}

TEST(AptRoundTrip, CanonIso4343CanonGivesTheSameStream) {
  for (const auto& f : programs()) {
    const AptRun r = run(slurp(f));
    core::DiagnosticList diags;
    const std::string text = write_iso4343(r.result.records, "MM");
    const std::vector<ClRecord> back = read_cl_text(text, 1, ClDialect::AptCl, diags);
    EXPECT_FALSE(diags.has_errors()) << f << "\n" << text;
    // ISO 4343 holds IBM's chords of a circle (its CIRCLE a comment), so the
    // stream read back is the chords' stream.
    expect_near(stream(back), stream(r.result.records, Circles::Chords), f.string() + "\n" + text);
  }
}

TEST(AptRoundTrip, AClFilesArcsStayArcs) {
  const std::string cl =
      "FEDRAT/1000,MMPM\nGOTO/0,0,0\nCIRCLE/5,0,0,0,0,1,5\nGOTO/10,0,0\n"
      "CIRCLE/5,0,0,0,0,-1\nGOTO/0,0,-1\nFINI\n";
  core::DiagnosticList diags;
  const std::vector<ClRecord> records = read_cl_text(cl, 1, ClDialect::AptCl, diags);
  ASSERT_FALSE(diags.has_errors());
  const std::vector<std::string> want = stream(records);
  ASSERT_EQ(want.size(), 3u);
  EXPECT_EQ(want[1],
            R"({"op":"arc","to":[10,0,0],"center":[5,0,0],"normal":[0,0,1],"turn":1,"f":1000})");
  EXPECT_EQ(want[2],
            R"({"op":"arc","to":[0,0,-1],"center":[5,0,0],"normal":[0,0,-1],"turn":1,"f":1000})");
  EXPECT_EQ(stream(read_cldata(write_cldata(records), 1, diags)), want);
  const std::string text = write_iso4343(records);
  EXPECT_NE(text.find("CIRCLE/5,0,0,0,0,1,5\nGOTO/10,0,0\n"), std::string::npos) << text;
  EXPECT_EQ(stream(read_cl_text(text, 1, ClDialect::AptCl, diags)), want);
  EXPECT_FALSE(diags.has_errors());
}

TEST(AptRoundTrip, Iso4343WritesEachRecordAsItsStatement) {
  const AptRun r =
      run("PARTNO SAMPLE\nCUTTER/.25\nSPINDL/2000,CLW\nFEDRAT/20\nFROM/0,0,0\nRAPID,GOTO/1,2,3\n"
          "GOTO/4,5,6\nCOOLNT/OFF\nEND\nFINI\n");
  ASSERT_FALSE(r.diags.has_errors());
  EXPECT_EQ(write_iso4343(r.result.records, "INCHES"),
            "UNITS/INCHES\nPARTNO/SAMPLE\nCUTTER/0.25\nSPINDL/2000,CLW\nFEDRAT/20\n"
            "FROM/0,0,0\nRAPID\nGOTO/1,2,3\nGOTO/4,5,6\nCOOLNT/OFF\nEND\nFINI\n");
}

}  // namespace
}  // namespace usina::apt::test
