// Tool lives: a machine's `tool_life` table of usina-serve.toml read and
// every bad value refused at its line; GET /api/machines/{m}/tools gives
// each tool's life, the share used and whether it is worn, and a tool with
// a life that has cut nothing yet.
#include "dnc/tool_life_config.hpp"

#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/machine_settings.hpp"
#include "dnc/server_config.hpp"

namespace usina::dnc {
namespace {

const std::string kMachine = "[[machine]]\nname = \"m1\"\nport = \"/dev/null\"\n";

TEST(ToolLifeConfig, AMachinesToolsHaveTheirLives) {
  core::DiagnosticList diags;
  auto c = read_server_config(kMachine +
                                  "[machine.tool_life]\nT1 = {parts = 500}\n"
                                  "T02 = {cutting_minutes = 90.5, parts = 200}\n",
                              0, diags);
  ASSERT_TRUE(c) << (diags.all().empty() ? "" : diags.all()[0].message);
  EXPECT_TRUE(diags.all().empty());
  const ToolLives& lives = c->machines.at(0).tool_life;
  ASSERT_EQ(lives.size(), 2u);
  EXPECT_EQ(lives.at(1).parts, 500);
  EXPECT_FALSE(lives.at(1).cutting_minutes);
  EXPECT_EQ(lives.at(2).parts, 200);
  EXPECT_EQ(lives.at(2).cutting_minutes, 90.5);
  // Without the table, no tool has a life.
  auto none = read_server_config(kMachine, 0, diags);
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->machines.at(0).tool_life.empty());
}

TEST(ToolLifeConfig, EachBadValueIsAnErrorAtItsLine) {
  struct Bad {
    const char* body;  // after [machine.tool_life] (line 5)
    const char* says;
  };

  const Bad cases[] = {
      {"T = {parts = 5}\n", "tool_life.T is no tool"},
      {"X1 = {parts = 5}\n", "tool_life.X1 is no tool"},
      {"T123456789 = {parts = 5}\n", "tool_life.T123456789 is no tool"},
      {"T1 = 5\n", "tool_life.T1 must be a table"},
      {"T1 = {parts = 0}\n", "tool_life.T1.parts must be a whole number from 1"},
      {"T1 = {parts = 1.5}\n", "tool_life.T1.parts must be a whole number"},
      {"T1 = {parts = 2000000000}\n", "tool_life.T1.parts must be a whole number"},
      {"T1 = {cutting_minutes = -1}\n", "tool_life.T1.cutting_minutes must be a number above 0"},
      {"T1 = {cutting_minutes = nan}\n", "cutting_minutes must be a number above 0"},
      {"T1 = {cutting_minutes = \"90\"}\n", "cutting_minutes must be a number above 0"},
      {"T1 = {}\n", "gives neither parts nor cutting_minutes"},
      {"T1 = {parts = 5}\nt1 = {parts = 6}\n", "tool_life gives T1 twice"},
  };
  for (const Bad& b : cases) {
    core::DiagnosticList diags;
    EXPECT_FALSE(read_server_config(kMachine + "[machine.tool_life]\n" + b.body, 0, diags))
        << b.body;
    bool found = false;
    for (const core::Diagnostic& d : diags.all()) {
      if (d.code != core::Code::DncConfig || d.message.find(b.says) == std::string::npos) continue;
      found = true;
      EXPECT_GE(d.loc.line, 5u) << b.body << d.message;
      EXPECT_NE(d.message.find("machine `m1`"), std::string::npos) << d.message;
    }
    EXPECT_TRUE(found) << b.body << " wanted: " << b.says
                       << "\ngot: " << (diags.all().empty() ? "nothing" : diags.all()[0].message);
  }
  core::DiagnosticList diags;
  EXPECT_FALSE(read_server_config(kMachine + "tool_life = 3\n", 0, diags));
  ASSERT_FALSE(diags.all().empty());
  EXPECT_NE(diags.all()[0].message.find("tool_life must be a table"), std::string::npos);
}

TEST(ToolLifeConfig, AnUnknownKeyIsAWarningWithTheNearestName) {
  core::DiagnosticList diags;
  auto c = read_server_config(
      kMachine + "[machine.tool_life]\nT1 = {parts = 5, cutting_minute = 3}\n", 0, diags);
  ASSERT_TRUE(c);
  ASSERT_EQ(diags.all().size(), 1u);
  EXPECT_EQ(diags.all()[0].code, core::Code::UnknownDncKey);
  EXPECT_NE(diags.all()[0].message.find("did you mean `cutting_minutes`?"), std::string::npos)
      << diags.all()[0].message;
  EXPECT_FALSE(c->machines.at(0).tool_life.at(1).cutting_minutes);
}

TEST(ToolLifeConfig, TheShareUsedIsTheLargerOfPartsAndMinutes) {
  EXPECT_FALSE(life_used({}, 10, 60.0));
  EXPECT_DOUBLE_EQ(*life_used({4, std::nullopt}, 1, 1e9), 0.25);
  EXPECT_DOUBLE_EQ(*life_used({std::nullopt, 2.0}, 100, 60.0), 0.5);
  EXPECT_DOUBLE_EQ(*life_used({4, 2.0}, 1, 180.0), 1.5);
}

TEST(ToolLifeConfig, TheMachineSettingsApiLeavesItToTheFile) {
  auto m = machine_from_settings(
      {{"name", "m9"}, {"port", "/dev/null"}, {"tool_life", {{"T1", {{"parts", 5}}}}}});
  ASSERT_FALSE(m);
  EXPECT_NE(m.error().find("tool_life names a file or table of usina-serve.toml"),
            std::string::npos)
      << m.error();
}

// T1 cuts 10 mm at F100 (6 s), T2 20 mm (12 s); T7 has a life and never cut.
const std::string kTwoTools = "T1 M6\nG1 X10 F100\nT2 M6\nG1 X-10 F100\nM2\n";

nlohmann::json tool_of(const nlohmann::json& answer, int number) {
  for (const auto& t : answer["tools"])
    if (t["tool"] == number) return t;
  return nullptr;
}

TEST(ApiToolLife, EachToolSaysItsLifeTheShareUsedAndWhetherItIsWorn) {
  RunningServer s;
  ToolLives lives;
  lives[1] = {2, std::nullopt};
  lives[2] = {std::nullopt, 0.1};  // 6 s: the 12 s of one part wear it out
  lives[7] = {10, std::nullopt};
  Control control = start_with_control(s, 115200, lives);
  const ApiClient c = s.client();
  const std::string rev = released(c, "O777", kTwoTools);
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  const auto job = c.post("/api/machines/mill-1/jobs",
                          {{"program", "O777"}, {"revision", rev}, {"mode", "drip"}}, oper);
  ASSERT_EQ(job.status, 201) << job.body;
  ASSERT_EQ(wait_for_end(c, oper, job.json()["job"].get<std::int64_t>())["state"], "done");

  const auto t = c.get("/api/machines/mill-1/tools", oper).json();
  const auto t1 = tool_of(t, 1);
  EXPECT_EQ(t1["life_parts"], 2);
  EXPECT_TRUE(t1["life_cutting_minutes"].is_null());
  EXPECT_DOUBLE_EQ(t1["life_used"].get<double>(), 0.5);
  EXPECT_EQ(t1["worn"], false);
  const auto t2 = tool_of(t, 2);
  // 12 s of cutting over 6 s of life (the planner's acceleration adds ms).
  EXPECT_NEAR(t2["life_used"].get<double>(), 2.0, 0.01) << t2;
  EXPECT_EQ(t2["worn"], true);
  const auto t7 = tool_of(t, 7);
  ASSERT_FALSE(t7.is_null()) << t.dump();
  EXPECT_EQ(t7["parts"], 0);
  EXPECT_EQ(t7["life_used"], 0.0);
  EXPECT_EQ(t7["worn"], false);
  // A tool without a life says so; the list stays in tool order.
  EXPECT_TRUE(tool_of(t, 0).is_null() || tool_of(t, 0)["life_used"].is_null());
  for (std::size_t i = 1; i < t["tools"].size(); ++i)
    EXPECT_LT(t["tools"][i - 1]["tool"].get<int>(), t["tools"][i]["tool"].get<int>());

  // A new tool in the spindle: T2's count, and its wear, start again.
  ASSERT_EQ(c.post("/api/machines/mill-1/tools/T2/reset", {{"reason", "new"}}, oper).status, 200);
  const auto after = tool_of(c.get("/api/machines/mill-1/tools", oper).json(), 2);
  EXPECT_EQ(after["life_used"], 0.0);
  EXPECT_EQ(after["worn"], false);
}

}  // namespace
}  // namespace usina::dnc
