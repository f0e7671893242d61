// `usina stats` as a user runs it: text and JSON on standard output, the
// checks on standard error, and every error path with its exit status
// (0; 1 program error, figures still printed; 2 bad input).
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/usina_process.hpp"

namespace {

using nlohmann::json;
using usina::test::contains;
using usina::test::slurp;
using usina::test::TempDir;
using usina::test::usina;
using Result = usina::test::Run;

const std::string kExamples = std::string(USINA_TEST_DIR) + "/../examples";
const std::string kVmc = kExamples + "/machines/small_vmc.toml";

json parse(const Result& r) {
  json j = json::parse(r.out, nullptr, /*allow_exceptions=*/false);
  EXPECT_FALSE(j.is_discarded()) << r.out;
  return j;
}

// G0 X100 then G1 Y100 F600 (10 mm/s) on the default profile (rapid
// 10000 mm/min, accel 500 mm/s²) with the spindle at 12000 of 24000 rpm
// (2 s × 0.5 = 1 s).
const std::string kSquare = "G21 G90\nS12000 M3\nG0 X100\nG1 Y100 F600\nM5\nM2\n";

TEST(StatsCli, JsonHasTheDocumentedFields) {
  const Result r = usina("stats --format json -", kSquare);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  const json j = parse(r);
  for (const char* k : {"total_s", "cutting_s", "rapid_s", "other_s", "exact_stop_s"})
    EXPECT_TRUE(j["time"][k].is_number()) << k;
  EXPECT_DOUBLE_EQ(j["distance"]["cutting_mm"].get<double>(), 100.0);
  EXPECT_DOUBLE_EQ(j["distance"]["rapid_mm"].get<double>(), 100.0);
  ASSERT_TRUE(j["tools"].is_array());
  ASSERT_EQ(j["tools"].size(), 1u);
  EXPECT_EQ(j["tools"][0]["tool"], 0);
  EXPECT_EQ(j["bounds"]["max"], json({100.0, 100.0, 0.0}));
  EXPECT_TRUE(j["diagnostics"].is_array());
  EXPECT_TRUE(j["complete"].get<bool>());
  EXPECT_EQ(j["counts"]["rapids"], 1);
  EXPECT_EQ(j["counts"]["feeds"], 1);
  EXPECT_EQ(j["feed_mm_per_min"]["max"], 600.0);
  EXPECT_EQ(j["rpm"]["min"], 12000.0);
  EXPECT_TRUE(j["machine"]["profile"].is_null());
  // The feed: 100 mm at 10 mm/s, at least 10 s; spindle start-up 1 s.
  EXPECT_GE(j["time"]["cutting_s"].get<double>(), 10.0);
  EXPECT_NEAR(j["time"]["other_s"].get<double>(), 1.0, 1e-9);
  EXPECT_GE(j["time"]["exact_stop_s"].get<double>(), j["time"]["total_s"].get<double>());
  const double total = j["time"]["total_s"].get<double>();
  EXPECT_NEAR(total,
              j["time"]["cutting_s"].get<double>() + j["time"]["rapid_s"].get<double>() +
                  j["time"]["other_s"].get<double>(),
              1e-9);
}

TEST(StatsCli, TextIsForAMachinist) {
  const Result r = usina("stats -", kSquare);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* part :
       {"cycle time", "cutting", "rapid", "exact stop (G61)",
        "distance         cutting 100.000 mm, rapid 100.000 mm", "feed             600 mm/min",
        "spindle          12000 rpm", "(no --machine given)"}) {
    EXPECT_TRUE(contains(r.out, part)) << part << "\n" << r.out;
  }
}

TEST(StatsCli, MachineProfileAndItsChecks) {
  // small_vmc: Z from -350 to 0, so Z5 is over travel with program zero at machine zero.
  const Result r = usina("stats --format json --work-zero 0,0,0 --machine '" + kVmc + "' -",
                         "G21\nS1000 M3\nG0 Z5\nG1 X10 F100\nM2\n");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse(r);
  EXPECT_EQ(j["machine"]["name"], "small VMC");
  EXPECT_GT(j["cost"]["total"].get<double>(), 0.0);
  ASSERT_EQ(j["diagnostics"].size(), 1u);
  EXPECT_EQ(j["diagnostics"][0]["code"], "W_OVERTRAVEL");
  EXPECT_EQ(j["diagnostics"][0]["line"], 3);
  EXPECT_EQ(j["diagnostics"][0]["severity"], "warning");
  EXPECT_EQ(j["checks"]["W_OVERTRAVEL"], 2);  // the feed starts at Z5 too
  EXPECT_TRUE(contains(r.err, "<stdin>:3:1: warning: Z goes to 5.000 mm")) << r.err;
}

TEST(StatsCli, StockTopReportsRapidsIntoTheStock) {
  const Result r = usina("stats --stock-top 0 -", "G21\nS1000 M3\nG0 X10 Z-1\nM2\n");
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(contains(r.err, "[W_RAPID_INTO_STOCK]")) << r.err;
  EXPECT_TRUE(contains(r.out, "W_RAPID_INTO_STOCK")) << r.out;
  EXPECT_FALSE(contains(usina("stats -", "G21\nG0 X10 Z-1\nM2\n").err, "W_RAPID"));
}

// Without a work zero, a program that fits the machine's travel is not
// flagged wherever its zero is; one longer than the travel is.
TEST(StatsCli, WithoutWorkZeroTheExtentIsChecked) {
  const std::string vmc = " --machine '" + kVmc + "' -";
  EXPECT_FALSE(contains(usina("stats" + vmc, "G21\nS1000 M3\nG0 Z5\nG1 X10 F100\nM2\n").err,
                        "W_OVERTRAVEL"));
  const Result r = usina("stats" + vmc, "G21\nS1000 M3\nG0 X-400\nG1 X400 F100\nM2\n");
  EXPECT_TRUE(contains(r.err, "<stdin>:4:1: warning: X spans 800.000 mm")) << r.err;
  EXPECT_NE(usina("stats --work-zero 1,2" + vmc, "M2\n").status, 0);
}

// The simulation's warnings and the program's come in the order of their
// blocks, on standard error and in the JSON: the ops reach the simulation
// in batches (canon/batch_sink.hpp), handed on before each of the
// program's diagnostics.
TEST(StatsCli, TheSimulationsWarningsKeepTheirPlaceAmongTheProgramsDiagnostics) {
  // Line 2: a feed with the spindle stopped (the simulation's warning);
  // line 4: a coordinate without a decimal point (the fanuc reader's).
  const std::string program = "G21 G90\nG1 X1. F100.\nG1 X2.\nX3\nM30\n";
  const Result text = usina("stats --dialect fanuc -", program);
  ASSERT_EQ(text.status, 0) << text.err;
  const std::size_t sim = text.err.find("W_FEED_SPINDLE_STOPPED");
  const std::size_t reader = text.err.find("W_INTEGER_COORDINATE");
  ASSERT_NE(sim, std::string::npos) << text.err;
  ASSERT_NE(reader, std::string::npos) << text.err;
  EXPECT_LT(sim, reader) << text.err;
  const json j = parse(usina("stats --format json --dialect fanuc -", program));
  ASSERT_EQ(j["diagnostics"].size(), 2u) << j.dump();
  EXPECT_EQ(j["diagnostics"][0]["code"], "W_FEED_SPINDLE_STOPPED");
  EXPECT_EQ(j["diagnostics"][1]["code"], "W_INTEGER_COORDINATE");
}

TEST(StatsCli, ProgramErrorExitsOneWithTheFiguresBeforeIt) {
  const Result r = usina("stats --format json -", "G21\nS1000 M3\nG1 X10 F100\nG2 X20 R1\nM2\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "error:")) << r.err;
  const json j = parse(r);
  EXPECT_FALSE(j["complete"].get<bool>());
  EXPECT_DOUBLE_EQ(j["distance"]["cutting_mm"].get<double>(), 10.0);
  // The program's error is in the JSON too, with its line.
  bool listed = false;
  for (const json& d : j["diagnostics"]) {
    if (d["severity"] == "error" && d["line"] == 4) listed = true;
  }
  EXPECT_TRUE(listed) << j["diagnostics"].dump();
}

TEST(StatsCli, UnreadableProgramIsBadInput) {
  const Result r = usina("stats /nonexistent/part.ngc");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_TRUE(contains(r.err, "usina: error: cannot read /nonexistent/part.ngc")) << r.err;
}

TEST(StatsCli, UnreadableProfileIsBadInput) {
  const Result r = usina("stats --machine /nonexistent/m.toml -", kSquare);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_TRUE(contains(r.err, "usina: error: cannot read /nonexistent/m.toml")) << r.err;
}

TEST(StatsCli, BadProfileIsBadInputWithItsDiagnostic) {
  const TempDir dir;
  std::string text = slurp(kVmc);
  text.replace(text.find("accel = 1500.0"), 14, "accel = \"fast\"");
  const std::string m = dir.write("m.toml", text);
  const Result r = usina("stats --machine '" + m + "' -", kSquare);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty());
  EXPECT_TRUE(contains(r.err, "[axes.z] accel must be a number [E_BAD_MACHINE_PROFILE]")) << r.err;
  EXPECT_TRUE(contains(r.err, "  accel = \"fast\"")) << r.err;  // the line itself, shown
  EXPECT_TRUE(contains(r.err, "cannot be used")) << r.err;
}

TEST(StatsCli, ProfileThatIsNotTomlIsBadInput) {
  const TempDir dir;
  const std::string m = dir.write("m.toml", "[machine\n");
  const Result r = usina("stats --machine '" + m + "' -", kSquare);
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "not valid TOML")) << r.err;
}

TEST(StatsCli, BadOptionsAreUsageErrors) {
  for (const char* args : {"stats --format xml -", "stats --stock-top high -", "stats"}) {
    const Result r = usina(args, kSquare);
    EXPECT_NE(r.status, 0) << args;
    EXPECT_NE(r.status, 1) << args;
    EXPECT_TRUE(r.out.empty()) << args;
  }
}

TEST(StatsCli, RunOptionsApply) {
  // --block-delete skips the '/' block: 1 mm of rapid instead of 10 + 9.
  const std::string program = "G21\n/G0 X10\nG0 X1\nM2\n";
  const Result on = usina("stats --format json --block-delete -", program);
  ASSERT_EQ(on.status, 0) << on.err;
  EXPECT_NEAR(parse(on)["distance"]["rapid_mm"].get<double>(), 1.0, 1e-9);
  const Result off = usina("stats --format json -", program);
  EXPECT_NEAR(parse(off)["distance"]["rapid_mm"].get<double>(), 19.0, 1e-9);
}

TEST(StatsCli, ShippedExampleRuns) {
  const Result r = usina("stats --format json --tool-table '" + kExamples + "/tools.tbl' '" +
                         kExamples + "/bracket.ngc'");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = parse(r);
  EXPECT_GT(j["time"]["total_s"].get<double>(), 0.0);
  EXPECT_GT(j["counts"]["holes"].get<int>(), 0);
}

}  // namespace
