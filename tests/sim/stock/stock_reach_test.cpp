// The tool above its end (issue 17): the shank above the flutes rubbing the
// stock where the tool enters it, the holder meeting the stock, a tool that
// does not cut at its centre going down into the stock; and the volume
// removed per operation. Programs run by the interpreter, or sweeps on a
// height map set by hand where the case needs a shape no program leaves.
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "sim/stock/holder.hpp"
#include "sim/stock/simulator.hpp"
#include "support/dialect_run.hpp"

namespace usina::sim::stock {
namespace {

struct Simulated {
  std::unique_ptr<HeightMap> map;
  std::unique_ptr<StockSimulator> sim;
  core::DiagnosticList diags;
};

std::unique_ptr<Simulated> simulate(const std::string& program, const StockBox& box,
                                    SimulateOptions options) {
  auto s = std::make_unique<Simulated>();
  auto made = HeightMap::make(box, 0.1);
  EXPECT_TRUE(made) << made.error();
  s->map = std::make_unique<HeightMap>(std::move(*made));
  const auto run = gcode::dialect_test::run_in("rs274ngc", program);
  EXPECT_TRUE(run->ok);
  s->sim = std::make_unique<StockSimulator>(*s->map, std::move(options), s->diags);
  for (const canon::Op& op : run->path.ops())
    s->sim->on(op);
  return s;
}

// Tool 1 (and more) as `--tool-shape` reads them.
SimulateOptions tools(std::initializer_list<const char*> specs) {
  SimulateOptions o;
  for (const char* spec : specs) {
    const auto t = parse_tool_spec(spec, {});
    EXPECT_TRUE(t) << t.error();
    o.tools[t->first] = t->second;
  }
  return o;
}

std::string describe(const std::vector<Check>& checks) {
  std::string all;
  for (const Check& c : checks)
    all += std::to_string(c.loc.line) + ": " + c.message + "\n";
  return all;
}

void expect_one(const Simulated& s, core::Code code, std::uint32_t line, const std::string& words) {
  ASSERT_EQ(s.sim->checks().size(), 1u) << describe(s.sim->checks());
  EXPECT_EQ(s.sim->checks()[0].code, code);
  EXPECT_EQ(s.sim->checks()[0].loc.line, line);
  EXPECT_NE(s.sim->checks()[0].message.find(words), std::string::npos)
      << s.sim->checks()[0].message;
}

// A slot 5 deep along X, fed in straight down at line 3, along at line 4.
const char* const kSlot = "T1 M6\nG0 X10 Y20 Z2\nG1 Z-5 F100\nG1 X40\nG0 Z5\nM30\n";

TEST(StockReach, AWallThreeMillimetresAboveTheFlutesRubsTheShank) {
  const auto s = simulate(kSlot, {60, 40, 10, {}}, tools({"1=flat/6,flutes:2"}));
  // The plunge goes down its own hole; along X the stock stands 5 - 2 mm above the flutes.
  expect_one(*s, core::Code::ShankRubsStock, 4, "3.000 mm above the flutes of tool 1 (2 mm");
  ASSERT_FALSE(s->diags.all().empty());
  EXPECT_EQ(s->diags.all()[0].severity, core::Severity::Error);
}

TEST(StockReach, FlutesAsLongAsTheDepthClearAndAHundredthLessRub) {
  EXPECT_TRUE(
      simulate(kSlot, {60, 40, 10, {}}, tools({"1=flat/6,flutes:5"}))->sim->checks().empty());
  const auto s = simulate(kSlot, {60, 40, 10, {}}, tools({"1=flat/6,flutes:4.99"}));
  expect_one(*s, core::Code::ShankRubsStock, 4, "0.010 mm above the flutes");
}

TEST(StockReach, StepsNoDeeperThanTheFlutesClear) {
  // Two passes 2 mm down each with 2.5 mm of flutes: the second enters stock
  // the first left 2 mm lower (the height before the move is what counts).
  const auto s = simulate("T1 M6\nG0 X10 Y20 Z2\nG1 Z-2 F100\nG1 X40\nG1 Z-4\nG1 X10\nG0 Z5\nM30\n",
                          {60, 40, 10, {}}, tools({"1=flat/6,flutes:2.5"}));
  EXPECT_TRUE(s->sim->checks().empty()) << describe(s->sim->checks());
}

// The tool runs along X outside the stock (Y < 0), 15 deep, its holder (20
// mm, 10 mm above the tip) reaching over the stock's first row of cells
// (centres at Y 0.05) when the tool's axis is within 10 mm of it.
std::string beside_the_stock(double y) {
  return "T1 M6\nG0 X5 Y" + std::to_string(y) + " Z5\nG1 Z-15 F100\nG1 X50\nG0 Z5\nM30\n";
}

TEST(StockReach, AHolderReachesAWallByTheAnalyticDepth) {
  // The holder's face at -15 + 10 = -5 under a top at 0: 5.000 mm into it,
  // going down (line 3) and along (line 4).
  const auto s = simulate(beside_the_stock(0.05 - 10.0 + 0.001), {60, 40, 30, {}},
                          tools({"1=flat/6,holder:20,stickout:10"}));
  ASSERT_EQ(s->sim->checks().size(), 2u) << describe(s->sim->checks());
  for (const Check& c : s->sim->checks()) {
    EXPECT_EQ(c.code, core::Code::HolderHitsStock);
    EXPECT_NE(c.message.find("goes 5.000 mm into the stock"), std::string::npos) << c.message;
  }
  EXPECT_EQ(s->sim->checks()[0].loc.line, 3u);
  EXPECT_EQ(s->sim->checks()[1].loc.line, 4u);
  EXPECT_DOUBLE_EQ(s->sim->removed_mm3(), 0.0);  // the tool itself is outside
}

TEST(StockReach, AHolderClearsTheWallAHundredthFurther) {
  const auto s = simulate(beside_the_stock(0.05 - 10.0 - 0.01), {60, 40, 30, {}},
                          tools({"1=flat/6,holder:20,stickout:10"}));
  EXPECT_TRUE(s->sim->checks().empty()) << describe(s->sim->checks());
}

TEST(StockReach, AToolWithoutTheValuesIsNotChecked) {
  const auto s = simulate(beside_the_stock(0.05 - 10.0 + 0.001), {60, 40, 30, {}},
                          tools({"1=flat/6,flutes:20"}));
  EXPECT_TRUE(s->sim->checks().empty()) << describe(s->sim->checks());
  const auto plain = simulate(kSlot, {60, 40, 10, {}}, tools({"1=flat/6"}));
  EXPECT_TRUE(plain->sim->checks().empty()) << describe(plain->sim->checks());
}

TEST(StockReach, AHolderLevelWithTheTopClearsAndAHundredthBelowHits) {
  const SimulateOptions holder = tools({"1=flat/6,holder:20,stickout:10"});
  const auto level =
      simulate("T1 M6\nG0 X30 Y20 Z2\nG1 Z-10 F100\nG0 Z5\nM30\n", {60, 40, 30, {}}, holder);
  EXPECT_TRUE(level->sim->checks().empty()) << describe(level->sim->checks());
  const auto below =
      simulate("T1 M6\nG0 X30 Y20 Z2\nG1 Z-10.01 F100\nG0 Z5\nM30\n", {60, 40, 30, {}}, holder);
  expect_one(*below, core::Code::HolderHitsStock, 3, "goes 0.010 mm into the stock");
}

TEST(StockReach, AHolderInsideAWiderPocketClears) {
  // A 40 mm end mill opens a pocket of radius 20, 20 deep; tool 1 works 15
  // deep in it, 5 mm off its centre: a holder of radius 10 stays within 15
  // of the centre; one of radius 16 reaches 21, 1 mm into the pocket's wall.
  const char* program =
      "T2 M6\nG0 X30 Y20 Z2\nG1 Z-20 F100\nG0 Z5\nT1 M6\nG0 X30 Y20 Z2\nG1 Z-15\nG1 X35\nG0 "
      "Z5\nM30\n";
  const auto inside =
      simulate(program, {60, 40, 30, {}}, tools({"2=flat/40", "1=flat/6,holder:20,stickout:10"}));
  EXPECT_TRUE(inside->sim->checks().empty()) << describe(inside->sim->checks());
  const auto wide =
      simulate(program, {60, 40, 30, {}}, tools({"2=flat/40", "1=flat/6,holder:32,stickout:10"}));
  expect_one(*wide, core::Code::HolderHitsStock, 8, "goes 5.000 mm into the stock");
}

// A height map whose cells are all at `low` but for a block [x0, x1] x [y0, y1] at the top.
std::unique_ptr<HeightMap> pin(double x0, double x1, double y0, double y1, float low) {
  auto m = HeightMap::make({40, 60, 40, {}}, 0.1);
  EXPECT_TRUE(m);
  auto map = std::make_unique<HeightMap>(std::move(*m));
  for (std::size_t j = 0; j < map->ny(); ++j) {
    for (std::size_t i = 0; i < map->nx(); ++i) {
      const bool in = map->x(i) >= x0 && map->x(i) <= x1 && map->y(j) >= y0 && map->y(j) <= y1;
      map->at(i, j) = in ? 0.0f : low;
      map->touch(i / HeightMap::kTile, j / HeightMap::kTile);
    }
  }
  return map;
}

TEST(StockReach, AHolderMeetsAPinBeforeTheToolCutsItAway) {
  // A 1 mm pin the 6 mm tool cuts away whole: its holder reached it first.
  auto map = pin(19.5, 20.5, 29.5, 30.5, -25.0f);
  const ToolShape tool = *tool_from_comment("holder:20 stickout:10", 6.0);
  const Cut c = sweep(*map, tool, {5, 30, -15}, {35, 30, -15}, 1);
  EXPECT_NEAR(c.removed_mm3, 1.0 * 1.0 * 15.0, 0.01);
  EXPECT_DOUBLE_EQ(c.holder_hit, 5.0);  // the pin's top at 0, the face at -5
}

TEST(StockReach, TheDeepestContactIsReportedWhereverItIsFound) {
  // Two pins on the holder's way, 2 and 5 mm above its face, in either order
  // (tiles a shallower contact already found cannot beat are passed over).
  for (const bool deep_first : {false, true}) {
    auto map = pin(14.5, 15.5, 29.5, 30.5, -25.0f);
    for (std::size_t j = 0; j < map->ny(); ++j) {
      for (std::size_t i = 0; i < map->nx(); ++i) {
        const double x = map->x(i), y = map->y(j);
        if (std::abs(y - 30.0) > 0.5) continue;
        if (std::abs(x - 15.0) <= 0.5) map->at(i, j) = deep_first ? 0.0f : -3.0f;
        if (std::abs(x - 25.0) <= 0.5) map->at(i, j) = deep_first ? -3.0f : 0.0f;
      }
    }
    const ToolShape tool = *tool_from_comment("holder:20 stickout:10", 6.0);
    EXPECT_DOUBLE_EQ(sweep(*map, tool, {5, 30, -15}, {35, 30, -15}, 1).holder_hit, 5.0)
        << deep_first;
  }
}

TEST(StockReach, AHolderComingDownBehindTheToolMeetsWhatTheToolLeft) {
  // A 2 mm pin under the tool's start; the tool ramps down 45° and leaves
  // it, its holder (1 mm above the tip) still over it, 4 mm lower. The cell
  // at along = -0.95, 0.95 beside the path: the tool left it at
  // -(-0.95 + √(9 - 0.95²)) and the face comes down to -4 + 1.
  auto map = pin(9.0, 11.0, 29.0, 31.0, -30.0f);
  const ToolShape tool = *tool_from_comment("holder:20 stickout:1", 6.0);
  const Cut c = sweep(*map, tool, {10, 30, 0}, {14, 30, -4}, 1);
  EXPECT_NEAR(c.holder_hit, 3.0 + 0.95 - std::sqrt(9.0 - 0.95 * 0.95), 1e-4);
}

TEST(StockPlunge, ANoPlungeToolGoingStraightDownIntoStockIsWarnedAtItsLine) {
  const auto s =
      simulate("T1 M6\nG0 X20 Y20 Z2\nG1 Z-3 F100\nG1 X40\nG0 Z2\nG0 X30\nG1 Z-3\nG0 Z5\nM30\n",
               {60, 40, 10, {}}, tools({"1=flat/6,no-plunge"}));
  // Line 7 goes down into the slot line 4 cut: no stock under its axis.
  expect_one(*s, core::Code::PlungeNotCentreCutting, 3, "standing 3.000 mm above its tip");
  EXPECT_EQ(s->diags.all()[0].severity, core::Severity::Warning);
  EXPECT_TRUE(simulate("T1 M6\nG0 X20 Y20 Z2\nG1 Z-3 F100\nG0 Z5\nM30\n", {60, 40, 10, {}},
                       tools({"1=flat/6"}))
                  ->sim->checks()
                  .empty());
}

TEST(StockPlunge, ARampAngleCanBeGiven) {
  // A 10° ramp: 20 mm along, 20 tan 10° = 3.527 down.
  const char* ramp = "T1 M6\nG0 X10 Y20 Z0\nG1 X30 Z-3.52654 F100\nG0 Z5\nM30\n";
  const auto five = simulate(ramp, {60, 40, 10, {}}, tools({"1=flat/6,no-plunge"}));
  expect_one(*five, core::Code::PlungeNotCentreCutting, 3, "steeper than 5°");
  const auto nine = simulate(ramp, {60, 40, 10, {}}, tools({"1=bull:1/6,no-plunge:9.9"}));
  expect_one(*nine, core::Code::PlungeNotCentreCutting, 3, "steeper than 9.9°");
  const auto eleven = simulate(ramp, {60, 40, 10, {}}, tools({"1=flat/6,no-plunge:10.1"}));
  EXPECT_TRUE(eleven->sim->checks().empty()) << describe(eleven->sim->checks());
}

TEST(StockOperations, EachToolChangeBeginsAnOperation) {
  const auto s = simulate(
      "T1 M6\nG0 X10 Y10 Z1\nG1 Z-1 F100\nG1 X30\nG0 Z5\n"
      "T2 M6\nG0 X10 Y30 Z1\nG1 Z-1\nG1 X30\nG0 Z5\n"
      "T1 M6\nG0 X40 Y10 Z1\nG1 Z-1\nG1 X50\nG0 Z5\nM30\n",
      {60, 40, 10, {}}, tools({"1=flat/6", "2=flat/2"}));
  const auto& ops = s->sim->operations();
  ASSERT_EQ(ops.size(), 3u);
  EXPECT_EQ(ops[0].tool, 1);
  EXPECT_EQ(ops[1].tool, 2);
  EXPECT_EQ(ops[2].tool, 1);
  EXPECT_EQ(ops[0].first_line, 1u);
  EXPECT_EQ(ops[0].last_line, 5u);
  EXPECT_EQ(ops[1].first_line, 6u);
  EXPECT_EQ(ops[1].last_line, 10u);
  EXPECT_EQ(ops[2].first_line, 11u);
  EXPECT_EQ(ops[2].last_line, 15u);
  EXPECT_NEAR(ops[0].removed_mm3, 6.0 * 20.0 + M_PI * 9.0, 0.5);
  EXPECT_NEAR(ops[2].removed_mm3, 6.0 * 10.0 + M_PI * 9.0, 0.5);
  EXPECT_NEAR(ops[0].removed_mm3 + ops[2].removed_mm3, s->sim->tools()[0].removed_mm3, 1e-9);
  EXPECT_NEAR(ops[1].removed_mm3, s->sim->tools()[1].removed_mm3, 1e-9);
}

TEST(StockOperations, MovesBeforeAnyToolChangeAreOneOperation) {
  const auto s = simulate("G0 X10 Y10 Z1\nG1 Z-1 F100\nG1 X30\nG0 Z5\nM30\n", {60, 40, 10, {}},
                          tools({"0=flat/6"}));
  ASSERT_EQ(s->sim->operations().size(), 1u);
  EXPECT_EQ(s->sim->operations()[0].tool, 0);
  EXPECT_EQ(s->sim->operations()[0].first_line, 1u);
  EXPECT_DOUBLE_EQ(s->sim->operations()[0].removed_mm3, s->sim->removed_mm3());
}

}  // namespace
}  // namespace usina::sim::stock
