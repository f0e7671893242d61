// `usina calc` as a user runs it: seed 004's examples 7.1-7.3 on standard
// output, in text and JSON, and every bad input as "usina: error:" with exit
// status 2.
#include <array>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/usina_process.hpp"

namespace {

using nlohmann::json;
using usina::test::contains;
using usina::test::usina;
using Result = usina::test::Run;

const std::string kExample71 = "--pitch 6 --gear-ratio 5 --steps 48 --distance 250 --feed 500";
const std::string kExample72 =
    "--pitch 6 --gear-ratio 5 --encoder-slots 48 --distance 250 --feed 500";
const std::string kExample73 =
    "--pitch 6 --gear-ratio 5 --steps 48 --travel 1000 --bits 16 --sigma 0.005";

// Runs a subcommand with --format json and parses what it printed.
json usina_json(const std::string& args) {
  const Result r = usina(args + " --format json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  return json::parse(r.out, nullptr, /*allow_exceptions=*/false);
}

// --- the seed's examples --------------------------------------------------------

TEST(CalcCli, OpenLoopPrintsExample71WithFormulasAndUnits) {
  const Result r = usina("calc open-loop " + kExample71);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* part : {"10000 pulses", "(eq. 7.8)", "333.333 Hz", "(eq. 7.11)",
                           "416.667 rev/min", "83.3333 rev/min", "7.5 deg per step",
                           "n_p = n_s x r_g / p", "f_p = f_r n_s r_g / (60 p)"}) {
    EXPECT_TRUE(contains(r.out, part)) << part << " missing from\n" << r.out;
  }
  EXPECT_FALSE(contains(r.out, "whole pulses")) << r.out;  // 10000 is whole
}

TEST(CalcCli, OpenLoopJsonHasTheDocumentedFields) {
  const json j = usina_json("calc open-loop " + kExample71);
  ASSERT_TRUE(j.is_object());
  EXPECT_EQ(j["calculation"], "open_loop");
  EXPECT_EQ(j["inputs"]["steps_per_rev"], 48);
  EXPECT_DOUBLE_EQ(j["inputs"]["pitch_mm"].get<double>(), 6.0);
  const json& res = j["results"];
  EXPECT_DOUBLE_EQ(res["pulses"].get<double>(), 10000.0);
  EXPECT_EQ(res["whole_pulses"], 10000);
  EXPECT_NEAR(res["pulse_frequency_hz"].get<double>(), 333.333, 0.0005);
  EXPECT_NEAR(res["motor_rpm"].get<double>(), 416.667, 0.0005);
  EXPECT_NEAR(res["screw_rpm"].get<double>(), 83.333, 0.0005);
  for (const char* key :
       {"step_angle_deg", "screw_angle_deg", "motor_angle_deg", "distance_reached_mm"}) {
    EXPECT_TRUE(res.contains(key)) << key;
  }
}

TEST(CalcCli, OpenLoopShowsWhereAFractionOfAStepLeavesTheTable) {
  const Result r =
      usina("calc open-loop --pitch 6 --gear-ratio 5 --steps 48 --distance 250.01 --feed 500");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "10000.4 pulses")) << r.out;
  EXPECT_TRUE(contains(r.out, "whole pulses")) << r.out;
  EXPECT_TRUE(contains(r.out, "250 mm")) << r.out;
}

TEST(CalcCli, OpenLoopTakesANegativeDistance) {
  const Result r =
      usina("calc open-loop --pitch 6 --gear-ratio 5 --steps 48 --distance -250 --feed 500");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "-10000 pulses")) << r.out;
}

TEST(CalcCli, ClosedLoopPrintsExample72) {
  const Result r = usina("calc closed-loop " + kExample72);
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* part :
       {"2000 pulses", "(eq. 7.13, 7.14)", "66.6667 Hz", "(eq. 7.15)", "416.667 rev/min"}) {
    EXPECT_TRUE(contains(r.out, part)) << part << " missing from\n" << r.out;
  }
  const json j = usina_json("calc closed-loop " + kExample72);
  EXPECT_EQ(j["calculation"], "closed_loop");
  EXPECT_EQ(j["inputs"]["encoder_slots"], 48);
  EXPECT_DOUBLE_EQ(j["results"]["pulses"].get<double>(), 2000.0);
  EXPECT_NEAR(j["results"]["pulse_frequency_hz"].get<double>(), 66.667, 0.0005);
  EXPECT_NEAR(j["results"]["motor_rpm"].get<double>(), 416.667, 0.0005);
}

TEST(CalcCli, PrecisionPrintsExample73) {
  const Result r = usina("calc precision " + kExample73);
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* part :
       {"0.025 mm", "0.015259 mm", "0.0275 mm", "±0.015 mm", "(eq. 7.16)", "(eq. 7.17)",
        "(eq. 7.18)", "(eq. 7.19)", "(eq. 7.20)", "limited by: the mechanics"}) {
    EXPECT_TRUE(contains(r.out, part)) << part << " missing from\n" << r.out;
  }
  const json j = usina_json("calc precision " + kExample73);
  EXPECT_EQ(j["calculation"], "precision");
  const json& res = j["results"];
  EXPECT_DOUBLE_EQ(res["cr1_mm"].get<double>(), 0.025);
  EXPECT_NEAR(res["cr2_mm"].get<double>(), 0.01526, 0.000005);
  EXPECT_DOUBLE_EQ(res["control_resolution_mm"].get<double>(), 0.025);
  EXPECT_NEAR(res["accuracy_mm"].get<double>(), 0.0275, 1e-12);
  EXPECT_NEAR(res["repeatability_mm"].get<double>(), 0.015, 1e-12);
  EXPECT_EQ(res["limited_by"], "mechanics");
}

TEST(CalcCli, PrecisionSaysWhenTheRegisterLimits) {
  const Result r = usina(
      "calc precision --pitch 6 --gear-ratio 5 --steps 48 --travel 1000 --bits 8 "
      "--sigma 0.005");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "limited by: the register bits")) << r.out;
}

TEST(CalcCli, CuttingPrintsSpindleSpeedAndFeed) {
  const Result r =
      usina("calc cutting --cutting-speed 100 --tool-diameter 20 --flutes 4 --chip-load 0.05");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "1591.55 rev/min")) << r.out;
  EXPECT_TRUE(contains(r.out, "(eq. 7.1)")) << r.out;
  EXPECT_TRUE(contains(r.out, "318.31 mm/min")) << r.out;
  EXPECT_TRUE(contains(r.out, "(eq. 7.2)")) << r.out;
}

TEST(CalcCli, CuttingWithoutTeethHasNoFeed) {
  const Result r = usina("calc cutting --cutting-speed 100 --tool-diameter 20");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(contains(r.out, "(eq. 7.2)")) << r.out;
  const json j = usina_json("calc cutting --cutting-speed 100 --tool-diameter 20");
  EXPECT_EQ(j["calculation"], "cutting");
  EXPECT_NEAR(j["results"]["spindle_rpm"].get<double>(), 1591.55, 0.005);
  EXPECT_TRUE(j["results"]["feed_mm_per_min"].is_null());
  EXPECT_TRUE(j["inputs"]["teeth"].is_null());
}

TEST(CalcCli, BcdPrintsTheSeedsTableFor1250) {
  const Result r = usina("calc bcd 1250");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "code: 0001 0010 0101 0000")) << r.out;
  EXPECT_TRUE(contains(r.out, "table 7.4")) << r.out;
  const json j = usina_json("calc bcd 1250");
  EXPECT_EQ(j["calculation"], "bcd");
  EXPECT_EQ(j["results"]["value"], 1250);
  EXPECT_EQ(j["results"]["code"], "0001 0010 0101 0000");
  ASSERT_EQ(j["results"]["digits"].size(), 4u);
  EXPECT_EQ(j["results"]["digits"][2]["bits"], "0101");
  EXPECT_EQ(j["results"]["digits"][2]["place_value"], 50);
}

TEST(CalcCli, HelpListsTheCalculators) {
  const Result r = usina("calc --help");
  EXPECT_EQ(r.status, 0);
  for (const char* sub : {"open-loop", "closed-loop", "precision", "cutting", "bcd"})
    EXPECT_TRUE(contains(r.out, sub)) << sub << " missing from\n" << r.out;
}

// --- bad input ----------------------------------------------------------------

TEST(CalcCli, BadInputIsAnErrorWithStatusTwo) {
  const std::string ol = "calc open-loop --gear-ratio 5 --steps 48 --distance 250 --feed 500 ";
  const std::vector<std::string> cases = {
      ol + "--pitch 0",
      ol + "--pitch -6",
      ol + "--pitch abc",
      ol + "--pitch 6,5",
      ol + "--pitch nan",
      ol + "--pitch inf",
      ol + "--pitch 1e400",
      ol + "--pitch ''",
      ol,  // no pitch
      "calc open-loop --pitch 6 --gear-ratio 5 --steps 48.5 --distance 250 --feed 500",
      "calc open-loop --pitch 6 --gear-ratio 5 --steps 0 --distance 250 --feed 500",
      "calc open-loop --pitch 6 --gear-ratio 0 --steps 48 --distance 250 --feed 500",
      "calc open-loop --pitch 6 --gear-ratio 5 --steps 48 --distance 250 --feed 0",
      "calc open-loop --pitch 6 --gear-ratio 5 --steps 48 --distance 250 --feed -500",
      "calc open-loop --pitch 1e-300 --gear-ratio 5 --steps 48 --distance 1e300 --feed 500",
      "calc closed-loop --pitch -6 --gear-ratio 5 --encoder-slots 48 --distance 250 --feed 500",
      "calc closed-loop --pitch 6 --gear-ratio 5 --encoder-slots -48 --distance 250 --feed 5",
      "calc precision --pitch 6 --gear-ratio 5 --steps 48 --travel 1000 --bits 0 --sigma 0.005",
      "calc precision --pitch 6 --gear-ratio 5 --steps 48 --travel 1000 --bits 65 --sigma 0.005",
      "calc precision --pitch 6 --gear-ratio 5 --steps 48 --travel 1000 --bits 1e3 --sigma 0",
      "calc precision --pitch 6 --gear-ratio 5 --steps 48 --travel 1000 --bits 16 --sigma -1",
      "calc precision --pitch 6 --gear-ratio 5 --steps 48 --travel 0 --bits 16 --sigma 0.005",
      "calc cutting --cutting-speed 0 --tool-diameter 20",
      "calc cutting --cutting-speed 100 --tool-diameter -20",
      "calc cutting --cutting-speed 100 --tool-diameter 20 --flutes 4",
      "calc cutting --cutting-speed 100 --tool-diameter 20 --chip-load 0.05",
      "calc cutting --cutting-speed 100 --tool-diameter 20 --flutes 2.5 --chip-load 0.05",
      "calc bcd -5",
      "calc bcd 12.5",
      "calc bcd abc",
      "calc bcd 99999999999999999999",
      "calc bcd",
  };
  for (const std::string& c : cases) {
    const Result r = usina(c);
    EXPECT_EQ(r.status, 2) << c << "\n" << r.err;
    EXPECT_TRUE(r.err.starts_with("usina: error: calc ")) << c << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << c << "\n" << r.out;
  }
}

TEST(CalcCli, ErrorsSayWhatIsWrong) {
  Result r = usina(
      "calc open-loop --pitch 6 --gear-ratio 5 --steps 48.5 --distance 250 "
      "--feed 500");
  EXPECT_EQ(r.err, "usina: error: calc open-loop: --steps: '48.5' is not a whole number\n");
  r = usina("calc bcd -5");
  EXPECT_TRUE(contains(r.err, "negative")) << r.err;
  r = usina("calc bcd 12.5");
  EXPECT_TRUE(contains(r.err, "not a whole number")) << r.err;
  r = usina("calc open-loop --gear-ratio 5 --steps 48 --distance 250 --feed 500");
  EXPECT_TRUE(contains(r.err, "--pitch is required")) << r.err;
}

TEST(CalcCli, CommandLineMistakesExitNonZero) {
  // CLI11's own checks: no calculator, an unknown format, a flag without its
  // value, an extra argument, an unknown calculator.
  const std::array<std::string, 5> cases = {
      "calc", "calc open-loop " + kExample71 + " --format xml", "calc open-loop --pitch",
      "calc bcd 1 2", "calc nothing"};
  for (const std::string& c : cases) {
    const Result r = usina(c);
    EXPECT_NE(r.status, 0) << c;
    EXPECT_FALSE(r.err.empty()) << c;
    EXPECT_TRUE(r.out.empty()) << c << "\n" << r.out;
  }
}

TEST(CalcCli, NoNanOrInfinityEverReachesTheOutput) {
  const std::array<const char*, 4> cases = {
      "calc open-loop --pitch 1e-308 --gear-ratio 1e308 --steps 48 --distance 1 --feed 1e308",
      "calc precision --pitch 6 --gear-ratio 5 --steps 48 --travel 1e308 --bits 64 --sigma 1e308",
      "calc cutting --cutting-speed 1e308 --tool-diameter 1e-308 --flutes 4 --chip-load 1",
      "calc open-loop --pitch 6 --gear-ratio 5 --steps 48 --distance 0 --feed 1",
  };
  for (const std::string c : cases) {
    for (const char* format : {" --format text", " --format json"}) {
      const Result r = usina(c + format);
      EXPECT_TRUE(r.status == 0 || r.status == 2) << c << format;
      for (const char* bad : {"nan", "inf", "NaN", "null"})
        EXPECT_FALSE(contains(r.out, bad)) << c << format << "\n" << r.out;
    }
  }
}

}  // namespace
