// POST /api/calc/{name} on a real server: seed 004's example 7.1 as
// `usina calc open-loop --format json` answers it; a bad input or an
// unknown calculator is 400 with the message; no session is 401.
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

using nlohmann::json;

const json kExample71 = {{"pitch_mm", 6},
                         {"gear_ratio", 5},
                         {"steps_per_rev", 48},
                         {"distance_mm", 250},
                         {"feed_mm_per_min", 500}};

TEST(ApiCalc, AnOperatorGetsExample71AsTheCommandLinePrintsIt) {
  test::RunningServer s;
  s.start();
  const test::ApiClient c = s.client();
  const test::Reply r =
      c.post("/api/calc/open-loop", kExample71, c.log_in("oper", test::kPassword));
  ASSERT_EQ(r.status, 200) << r.body;
  const json j = r.json();
  EXPECT_EQ(j["calculation"], "open_loop");
  EXPECT_EQ(j["inputs"], kExample71);
  EXPECT_EQ(j["results"]["whole_pulses"], 10000);
  EXPECT_NEAR(j["results"]["pulse_frequency_hz"].get<double>(), 1000.0 / 3.0, 1e-9);
}

TEST(ApiCalc, BadInputsAndUnknownCalculatorsAre400WithTheMessage) {
  test::RunningServer s;
  s.start();
  const test::ApiClient c = s.client();
  const std::string oper = c.log_in("oper", test::kPassword);
  json half = kExample71;
  half["steps_per_rev"] = 7.5;
  const test::Reply r = c.post("/api/calc/open-loop", half, oper);
  EXPECT_EQ(r.status, 400);
  EXPECT_NE(r.body.find("steps_per_rev: 7.5 is not a whole number"), std::string::npos) << r.body;
  const test::Reply none = c.post("/api/calc/surfacing", json::object(), oper);
  EXPECT_EQ(none.status, 400);
  EXPECT_NE(none.body.find("no calculator"), std::string::npos) << none.body;
  EXPECT_EQ(c.post("/api/calc/open-loop", kExample71).status, 401);
}

TEST(ApiCalc, BcdAsTheCommandLinePrintsIt) {
  test::RunningServer s;
  s.start();
  const test::ApiClient c = s.client();
  const std::string oper = c.log_in("oper", test::kPassword);
  const test::Reply r = c.post("/api/calc/bcd", {{"numeral", "1250"}}, oper);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json()["results"]["code"], "0001 0010 0101 0000");
  const test::Reply bad = c.post("/api/calc/bcd", {{"numeral", "1.5"}}, oper);
  EXPECT_EQ(bad.status, 400);
}

}  // namespace
}  // namespace usina::dnc
