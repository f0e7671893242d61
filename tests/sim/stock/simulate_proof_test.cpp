// The proofs of issue 17: programs run by the interpreter and simulated,
// their volumes against the analytic ones within 0.1 % on a 0.05 mm grid
// (a slot with a flat end mill, a ball-nose groove, a drilled hole with its
// point by G81, a circular pocket by helix), the chord error of arcs bounded,
// and the checks found at their lines.
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "sim/stock/simulator.hpp"
#include "support/dialect_run.hpp"

namespace usina::sim::stock {
namespace {

constexpr double kPi = M_PI;

struct Simulated {
  std::unique_ptr<HeightMap> map;
  std::unique_ptr<StockSimulator> sim;
  core::DiagnosticList diags;
  bool program_ok = false;
};

std::unique_ptr<Simulated> simulate(const std::string& program, const StockBox& box,
                                    double resolution, SimulateOptions options = {}) {
  auto s = std::make_unique<Simulated>();
  auto made = HeightMap::make(box, resolution);
  EXPECT_TRUE(made) << made.error();
  s->map = std::make_unique<HeightMap>(std::move(*made));
  const auto run = gcode::dialect_test::run_in("rs274ngc", program);
  s->program_ok = run->ok;
  s->sim = std::make_unique<StockSimulator>(*s->map, std::move(options), s->diags);
  for (const canon::Op& op : run->path.ops())
    s->sim->on(op);
  return s;
}

SimulateOptions with_tool(int n, const char* shape, double diameter) {
  SimulateOptions o;
  o.tools[n] = *parse_shape(shape, diameter);
  return o;
}

void expect_within(double got, double want, double fraction) {
  testing::Test::RecordProperty("relative_error", std::to_string((got - want) / want));
  EXPECT_NEAR(got, want, std::abs(want) * fraction) << "relative error " << (got - want) / want;
}

TEST(StockProof, SlotWithAFlatEndMill) {
  // A 6 mm end mill 5 deep along 50 mm: a stadium of 6 x 50 + pi 3² mm².
  const auto s = simulate("T1 M6\nG0 X20 Y30.013 Z5\nG1 Z-5 F100\nG1 X70\nG0 Z5\nM30\n",
                          {100, 60, 20, {}}, 0.05, with_tool(1, "flat", 6.0));
  const double want = (6.0 * 50.0 + kPi * 9.0) * 5.0;
  expect_within(s->sim->removed_mm3(), want, 0.001);
  expect_within(s->map->removed(), want, 0.001);
  ASSERT_EQ(s->sim->tools().size(), 1u);
  EXPECT_EQ(s->sim->tools()[0].tool, 1);
  EXPECT_DOUBLE_EQ(s->sim->tools()[0].removed_mm3, s->sim->removed_mm3());
  EXPECT_TRUE(s->sim->checks().empty());
}

TEST(StockProof, BallNoseGroove) {
  // A 10 mm ball sunk to its centre along 40 mm: half a cylinder and two
  // quarter spheres: pi R²/2 x L + 2/3 pi R³.
  const auto s = simulate("T2 M6\nG0 X20.01 Y30.02 Z2\nG1 Z-5 F100\nG1 X60.01\nG0 Z5\nM30\n",
                          {100, 60, 20, {}}, 0.05, with_tool(2, "ball", 10.0));
  const double want = kPi * 25.0 / 2.0 * 40.0 + 2.0 / 3.0 * kPi * 125.0;
  expect_within(s->sim->removed_mm3(), want, 0.001);
}

TEST(StockProof, DrilledHoleWithItsPointByG81) {
  // A 10 mm drill, 118°, tip at Z-12: a cylinder down to the point's top
  // and a cone of height R / tan 59°.
  const auto s = simulate("T3 M6\nG0 X30.01 Y30.02 Z5\nG81 X30.01 Y30.02 Z-12 R2 F100\nG80\nM30\n",
                          {60, 60, 30, {}}, 0.05, with_tool(3, "drill", 10.0));
  const double cone = 5.0 / std::tan(59.0 * kPi / 180.0);
  const double want = kPi * 25.0 * (12.0 - cone) + kPi * 25.0 * cone / 3.0;
  expect_within(s->sim->removed_mm3(), want, 0.001);
  EXPECT_TRUE(s->sim->checks().empty());  // the cycle's rapids stay above the stock
}

TEST(StockProof, CircularPocketByHelix) {
  // A 10 mm end mill on a 4 mm helix, 5 turns down 5 mm, then a full circle
  // at the bottom: a cylinder of radius 4 + 5, 5 deep (no island: 4 < 5).
  const auto s = simulate(
      "T4 M6\nG0 X54 Y30 Z1\nG1 Z0 F100\nG3 X54 Y30 I-4 J0 Z-5 P5\nG3 X54 Y30 I-4 J0\nG0 Z5\nM30\n",
      {100, 60, 20, {}}, 0.05, with_tool(4, "flat", 10.0));
  expect_within(s->sim->removed_mm3(), kPi * 81.0 * 5.0, 0.001);
}

TEST(StockProof, ArcChordsMissAtMostTheirBoundedVolume) {
  // The same full circle cut with the simulator's chords and against the
  // analytic ring: the chords (sagitta t = cell/1000) change the swept
  // area by at most 2 t per mm of path on each wall, far inside the grid's error.
  const std::string program = "T1 M6\nG0 X70 Y30 Z1\nG1 Z-2 F100\nG3 X70 Y30 I-20 J0\nG0 Z5\nM30\n";
  const auto s = simulate(program, {100, 60, 10, {}}, 0.05, with_tool(1, "flat", 6.0));
  const double want = kPi * (23.0 * 23.0 - 17.0 * 17.0) * 2.0;
  const double tol = s->sim->chord_tolerance();
  EXPECT_DOUBLE_EQ(tol, 0.05 / 1000.0);
  const double chord_bound = 2.0 * tol * 2.0 * kPi * 23.0 * 2.0;  // outer wall, the worst
  EXPECT_LT(chord_bound / want, 1e-4);  // a tenth of the 0.1 % the grid is held to
  expect_within(s->sim->removed_mm3(), want, 0.001);
}

TEST(StockProof, ARapidIntoTheStockIsFoundAtItsLine) {
  const auto s = simulate("T1 M6\nG0 X-10 Y20 Z5\nG0 Z-2\nG0 X30\nG0 Z5\nM30\n", {60, 40, 10, {}},
                          0.1, with_tool(1, "flat", 6.0));
  ASSERT_EQ(s->sim->checks().size(), 1u);
  EXPECT_EQ(s->sim->checks()[0].code, core::Code::RapidCutsStock);
  EXPECT_EQ(s->sim->checks()[0].loc.line, 4u);
  ASSERT_FALSE(s->diags.all().empty());
  EXPECT_EQ(s->diags.all()[0].severity, core::Severity::Error);
  EXPECT_GT(s->sim->rapid_removed_mm3(), 0.0);
  EXPECT_DOUBLE_EQ(s->sim->rapid_removed_mm3(), s->sim->removed_mm3());
}

TEST(StockProof, ARapidThatGrazesWithinTheToleranceIsNotACheck) {
  const auto s = simulate("T1 M6\nG0 X-10 Y20 Z-0.005\nG0 X30\nG0 Z5\nM30\n", {60, 40, 10, {}}, 0.1,
                          with_tool(1, "flat", 6.0));
  EXPECT_TRUE(s->sim->checks().empty());
}

TEST(StockProof, ACutBelowTheFloorIsFoundAtItsLine) {
  SimulateOptions o = with_tool(1, "flat", 6.0);
  o.floor = -8.0;
  const auto s =
      simulate("T1 M6\nG0 X20 Y20 Z5\nG1 Z-5 F100\nG1 Z-9\nG0 Z5\nM30\n", {60, 40, 10, {}}, 0.1, o);
  ASSERT_EQ(s->sim->checks().size(), 1u);
  EXPECT_EQ(s->sim->checks()[0].code, core::Code::CutBelowFloor);
  EXPECT_EQ(s->sim->checks()[0].loc.line, 4u);
  EXPECT_NE(s->sim->checks()[0].message.find("Z-9.0000"), std::string::npos)
      << s->sim->checks()[0].message;
}

TEST(StockProof, VolumeIsSummedPerTool) {
  SimulateOptions o = with_tool(1, "flat", 6.0);
  o.tools[2] = *parse_shape("flat", 2.0);
  const auto s = simulate(
      "T1 M6\nG0 X10 Y10 Z1\nG1 Z-1 F100\nG1 X30\nG0 Z5\nT2 M6\nG0 X10 Y30 Z1\nG1 Z-1\nG1 "
      "X30\nG0 Z5\nM30\n",
      {60, 40, 10, {}}, 0.05, o);
  ASSERT_EQ(s->sim->tools().size(), 2u);
  expect_within(s->sim->tools()[0].removed_mm3, 6.0 * 20.0 + kPi * 9.0, 0.002);
  expect_within(s->sim->tools()[1].removed_mm3, 2.0 * 20.0 + kPi * 1.0, 0.005);
  EXPECT_NEAR(s->sim->removed_mm3(),
              s->sim->tools()[0].removed_mm3 + s->sim->tools()[1].removed_mm3, 1e-9);
}

TEST(StockProof, AToolWithoutADiameterIsTheDefaultAndSaysSo) {
  const auto s = simulate("T7 M6\nG0 X10 Y10 Z1\nG1 Z-1 F100\nG0 Z5\nM30\n", {60, 40, 10, {}}, 0.1);
  ASSERT_EQ(s->sim->checks().size(), 1u);
  EXPECT_EQ(s->sim->checks()[0].code, core::Code::SimToolDefaulted);
  EXPECT_EQ(s->sim->checks()[0].loc.line, 1u);
  EXPECT_DOUBLE_EQ(s->sim->tools()[0].shape.diameter, 6.0);
}

TEST(StockProof, TheFirstMoveCutsOnlyWhereItEnds) {
  // 5 mm of stock above Z0: the stream's conventional start 0,0,0 is inside
  // it, but the machine was elsewhere; the first rapid is not a cut.
  const auto s = simulate("T1 M6\nG0 X20 Y20 Z10\nG1 Z2 F100\nG0 Z10\nM30\n",
                          {60, 40, 10, {0, 0, 5}}, 0.1, with_tool(1, "flat", 6.0));
  EXPECT_TRUE(s->sim->checks().empty());
  expect_within(s->sim->removed_mm3(), M_PI * 9.0 * 3.0, 0.002);
  // A first move that ends in the stock is a rapid into it.
  const auto in = simulate("T1 M6\nG0 X20 Y20 Z2\nG0 Z10\nM30\n", {60, 40, 10, {0, 0, 5}}, 0.1,
                           with_tool(1, "flat", 6.0));
  ASSERT_EQ(in->sim->checks().size(), 1u);
  EXPECT_EQ(in->sim->checks()[0].loc.line, 2u);
}

TEST(StockProof, ARotaryMoveCutsNothingAndSaysSoOnce) {
  auto map = HeightMap::make({60, 40, 10, {}}, 0.5);
  ASSERT_TRUE(map);
  core::DiagnosticList diags;
  StockSimulator sim(*map, with_tool(1, "flat", 6.0), diags);
  const auto at = [](canon::OpKind k, std::uint32_t line) {
    return canon::Op{std::move(k), core::SourceLoc{0, line, 1, 1, 0}};
  };
  sim.on(at(canon::ToolChange{1, 6.0}, 1));
  sim.on(at(canon::Traverse{{10, 10, 5}, {}}, 2));
  sim.on(at(canon::Feed{{10, 10, -2}, 100.0, {90, 0, 0}, {}}, 3));
  sim.on(at(canon::Feed{{30, 10, -2}, 100.0, {180, 0, 0}, {}}, 4));
  EXPECT_DOUBLE_EQ(sim.removed_mm3(), 0.0);
  ASSERT_EQ(sim.checks().size(), 1u);
  EXPECT_EQ(sim.checks()[0].code, core::Code::SimMotionNotModeled);
  EXPECT_EQ(sim.checks()[0].loc.line, 3u);
}

}  // namespace
}  // namespace usina::sim::stock
