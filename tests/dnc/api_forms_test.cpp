// POST /api/forms/{cycle}/preview against a real server: each cycle's
// program in each control, read back by that dialect with no error; each
// bad field named; too much work refused before anything is made; roles.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "dnc/form_cycles.hpp"
#include "pool_gate.hpp"
#include "server_fixture.hpp"
#include "support/dialect_run.hpp"

namespace usina::dnc {
namespace {

using nlohmann::json;

// A form of each cycle with the numbers a shop would give (the ellipse:
// docs/gen.md's seed 002 example).
json form_of(std::string_view cycle) {
  if (cycle == "ellipse_pocket") {
    return {{"center_x", 50}, {"center_y", 40}, {"rx", 30},
            {"ry", 18},       {"depth", 5},     {"tool_diameter", 8},
            {"stepover", 3},  {"step_down", 2}, {"finish_allowance", 0.5}};
  }
  if (cycle == "rect_pocket") {
    return {{"width", 60}, {"height", 40},   {"corner_radius", 5},
            {"depth", 6},  {"step_down", 2}, {"stepover", 2.5}};
  }
  if (cycle == "circle_pocket") {
    return {{"radius", 20}, {"center_x", 50}, {"center_y", 50}, {"depth", 3}, {"stepover", 4}};
  }
  if (cycle == "drill_grid") {
    return {{"x0", 10}, {"y0", 10}, {"nx", 5}, {"ny", 3}, {"dx", 20}, {"dy", 15}, {"depth", 5}};
  }
  if (cycle == "bolt_circle") {
    return {{"radius", 40}, {"count", 6},           {"start_angle", 15},
            {"depth", 12},  {"tool_diameter", 8.5}, {"peck", 3}};
  }
  if (cycle == "pocket_dxf") {  // docs/cam.md's cover: an outline and two islands
    std::ifstream in(std::string(USINA_TEST_DIR) + "/../examples/cover.dxf");
    std::stringstream dxf;
    dxf << in.rdbuf();
    return {{"dxf", dxf.str()}, {"layer", "POCKET"},  {"depth", 4},
            {"stepover", 1.5},  {"tool_diameter", 4}, {"step_down", 2}};
  }
  if (cycle == "profile_dxf") {
    // docs/cam.md's profile of the plate, its drawing as the page uploads it.
    std::ifstream in(std::string(USINA_TEST_DIR) + "/../examples/plate.dxf");
    std::stringstream dxf;
    dxf << in.rdbuf();
    return {{"dxf", dxf.str()}, {"side", "outside"}, {"depth", 6},     {"step_down", 2},
            {"lead_radius", 4}, {"tabs", 4},         {"tab_width", 5}, {"tab_height", 1.5}};
  }
  return {{"text", "USINA 2026"}, {"height", 8}, {"at_x", 10}, {"at_y", 5}, {"tool_diameter", 0.5}};
}

class FormsRoute : public ::testing::Test {
 protected:
  void SetUp() override {
    server.start();
    prog = client().log_in("prog", test::kPassword);
    ASSERT_FALSE(prog.empty());
  }

  test::ApiClient client() const { return server.client(); }

  test::Reply preview(std::string_view cycle, json body, const std::string& dialect = "rs274ngc") {
    body["dialect"] = dialect;
    return client().post("/api/forms/" + std::string(cycle) + "/preview", body, prog);
  }

  // The field of each error of a 400 answer.
  static std::vector<std::string> fields(const test::Reply& r) {
    std::vector<std::string> out;
    const json body = r.json();
    for (const json& e : body["errors"])
      out.push_back(e["field"].get<std::string>());
    return out;
  }

  test::RunningServer server;
  std::string prog;
};

TEST_F(FormsRoute, EachCycleInEachControlIsReadByItsDialectWithNoError) {
  for (std::string_view cycle : form_cycles()) {
    for (const char* dialect : {"rs274ngc", "fanuc", "grbl", "romi"}) {
      const test::Reply r = preview(cycle, form_of(cycle), dialect);
      ASSERT_EQ(r.status, 200) << cycle << " " << dialect << ": " << r.body;
      const json j = r.json();
      const std::string text = j["text"].get<std::string>();
      EXPECT_GT(text.size(), 50u) << cycle << " " << dialect;
      auto run = gcode::dialect_test::run_in(dialect, text);
      EXPECT_TRUE(run->ok) << cycle << " " << dialect;
      EXPECT_EQ(run->first_error_text(), "") << cycle << " " << dialect << "\n" << text;
      EXPECT_EQ(j["checks"]["errors"], 0) << cycle << " " << dialect;
      EXPECT_TRUE(j["check_ok"]) << cycle << " " << dialect;
      EXPECT_FALSE(j["toolpath"].get<std::string>().empty());
    }
  }
}

TEST_F(FormsRoute, TheEllipseIsSeed002sPocketAsUsinaGenMakesIt) {
  const test::Reply r = preview("ellipse_pocket", form_of("ellipse_pocket"));
  ASSERT_EQ(r.status, 200) << r.body;
  const std::string text = r.json()["text"].get<std::string>();
  EXPECT_NE(text.find("elliptical pocket X50 Y40 RX30 RY18 depth 5 tool D8"), std::string::npos)
      << text.substr(0, 400);
  // The tool path stream: "USTP" little-endian, base64 of the header's start.
  EXPECT_EQ(r.json()["toolpath"].get<std::string>().substr(0, 6), "VVNUUA");
}

// The XY end of every move of an rs274ngc program (X and Y are modal).
std::vector<std::pair<double, double>> move_ends(const std::string& text) {
  std::vector<std::pair<double, double>> out;
  double x = 0;
  double y = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (line.starts_with("(")) continue;
    const auto word = [&](char c, double& v) {
      const auto at = line.find(c);
      if (at != std::string::npos) v = std::stod(line.substr(at + 1));
      return at != std::string::npos;
    };
    if (word('X', x) | word('Y', y)) out.emplace_back(x, y);
  }
  return out;
}

// docs/cam.md's cover: the tool (D4) clears the pocket 80 x 50 from (10,10)
// around the boss (a circle of radius 6 about (30,35)) and the block
// (60,28)-(75,42), and comes near both.
TEST_F(FormsRoute, APocketFromADrawingLeavesItsIslandsStanding) {
  const test::Reply r = preview("pocket_dxf", form_of("pocket_dxf"));
  ASSERT_EQ(r.status, 200) << r.body;
  const auto ends = move_ends(r.json()["text"].get<std::string>());
  ASSERT_GT(ends.size(), 100u);
  double near_boss = 1e9;
  double near_block = 1e9;
  for (const auto& [x, y] : ends) {
    const double boss = std::hypot(x - 30, y - 35) - 6;
    const double dx = std::max({60 - x, 0.0, x - 75});
    const double dy = std::max({28 - y, 0.0, y - 42});
    const double block = std::hypot(dx, dy);
    EXPECT_GE(boss, 2 - 1e-3) << x << "," << y;  // the tool's radius: the boss stands
    EXPECT_GE(block, 2 - 1e-3) << x << "," << y;
    EXPECT_TRUE(x >= 12 - 1e-3 && x <= 88 + 1e-3 && y >= 12 - 1e-3 && y <= 58 + 1e-3)
        << x << "," << y;
    near_boss = std::min(near_boss, boss);
    near_block = std::min(near_block, block);
  }
  EXPECT_LT(near_boss, 2.5) << "the rings go round the boss";
  EXPECT_LT(near_block, 2.5) << "the rings go round the block";
}

TEST_F(FormsRoute, EveryBadFieldIsNamed) {
  json bad = form_of("ellipse_pocket");
  bad["feed"] = 0;
  bad["rx"] = -3;
  bad["resolution"] = "fine";
  bad.erase("depth");
  bad["depht"] = 5;
  const test::Reply r = preview("ellipse_pocket", bad);
  ASSERT_EQ(r.status, 400) << r.body;
  const auto f = fields(r);
  for (const char* want : {"feed", "rx", "resolution", "depth", "depht"})
    EXPECT_NE(std::find(f.begin(), f.end(), want), f.end()) << want << ": " << r.body;
  EXPECT_EQ(f.size(), 5u) << r.body;
  EXPECT_EQ(r.json()["errors"][0]["code"], "E_GEN_BAD_VALUE");
}

TEST_F(FormsRoute, EachCyclesOwnBadFieldIsNamedWithUsinaGensMessage) {
  const std::tuple<const char*, const char*, json, const char*> cases[] = {
      {"ellipse_pocket", "tool_diameter", 40, "E_GEN_TOOL_TOO_BIG"},
      {"ellipse_pocket", "stepover", 9, "E_GEN_BAD_VALUE"},
      {"ellipse_pocket", "floor_allowance", 5, "E_GEN_BAD_VALUE"},
      {"rect_pocket", "corner_radius", 25, "E_GEN_BAD_VALUE"},
      {"rect_pocket", "finish_allowance", 30, "E_GEN_MATERIAL_LEFT"},
      {"circle_pocket", "tool_diameter", 50, "E_GEN_TOOL_TOO_BIG"},
      {"drill_grid", "dx", 0, "E_GEN_BAD_VALUE"},
      {"drill_grid", "nx", 100000, "E_GEN_BAD_VALUE"},
      {"bolt_circle", "retract", 9, "E_GEN_BAD_VALUE"},
      {"bolt_circle", "count", 0, "E_GEN_BAD_VALUE"},
      {"engrave", "text", "São Paulo", "E_TEXT_NOT_IN_FONT"},
      {"engrave", "font", "../../etc/passwd", "E_GEN_BAD_VALUE"},
      {"engrave", "font", "nosuchfont", "E_FONT_UNREADABLE"},
      {"rect_pocket", "dialect", "heidenhain", "E_GEN_BAD_VALUE"},
      {"profile_dxf", "dxf", "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n", "E_DXF_MALFORMED"},
      {"profile_dxf", "tab_height", 6, "E_GEN_BAD_VALUE"},
      {"profile_dxf", "side", "around", "E_GEN_BAD_VALUE"},
      {"pocket_dxf", "dxf", "0\nSECTION\n2\nENTITIES\n0\nLINE\n10\n", "E_DXF_MALFORMED"},
      {"pocket_dxf", "stepover", 5, "E_GEN_BAD_VALUE"},
  };
  for (const auto& [cycle, field, value, code] : cases) {
    json body = form_of(cycle);
    if (std::string_view(field) == "dialect") {
      const test::Reply r = preview(cycle, body, value.get<std::string>());
      EXPECT_EQ(fields(r), std::vector<std::string>{field}) << r.body;
      continue;
    }
    body[field] = value;
    const test::Reply r = preview(cycle, body);
    ASSERT_EQ(r.status, 400) << cycle << " " << field << ": " << r.body;
    EXPECT_EQ(fields(r), std::vector<std::string>{field}) << cycle << ": " << r.body;
    EXPECT_EQ(r.json()["errors"][0]["code"], code) << cycle << ": " << r.body;
    EXPECT_FALSE(r.json()["errors"][0]["message"].get<std::string>().empty());
  }
}

// The ellipse at resolution 0.0001 mm would be millions of moves: refused
// from the estimate, before a point is made (docs/gen.md).
TEST_F(FormsRoute, WorkPastTheBoundIsRefusedWithTheEstimate) {
  json big = form_of("ellipse_pocket");
  big["resolution"] = 0.0001;
  const auto start = std::chrono::steady_clock::now();
  const test::Reply r = preview("ellipse_pocket", big);
  const auto took = std::chrono::steady_clock::now() - start;
  ASSERT_EQ(r.status, 400) << r.body;
  EXPECT_EQ(fields(r), std::vector<std::string>{"resolution"});
  const json e = r.json()["errors"][0];
  EXPECT_EQ(e["code"], "E_GEN_TOO_MUCH_WORK");
  EXPECT_NE(e["message"].get<std::string>().find("more than the limit of 1,000,000"),
            std::string::npos)
      << e["message"];
  // Not a timing assertion: a record of the speed for the report.
  RecordProperty(
      "refused_ms",
      static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(took).count()));
  json raised = form_of("ellipse_pocket");
  raised["max_moves"] = 20e6;  // usina gen's own default is past a preview's bound
  EXPECT_EQ(fields(preview("ellipse_pocket", raised)), std::vector<std::string>{"max_moves"});
}

TEST_F(FormsRoute, AnOperatorIs403NoTokenIs401AnUnknownCycleIs404) {
  json body = form_of("circle_pocket");
  body["dialect"] = "grbl";
  const std::string oper = client().log_in("oper", test::kPassword);
  EXPECT_EQ(client().post("/api/forms/circle_pocket/preview", body, oper).status, 403);
  EXPECT_EQ(client().post("/api/forms/circle_pocket/preview", body).status, 401);
  const std::string appr = client().log_in("appr", test::kPassword);
  EXPECT_EQ(client().post("/api/forms/circle_pocket/preview", body, appr).status, 403);
  const std::string boss = client().log_in("boss", test::kPassword);
  EXPECT_EQ(client().post("/api/forms/circle_pocket/preview", body, boss).status, 200);
  const test::Reply none = client().post("/api/forms/spiral/preview", body, prog);
  EXPECT_EQ(none.status, 404);
  EXPECT_NE(none.body.find("ellipse_pocket"), std::string::npos) << none.body;
  EXPECT_EQ(client().call(test::bhttp::verb::post, "/api/forms/engrave/preview", "{x", prog).status,
            400);
}

// GET /api/forms describes each cycle's fields as the preview reads them:
// the page's ranges come from here, so a value the description puts past a
// field's range is one the preview refuses at that field.
TEST_F(FormsRoute, TheFormsDescribeTheRangesThePreviewChecks) {
  const test::Reply r = client().get("/api/forms", prog);
  ASSERT_EQ(r.status, 200) << r.body;
  const json specs = r.json();
  ASSERT_EQ(specs["cycles"].size(), form_cycles().size());
  int refused = 0;
  for (const json& cycle : specs["cycles"]) {
    const std::string name = cycle["name"];
    std::map<std::string, json> by_name;
    for (const json& f : cycle["fields"])
      by_name[f["name"]] = f;
    const json good = form_of(name);
    for (const auto& [key, value] : good.items())
      EXPECT_TRUE(by_name.contains(key)) << name << ": " << key << " is not described";
    for (const auto& [key, f] : by_name) {
      if (f["kind"] == "text") continue;
      json body = form_of(name);
      body[key] = f["max"].get<double>() * 2 + 1;
      EXPECT_EQ(fields(preview(name, body)), std::vector<std::string>{key}) << name << " " << key;
      ++refused;
    }
  }
  EXPECT_GE(refused, 100);  // 103 today: every number of the seven cycles
  const json& cutting = specs["cycles"][0]["fields"];
  const auto diameter = std::find_if(cutting.begin(), cutting.end(),
                                     [](const json& f) { return f["name"] == "tool_diameter"; });
  ASSERT_NE(diameter, cutting.end());
  EXPECT_EQ((*diameter)["min"], 0.001);
  EXPECT_EQ((*diameter)["max"], 1000.0);
  EXPECT_EQ((*diameter)["min_included"], true);
  EXPECT_EQ((*diameter)["unit"], "mm");
  EXPECT_EQ((*diameter)["default"], 6.0);
  EXPECT_EQ(client().get("/api/forms", client().log_in("oper", test::kPassword)).status, 403);
}

// The profile's side is one of its choices; its tab count a whole number
// (2.5 tabs were read as 2 before the count was described).
TEST_F(FormsRoute, TheSideIsAChoiceAndTabsAWholeNumber) {
  const json specs = client().get("/api/forms", prog).json();
  json side;
  json tabs;
  for (const json& cycle : specs["cycles"]) {
    for (const json& f : cycle["fields"]) {
      if (cycle["name"] == "profile_dxf" && f["name"] == "side") side = f;
      if (cycle["name"] == "profile_dxf" && f["name"] == "tabs") tabs = f;
    }
  }
  EXPECT_EQ(side["choices"],
            (std::vector<std::string>{"outside", "inside", "auto", "left", "right", "on"}));
  EXPECT_EQ(side["default"], "outside");
  EXPECT_EQ(tabs["kind"], "whole");
  json body = form_of("profile_dxf");
  body["tabs"] = 2.5;
  const test::Reply half = preview("profile_dxf", body);
  EXPECT_EQ(fields(half), std::vector<std::string>{"tabs"});
  EXPECT_NE(half.body.find("whole number"), std::string::npos) << half.body;
  body = form_of("profile_dxf");
  body["side"] = "around";
  const test::Reply around = preview("profile_dxf", body);
  EXPECT_EQ(fields(around), std::vector<std::string>{"side"});
  EXPECT_NE(around.body.find("the side is one of outside, inside, auto, left, right, on"),
            std::string::npos)
      << around.body;
}

TEST_F(FormsRoute, AFormSentAgainIsAnsweredFromTheCacheAndSavesAsADraft) {
  const test::Reply first = preview("bolt_circle", form_of("bolt_circle"), "fanuc");
  ASSERT_EQ(first.status, 200) << first.body;
  const test::Reply again = preview("bolt_circle", form_of("bolt_circle"), "fanuc");
  EXPECT_EQ(again.body, first.body);
  const auto counters = server.on_loop([&] { return server.server().toolpaths().counters(); });
  EXPECT_EQ(counters.hits, 1u);
  const test::Reply saved = client().post("/api/programs",
                                          {{"name", "O2001"},
                                           {"dialect", "fanuc"},
                                           {"machine_class", "mill"},
                                           {"text", first.json()["text"]},
                                           {"reason", "bolt circle form"}},
                                          prog);
  ASSERT_EQ(saved.status, 201) << saved.body;
  EXPECT_EQ(saved.json()["state"], "draft");
  EXPECT_TRUE(saved.json()["check_ok"]);
}

// The work is the pool's: while a preview is held there, the loop answers.
TEST_F(FormsRoute, TheLoopAnswersWhileAPreviewIsMade) {
  test::Gate gate;
  server.server().toolpaths().before_run = [&gate] { gate.enter(); };
  std::atomic<int> finished{0};
  int preview_done = 0;
  test::Reply made;
  std::jthread page([&] {
    made = preview("ellipse_pocket", form_of("ellipse_pocket"));
    preview_done = ++finished;
  });
  test::ReleaseOnExit release{gate};
  ASSERT_TRUE(gate.wait_entered(1));
  const test::Reply session = client().get("/api/session", prog);
  const int session_done = ++finished;
  EXPECT_EQ(session.status, 200);
  gate.release();
  page.join();
  EXPECT_EQ(made.status, 200) << made.body;
  EXPECT_LT(session_done, preview_done);
}

}  // namespace
}  // namespace usina::dnc
