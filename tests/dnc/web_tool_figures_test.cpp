// The figures of each tool (web_toolpath_tools.hpp): usina stats' per-tool
// times and distances of a revision, and their route, computed on the
// tool-path service's pool and then served from its cache.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "dnc/web_toolpath_tools.hpp"
#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

constexpr const char* kTwoTools =
    "G21 G90 G94\nT1 M6\nG0 X0 Y0 Z1\nG1 X100 F1000\nT2 M6\nG1 Y50 F500\nG0 Z10\nM2\n";

const nlohmann::json* tool(const nlohmann::json& figures, int n) {
  for (const auto& t : figures["tools"])
    if (t["tool"] == n) return &t;
  return nullptr;
}

TEST(WebToolFigures, EachToolHasItsDistancesAndTimes) {
  ToolFiguresSettings s;
  const auto figures = nlohmann::json::parse(tool_figures_json(kTwoTools, s));
  EXPECT_TRUE(figures["complete"]);
  const nlohmann::json* t1 = tool(figures, 1);
  const nlohmann::json* t2 = tool(figures, 2);
  ASSERT_NE(t1, nullptr) << figures.dump();
  ASSERT_NE(t2, nullptr) << figures.dump();
  EXPECT_NEAR((*t1)["cutting_mm"].get<double>(), 100.0, 1e-9);
  EXPECT_NEAR((*t2)["cutting_mm"].get<double>(), 50.0, 1e-9);
  // 100 mm at 1000 mm/min is 6 s, 50 mm at 500 mm/min too; acceleration adds a little.
  EXPECT_GE((*t1)["cutting_s"].get<double>(), 6.0);
  EXPECT_LT((*t1)["cutting_s"].get<double>(), 7.0);
  EXPECT_GE((*t2)["cutting_s"].get<double>(), 6.0);
  EXPECT_NEAR(figures["total"]["cutting_mm"].get<double>(), 150.0, 1e-9);
}

TEST(WebToolFigures, AnUnknownDialectIsIncomplete) {
  ToolFiguresSettings s;
  s.dialect = "no-such-control";
  const auto figures = nlohmann::json::parse(tool_figures_json("G1 X1 F100\n", s));
  EXPECT_FALSE(figures["complete"]);
  EXPECT_TRUE(figures["tools"].empty());
}

TEST(WebToolFiguresRoute, ComputedOnceThenFromTheCache) {
  test::RunningServer server;
  server.start();
  const test::ApiClient client = server.client();
  const std::string prog = client.log_in("prog", test::kPassword);
  const test::Reply up = client.post("/api/programs", {{"name", "O7"}, {"text", kTwoTools}}, prog);
  ASSERT_EQ(up.status, 201) << up.body;
  const std::string route =
      "/api/programs/O7/revisions/" + up.json()["revision"].get<std::string>() + "/tools";
  const std::string oper = client.log_in("oper", test::kPassword);
  const test::Reply first = client.get(route, oper);
  ASSERT_EQ(first.status, 200) << first.body;
  EXPECT_EQ(first.json()["tools"].size(), 2u);
  const test::Reply second = client.get(route, oper);
  EXPECT_EQ(second.body, first.body);
  const ToolpathCounters n = server.on_loop([&] { return server.server().toolpaths().counters(); });
  EXPECT_EQ(n.computed, 1u);
  EXPECT_EQ(n.hits, 1u);
  EXPECT_EQ(client.get(route).status, 401);
  EXPECT_EQ(
      client.get("/api/programs/O7/revisions/" + std::string(64, 'a') + "/tools", oper).status,
      404);
  EXPECT_EQ(
      client.get("/api/programs/O8/revisions/" + std::string(64, 'a') + "/tools", oper).status,
      404);
}

}  // namespace
}  // namespace usina::dnc
