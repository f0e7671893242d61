// The calculators read from and answered in JSON (the server's
// POST /api/calc/{name}, the page's calculators): seed 004's examples give
// their printed figures; every bad input is the message of that input.
#include "sim/calc_json.hpp"

#include <string>

#include <gtest/gtest.h>

namespace usina::sim {
namespace {

using nlohmann::json;

std::string error_of(std::string_view name, const json& inputs) {
  const auto r = calc_from_json(name, inputs);
  EXPECT_FALSE(r.has_value()) << r->dump();
  return r ? std::string() : r.error();
}

const json kExample71 = {{"pitch_mm", 6},
                         {"gear_ratio", 5},
                         {"steps_per_rev", 48},
                         {"distance_mm", 250},
                         {"feed_mm_per_min", 500}};

TEST(CalcJson, Example71FromJsonGivesThePrintedFigures) {
  const auto r = calc_from_json("open-loop", kExample71);
  ASSERT_TRUE(r.has_value()) << r.error();
  EXPECT_EQ((*r)["calculation"], "open_loop");
  EXPECT_EQ((*r)["inputs"]["steps_per_rev"], 48);
  EXPECT_EQ((*r)["results"]["whole_pulses"], 10000);
  EXPECT_NEAR((*r)["results"]["pulse_frequency_hz"].get<double>(), 333.333, 0.0005);
  EXPECT_NEAR((*r)["results"]["motor_rpm"].get<double>(), 416.667, 0.0005);
}

TEST(CalcJson, Examples72And73AndTheCuttingOnes) {
  json closed = kExample71;
  closed.erase("steps_per_rev");
  closed["encoder_slots"] = 48;
  const auto c = calc_from_json("closed-loop", closed);
  ASSERT_TRUE(c.has_value()) << c.error();
  EXPECT_EQ((*c)["results"]["whole_pulses"], 2000);  // x n_s / p: the encoder is on the screw
  EXPECT_NEAR((*c)["results"]["pulse_frequency_hz"].get<double>(), 66.667, 0.0005);

  const json example73 = {{"pitch_mm", 6},     {"gear_ratio", 5}, {"steps_per_rev", 48},
                          {"travel_mm", 1000}, {"bits", 16},      {"sigma_mm", 0.005}};
  const auto p = calc_from_json("precision", example73);
  ASSERT_TRUE(p.has_value()) << p.error();
  EXPECT_NEAR((*p)["results"]["control_resolution_mm"].get<double>(), 0.025, 1e-12);
  EXPECT_EQ((*p)["results"]["limited_by"], "mechanics");
  EXPECT_NEAR((*p)["results"]["accuracy_mm"].get<double>(), 0.0275, 1e-12);

  const auto cut = calc_from_json("cutting", {{"speed_m_per_min", 100}, {"diameter_mm", 10}});
  ASSERT_TRUE(cut.has_value()) << cut.error();
  EXPECT_NEAR((*cut)["results"]["spindle_rpm"].get<double>(), 3183.1, 0.05);
  EXPECT_TRUE((*cut)["results"]["feed_mm_per_min"].is_null());
  EXPECT_TRUE((*cut)["inputs"]["teeth"].is_null());
  const auto fed = calc_from_json(
      "cutting",
      {{"speed_m_per_min", 100}, {"diameter_mm", 10}, {"teeth", 4}, {"chip_load_mm", 0.05}});
  ASSERT_TRUE(fed.has_value()) << fed.error();
  EXPECT_NEAR((*fed)["results"]["feed_mm_per_min"].get<double>(), 636.62, 0.005);
}

TEST(CalcJson, EachBadInputIsNamed) {
  json missing = kExample71;
  missing.erase("feed_mm_per_min");
  EXPECT_EQ(error_of("open-loop", missing), "feed_mm_per_min is required");
  json negative = kExample71;
  negative["steps_per_rev"] = -48;  // whole, so the calculation's own message
  EXPECT_NE(error_of("open-loop", negative).find("not -48"), std::string::npos);
  json text = kExample71;
  text["pitch_mm"] = "6";
  EXPECT_EQ(error_of("open-loop", text), "pitch_mm: \"6\" is not a number");
  json half = kExample71;
  half["steps_per_rev"] = 48.5;
  EXPECT_EQ(error_of("open-loop", half), "steps_per_rev: 48.5 is not a whole number");
  json huge = kExample71;
  huge["steps_per_rev"] = 18446744073709551615ULL;
  EXPECT_EQ(error_of("open-loop", huge), "steps_per_rev: 18446744073709551615 is too large");
  json extra = kExample71;
  extra["feed"] = 500;
  EXPECT_NE(error_of("open-loop", extra).find("unknown input `feed`"), std::string::npos);
  EXPECT_EQ(error_of("open-loop", json::array()), "the inputs must be a JSON object of numbers");
  json nothing = kExample71;
  nothing["gear_ratio"] = nullptr;
  EXPECT_EQ(error_of("open-loop", nothing), "gear_ratio is required");
}

TEST(CalcJson, TheCalculationsOwnRefusalAndAnUnknownName) {
  json flat = kExample71;
  flat["pitch_mm"] = 0;
  EXPECT_NE(error_of("open-loop", flat).find("pitch"), std::string::npos);
  const json twelve_teeth = {{"speed_m_per_min", 100}, {"diameter_mm", 10}, {"teeth", 12}};
  EXPECT_FALSE(error_of("cutting", twelve_teeth).empty());  // teeth without a chip load
  EXPECT_NE(error_of("surfacing", json::object()).find("no calculator `surfacing`"),
            std::string::npos);
  EXPECT_NE(error_of("../etc", kExample71).find("no calculator"), std::string::npos);
}

// Table 7.4: the numeral as text keeps its leading zeros as digits of the
// code; a whole number of JSON is its decimal digits.
TEST(CalcJson, BcdOfTextAndOfAWholeNumber) {
  const auto text = calc_from_json("bcd", {{"numeral", "0125"}});
  ASSERT_TRUE(text.has_value()) << text.error();
  EXPECT_EQ((*text)["calculation"], "bcd");
  EXPECT_EQ((*text)["inputs"]["numeral"], "0125");
  EXPECT_EQ((*text)["results"]["value"], 125);
  EXPECT_EQ((*text)["results"]["code"], "0000 0001 0010 0101");
  ASSERT_EQ((*text)["results"]["digits"].size(), 4u);
  EXPECT_EQ((*text)["results"]["digits"][1]["place_value"], 100);
  const auto number = calc_from_json("bcd", {{"numeral", 1250}});
  ASSERT_TRUE(number.has_value()) << number.error();
  EXPECT_EQ((*number)["results"]["code"], "0001 0010 0101 0000");
  EXPECT_EQ(error_of("bcd", json::object()), "numeral is required");
  EXPECT_EQ(error_of("bcd", {{"numeral", 12.5}}),
            "numeral: 12.5 is neither digits as text (\"1250\") nor a whole number");
  EXPECT_EQ(error_of("bcd", {{"numeral", -3}}),
            "numeral: -3 is neither digits as text (\"1250\") nor a whole number");
  EXPECT_FALSE(error_of("bcd", {{"numeral", "12a"}}).empty());  // bcd's own refusal
  EXPECT_FALSE(error_of("bcd", {{"numeral", std::string(20, '9')}}).empty());
  EXPECT_NE(error_of("bcd", {{"number", "1"}}).find("unknown input `number`"), std::string::npos);
}

}  // namespace
}  // namespace usina::sim
