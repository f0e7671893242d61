// The operations checked against the stock (docs/job.md, "Checks against the
// stock"): each rule inside, on the edge and outside, on a box and on a
// cylinder; through the job (the program not made after an error, made
// after a warning) and the command (warnings on stderr, the file written);
// and the shipped examples, which fit their stock.
#include "job/stock_check.hpp"

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cam/pocket.hpp"
#include "canon/toolpath.hpp"
#include "job/make.hpp"
#include "job_test_util.hpp"
#include "support/files.hpp"
#include "support/usina_process.hpp"

namespace usina::job {
namespace {

using cam::Vec2;
using core::Code;
using testing::find;

// A box 100 x 60 x 10 from X0 Y0, and a cylinder D80 x 20 about X0 Y0.
Stock box() {
  Stock s;
  s.shape = "box";
  s.size = {100, 60, 10};
  return s;
}

Stock cylinder() {
  Stock s;
  s.shape = "cylinder";
  s.size = {80, 20, 0};
  return s;
}

// An operation whose keys are on lines of their own: the header on 10,
// the layer on 12, the depth on 13, center/at on 14.
Operation op_of(OpType type, double depth) {
  Operation op;
  op.type = type;
  op.depth = depth;
  op.layer = "L";
  op.loc.line = 10;
  op.layer_loc.line = 12;
  op.depth_loc.line = 13;
  op.place_loc.line = 14;
  return op;
}

Tool tool_of(ToolType type, double diameter, double pitch = 0) {
  Tool t;
  t.number = 7;
  t.type = type;
  t.diameter = diameter;
  t.pitch = pitch;
  return t;
}

// The one diagnostic of `d`, checked to be of `code` at `line`.
void expect_one(const core::DiagnosticList& d, Code code, std::uint32_t line) {
  ASSERT_EQ(d.all().size(), 1u);
  EXPECT_EQ(d.all()[0].code, code) << d.all()[0].message;
  EXPECT_EQ(d.all()[0].loc.line, line);
  EXPECT_EQ(d.all()[0].severity,
            code_name(code)[0] == 'E' ? core::Severity::Error : core::Severity::Warning);
}

// --- the top face ----------------------------------------------------------

TEST(JobStockTop, ABoxFromItsCorner) {
  Stock s = box();
  s.origin = {-5, -5};
  const StockTop top = stock_top(s);
  EXPECT_DOUBLE_EQ(top.height, 10);
  EXPECT_LT(outside_by(top, {0, 0}), 0);
  EXPECT_DOUBLE_EQ(outside_by(top, {95, 20}), 0);  // on the edge
  EXPECT_DOUBLE_EQ(outside_by(top, {97, 20}), 2);
  EXPECT_DOUBLE_EQ(outside_by(top, {98, 59}), 5);  // beyond a corner: 3, 4, 5
}

TEST(JobStockTop, ACylinderAboutItsCentre) {
  Stock s = cylinder();
  s.origin = {10, 10};
  const StockTop top = stock_top(s);
  EXPECT_DOUBLE_EQ(top.height, 20);
  EXPECT_DOUBLE_EQ(outside_by(top, {50, 10}), 0);
  EXPECT_DOUBLE_EQ(outside_by(top, {10, 55}), 5);
  // Inside the circle's bounding square, outside the circle.
  EXPECT_GT(outside_by(top, {45, 45}), 0);
}

TEST(JobStockTop, ASegmentMeetsTheFaceThoughBothEndsAreOff) {
  const StockTop b = stock_top(box());
  EXPECT_TRUE(segment_meets(b, {-10, 30}, {110, 30}));
  EXPECT_TRUE(segment_meets(b, {-10, 60}, {110, 60}));  // along the edge
  EXPECT_FALSE(segment_meets(b, {-10, 61}, {110, 61}));
  EXPECT_FALSE(segment_meets(b, {-10, 55}, {10, 75}));  // past the corner
  const StockTop c = stock_top(cylinder());
  EXPECT_TRUE(segment_meets(c, {-50, 39}, {50, 39}));
  EXPECT_FALSE(segment_meets(c, {-50, 41}, {50, 41}));
  EXPECT_FALSE(segment_meets(c, {35, 35}, {50, 20}));  // the square's corner, not the circle
}

TEST(JobStockTop, ADrillsPoint) {
  // 118°: 0.3 D (the 6.8 mm drill's 2.04 mm); 90°: half the diameter.
  EXPECT_NEAR(point_length(6.8, kDrillPointAngle), 2.043, 0.001);
  EXPECT_DOUBLE_EQ(point_length(10, kSpotPointAngle), 5);
}

// --- holes -----------------------------------------------------------------

TEST(JobStockCheck, HoleCentresOnTheStockAndOnItsEdge) {
  core::DiagnosticList d;
  EXPECT_TRUE(check_hole_centres(box(), op_of(OpType::Drill, 5), {{10, 10}, {100, 30}}, d));
  EXPECT_TRUE(check_hole_centres(cylinder(), op_of(OpType::Drill, 5), {{0, 40}, {-28, 28}}, d));
  EXPECT_TRUE(d.all().empty());
}

TEST(JobStockCheck, AHoleCentreOffTheStockIsAnErrorAtTheLayer) {
  core::DiagnosticList d;
  EXPECT_FALSE(
      check_hole_centres(box(), op_of(OpType::Tap, 5), {{10, 10}, {100.5, 30}, {50, -2}}, d));
  expect_one(d, Code::JobOutsideStock, 12);
  const std::string& m = d.all()[0].message;
  EXPECT_NE(m.find("2 of the 3 hole centres"), std::string::npos) << m;
  EXPECT_NE(m.find("reaches X50 Y-2, 2 mm outside"), std::string::npos) << m;
  EXPECT_NE(m.find("X0..100 Y0..60"), std::string::npos) << m;
}

TEST(JobStockCheck, AHoleCentreOffACylinderIsAnError) {
  core::DiagnosticList d;
  // Inside the cylinder's bounding square, outside its circle.
  EXPECT_FALSE(check_hole_centres(cylinder(), op_of(OpType::Spot, 1), {{30, 30}}, d));
  expect_one(d, Code::JobOutsideStock, 12);
  EXPECT_NE(d.all()[0].message.find("a circle D80 about X0 Y0"), std::string::npos);
}

TEST(JobStockCheck, AHoleBrokenOutOfTheStocksSideIsAWarning) {
  core::DiagnosticList quiet;
  // D6.8 holes 3.4 mm from the box's edge, and 36.6 from the cylinder's centre.
  check_hole_edges(box(), op_of(OpType::Drill, 5), {{6.8, {{3.4, 30}, {50, 56.6}}}}, quiet);
  check_hole_edges(cylinder(), op_of(OpType::Drill, 5), {{6.8, {{0, 36.6}}}}, quiet);
  EXPECT_TRUE(quiet.all().empty());
  core::DiagnosticList d;
  check_hole_edges(box(), op_of(OpType::Drill, 5), {{5, {{50, 30}, {1, 30}}}, {6.8, {{50, 59}}}},
                   d);
  expect_one(d, Code::JobPartlyOutsideStock, 12);
  EXPECT_NE(d.all()[0].message.find("2 of the holes"), std::string::npos) << d.all()[0].message;
  EXPECT_NE(d.all()[0].message.find("D5 at X1 Y30 by 1.5 mm"), std::string::npos)
      << d.all()[0].message;
  core::DiagnosticList round;
  check_hole_edges(cylinder(), op_of(OpType::Tap, 5), {{6.8, {{0, 37}}}}, round);
  expect_one(round, Code::JobPartlyOutsideStock, 12);
}

TEST(JobStockCheck, ABlindHoleAndAThroughHoleAreQuiet) {
  const Tool d68 = tool_of(ToolType::Drill, 6.8);
  // Full diameter through at 12.043, 13.043 the deepest; at 12 (the plate
  // example's) the hole is D6.66 at the bottom: within the 0.2 mm lip.
  for (const double depth : {8.0, 10.0, 12.0, 12.05, 13.0}) {
    core::DiagnosticList d;
    EXPECT_TRUE(check_hole_depth(box(), op_of(OpType::Drill, depth), d68, d));
    EXPECT_TRUE(d.all().empty()) << depth << ": " << d.all()[0].message;
  }
}

TEST(JobStockCheck, ADrillWhoseTipAloneBreaksThroughIsAWarning) {
  core::DiagnosticList d;
  // 1 mm of a 5 mm drill's 1.5 mm point through: a D3.33 hole at the bottom.
  EXPECT_TRUE(check_hole_depth(box(), op_of(OpType::Drill, 11), tool_of(ToolType::Drill, 5), d));
  expect_one(d, Code::JobHoleNotThrough, 13);
  const std::string& m = d.all()[0].message;
  EXPECT_NE(m.find("D3.329 at the bottom"), std::string::npos) << m;
  EXPECT_NE(m.find("depth 11.502 at least"), std::string::npos) << m;
  // The 6.8 mm drill 1.95 mm through: D6.49 at the bottom, a lip too wide.
  core::DiagnosticList lip;
  EXPECT_TRUE(
      check_hole_depth(box(), op_of(OpType::Drill, 11.95), tool_of(ToolType::Drill, 6.8), lip));
  expect_one(lip, Code::JobHoleNotThrough, 13);
}

TEST(JobStockCheck, ADrillFarBelowTheStockIsAWarning) {
  core::DiagnosticList d;
  // Full diameter through at 12.043, 13.043 the deepest.
  EXPECT_TRUE(
      check_hole_depth(box(), op_of(OpType::Drill, 13.1), tool_of(ToolType::Drill, 6.8), d));
  expect_one(d, Code::JobCutsBelowStock, 13);
  EXPECT_NE(d.all()[0].message.find("13.043 is the deepest"), std::string::npos);
}

TEST(JobStockCheck, ASpotDrillFarBelowTheStockIsAWarning) {
  const Tool spot = tool_of(ToolType::Spot, 10);  // a 5 mm point
  core::DiagnosticList quiet;
  EXPECT_TRUE(check_hole_depth(box(), op_of(OpType::Spot, 16), spot, quiet));
  EXPECT_TRUE(quiet.all().empty());
  core::DiagnosticList d;
  EXPECT_TRUE(check_hole_depth(box(), op_of(OpType::Spot, 16.5), spot, d));
  expect_one(d, Code::JobCutsBelowStock, 13);
}

TEST(JobStockCheck, ATapThroughTheStockByItsLead) {
  const Tool m8 = tool_of(ToolType::Tap, 8, 1.25);  // a lead of 5.5 x 1.25 = 6.875
  for (const double depth : {6.0, 10.0, 16.875}) {
    core::DiagnosticList d;
    EXPECT_TRUE(check_hole_depth(box(), op_of(OpType::Tap, depth), m8, d));
    EXPECT_TRUE(d.all().empty()) << depth;
  }
}

TEST(JobStockCheck, ATapDeeperThanTheStockAndItsLeadIsAnError) {
  core::DiagnosticList d;
  EXPECT_FALSE(
      check_hole_depth(cylinder(), op_of(OpType::Tap, 27), tool_of(ToolType::Tap, 8, 1.25), d));
  expect_one(d, Code::JobDeeperThanStock, 13);
  EXPECT_NE(d.all()[0].message.find("depth 26.875 at most"), std::string::npos)
      << d.all()[0].message;
}

// --- pockets ---------------------------------------------------------------

TEST(JobStockCheck, APocketInsideAndOnTheEdge) {
  core::DiagnosticList d;
  const Operation op = op_of(OpType::Pocket, 4);
  EXPECT_TRUE(check_pocket(box(), op, cam::rectangle({50, 30}, 40, 20, 4), d));
  // Its side on the stock's edge: an open-sided pocket, on the stock.
  EXPECT_TRUE(check_pocket(box(), op, cam::rectangle({80, 30}, 40, 20, 0), d));
  EXPECT_TRUE(check_pocket(cylinder(), op, cam::circle({0, 0}, 40), d));
  EXPECT_TRUE(d.all().empty());
}

TEST(JobStockCheck, APocketPartlyOffTheStockIsAnError) {
  core::DiagnosticList d;
  EXPECT_FALSE(
      check_pocket(box(), op_of(OpType::Pocket, 4), cam::rectangle({80, 30}, 41, 20, 0), d));
  expect_one(d, Code::JobOutsideStock, 12);
  EXPECT_NE(d.all()[0].message.find("0.5 mm outside"), std::string::npos) << d.all()[0].message;
}

TEST(JobStockCheck, APocketWhollyOffTheStockIsAnError) {
  core::DiagnosticList d;
  EXPECT_FALSE(
      check_pocket(box(), op_of(OpType::Pocket, 4), cam::rectangle({200, 30}, 20, 20, 0), d));
  expect_one(d, Code::JobOutsideStock, 12);
}

TEST(JobStockCheck, ASquarePocketWhoseCornersLeaveACylinderIsAnError) {
  core::DiagnosticList d;
  // 60 x 60 about the centre: its corners are 42.4 from it, the circle's 40.
  EXPECT_FALSE(
      check_pocket(cylinder(), op_of(OpType::Pocket, 4), cam::rectangle({0, 0}, 60, 60, 0), d));
  expect_one(d, Code::JobOutsideStock, 12);
}

TEST(JobStockCheck, APocketThroughTheStockIsAWarning) {
  const cam::Path outline = cam::rectangle({50, 30}, 40, 20, 4);
  core::DiagnosticList quiet;
  EXPECT_TRUE(check_pocket(box(), op_of(OpType::Pocket, 9.9), outline, quiet));
  EXPECT_TRUE(quiet.all().empty());
  for (const double depth : {10.0, 12.0}) {
    core::DiagnosticList d;
    EXPECT_TRUE(check_pocket(box(), op_of(OpType::Pocket, depth), outline, d));
    expect_one(d, Code::JobCutsThroughStock, 13);
    EXPECT_NE(d.all()[0].message.find("cuts through the stock"), std::string::npos);
    // 2 mm below the bottom is 1 mm more than a cut-out needs.
    EXPECT_EQ(d.all()[0].message.find("into what is under it") != std::string::npos, depth > 11);
  }
}

// --- ellipse pockets -------------------------------------------------------

Operation ellipse(double cx, double cy, double rx, double ry, double depth) {
  Operation op = op_of(OpType::EllipsePocket, depth);
  op.center = {cx, cy};
  op.rx = rx;
  op.ry = ry;
  return op;
}

TEST(JobStockCheck, AnEllipseOnTheStock) {
  core::DiagnosticList d;
  EXPECT_TRUE(check_ellipse_pocket(box(), ellipse(50, 30, 50, 30, 3), d));  // touches all four
  EXPECT_TRUE(check_ellipse_pocket(cylinder(), ellipse(0, 0, 40, 20, 3), d));
  EXPECT_TRUE(d.all().empty());
}

TEST(JobStockCheck, AnEllipseOffTheStockIsAnErrorAtItsCentre) {
  core::DiagnosticList d;
  EXPECT_FALSE(check_ellipse_pocket(box(), ellipse(50, 30, 30, 30.5, 3), d));
  expect_one(d, Code::JobOutsideStock, 14);
  EXPECT_NE(d.all()[0].message.find("0.5 mm outside"), std::string::npos) << d.all()[0].message;
  core::DiagnosticList round;
  EXPECT_FALSE(check_ellipse_pocket(cylinder(), ellipse(5, 0, 40, 20, 3), round));
  expect_one(round, Code::JobOutsideStock, 14);
}

TEST(JobStockCheck, AnEllipseThroughTheStockIsAWarning) {
  core::DiagnosticList d;
  EXPECT_TRUE(check_ellipse_pocket(cylinder(), ellipse(0, 0, 20, 10, 20), d));
  expect_one(d, Code::JobCutsThroughStock, 13);
}

// --- profiles --------------------------------------------------------------

TEST(JobStockCheck, AProfileOnTheStockIsQuiet) {
  core::DiagnosticList d;
  // The part's outline is the blank's edge: a profile of a blank cut to size.
  EXPECT_TRUE(check_profile(box(), op_of(OpType::Profile, 10.5),
                            {cam::rectangle({50, 30}, 100, 60, 0)}, d));
  EXPECT_TRUE(d.all().empty());
}

TEST(JobStockCheck, AProfilePartlyOffTheStockIsAWarning) {
  core::DiagnosticList d;
  EXPECT_TRUE(check_profile(box(), op_of(OpType::Profile, 5),
                            {cam::rectangle({50, 30}, 40, 20, 0), cam::circle({100, 30}, 10)}, d));
  expect_one(d, Code::JobPartlyOutsideStock, 12);
  const std::string& m = d.all()[0].message;
  EXPECT_NE(m.find("contour 2"), std::string::npos) << m;
  EXPECT_NE(m.find("10 mm outside"), std::string::npos) << m;
  EXPECT_NE(m.find("cuts air"), std::string::npos) << m;
}

TEST(JobStockCheck, AnOpenProfileAcrossTheStockMeetsIt) {
  cam::Path line;
  line.start = {-20, 30};
  line.segs.push_back({{120, 30}, std::nullopt, 0});
  core::DiagnosticList d;
  EXPECT_TRUE(check_profile(box(), op_of(OpType::Profile, 2), {line}, d));
  expect_one(d, Code::JobPartlyOutsideStock, 12);
}

TEST(JobStockCheck, AProfileWhollyOffTheStockIsAnError) {
  core::DiagnosticList d;
  EXPECT_FALSE(
      check_profile(cylinder(), op_of(OpType::Profile, 5), {cam::circle({100, 0}, 10)}, d));
  expect_one(d, Code::JobOutsideStock, 12);
  EXPECT_NE(d.all()[0].message.find("wholly outside"), std::string::npos);
}

TEST(JobStockCheck, AProfileAroundTheWholeStockIsAnError) {
  core::DiagnosticList d;
  EXPECT_FALSE(
      check_profile(box(), op_of(OpType::Profile, 5), {cam::rectangle({50, 30}, 120, 80, 5)}, d));
  expect_one(d, Code::JobOutsideStock, 12);
  EXPECT_NE(d.all()[0].message.find("larger than the blank"), std::string::npos)
      << d.all()[0].message;
}

TEST(JobStockCheck, AProfileBelowTheStockByMoreThanTheBreakthroughIsAWarning) {
  const std::vector<cam::Path> part{cam::circle({0, 0}, 30)};
  core::DiagnosticList quiet;
  EXPECT_TRUE(check_profile(cylinder(), op_of(OpType::Profile, 21), part, quiet));
  EXPECT_TRUE(quiet.all().empty());
  core::DiagnosticList d;
  EXPECT_TRUE(check_profile(cylinder(), op_of(OpType::Profile, 21.5), part, d));
  expect_one(d, Code::JobCutsBelowStock, 13);
  EXPECT_NE(d.all()[0].message.find("1.5 mm below"), std::string::npos) << d.all()[0].message;
}

// --- engraving and facing --------------------------------------------------

TEST(JobStockCheck, AnEngravingOnTheStock) {
  core::DiagnosticList d;
  Operation op = op_of(OpType::Engrave, 0.2);
  EXPECT_TRUE(check_engraving(box(), op, {{{10, 10}, {20, 20}}, {{90, 5}, {100, 60}}}, d));
  EXPECT_TRUE(check_engraving(cylinder(), op, {{{-20, -5}, {20, -5}, {39, 0}}}, d));
  EXPECT_TRUE(d.all().empty());
}

TEST(JobStockCheck, AnEngravingOffTheStockIsAnErrorAtItsPlace) {
  Operation op = op_of(OpType::Engrave, 0.2);
  op.text = "USINA";
  core::DiagnosticList d;
  EXPECT_FALSE(check_engraving(box(), op, {{{10, 10}, {20, 20}}, {{90, 5}, {103, 5}}}, d));
  expect_one(d, Code::JobOutsideStock, 14);
  EXPECT_NE(d.all()[0].message.find("\"USINA\""), std::string::npos);
  EXPECT_NE(d.all()[0].message.find("3 mm outside"), std::string::npos) << d.all()[0].message;
  core::DiagnosticList round;
  EXPECT_FALSE(check_engraving(cylinder(), op, {{{-20, -5}, {20, -5}, {41, 0}}}, round));
  expect_one(round, Code::JobOutsideStock, 14);
}

TEST(JobStockCheck, AnEngravingThroughTheStockIsAWarning) {
  core::DiagnosticList d;
  EXPECT_TRUE(check_engraving(box(), op_of(OpType::Engrave, 10), {{{10, 10}, {20, 20}}}, d));
  expect_one(d, Code::JobCutsThroughStock, 13);
}

TEST(JobStockCheck, AFacingLeavesPartOfTheStock) {
  core::DiagnosticList d;
  EXPECT_TRUE(check_face(box(), op_of(OpType::Face, 9.9), d));
  EXPECT_TRUE(d.all().empty());
  for (const double depth : {10.0, 12.0}) {
    core::DiagnosticList deep;
    EXPECT_FALSE(check_face(box(), op_of(OpType::Face, depth), deep));
    expect_one(deep, Code::JobDeeperThanStock, 13);
  }
  core::DiagnosticList round;
  EXPECT_FALSE(check_face(cylinder(), op_of(OpType::Face, 20), round));
  expect_one(round, Code::JobDeeperThanStock, 13);
}

// --- through the job -------------------------------------------------------

// The plate's drawing (outline 0..120 x 0..80, R8 corners; pocket 15..65 x
// 25..55; D6.8 holes at X10/110 Y10/70, D5 at X95 Y30/50) on `stock`, the
// [stock] lines before its material.
std::string plate_on(const std::string& stock, const std::string& ops) {
  std::string text = testing::job_text(ops);
  const std::string box = "shape = \"box\"\nsize = [130.0, 90.0, 10.0]\n";
  text.replace(text.find(box), box.size(), stock);
  return text;
}

struct Made {
  std::unique_ptr<testing::Loaded> loaded;
  core::DiagnosticList diags;
  bool ok = false;
};

Made make(const std::string& text) {
  Made m;
  m.loaded = testing::load_text(text);
  EXPECT_TRUE(m.loaded->job) << (m.loaded->diags.all().empty() ? m.loaded->io_error
                                                               : m.loaded->diags.all()[0].message);
  if (!m.loaded->job) return m;
  canon::Toolpath tp;
  m.ok = make_job(*m.loaded->job, tp, m.diags);
  return m;
}

// A blind drilling; after [stock]'s shape, size and origin its layer is on
// line 13.
const std::string kDrill =
    "[[operation]]\n"
    "type = \"drill\"\n"
    "layer = \"HOLES\"\n"
    "depth = 8.0\n"
    "tool = \"auto\"\n";

TEST(JobStockCheckMake, HolesOffTheStockStopTheJobAtTheLayersLine) {
  const Made m =
      make(plate_on("shape = \"box\"\nsize = [130.0, 90.0, 10.0]\norigin = [12.0, 0.0]\n", kDrill));
  EXPECT_FALSE(m.ok);
  const core::Diagnostic* d = find(m.diags, Code::JobOutsideStock);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, 13u);
  EXPECT_EQ(d->loc.col, 9u);  // the value: layer = "HOLES"
  EXPECT_NE(d->message.find("2 of the 6 hole centres"), std::string::npos) << d->message;
}

TEST(JobStockCheckMake, TheWholePlateFitsACylinderOfD150) {
  const std::string cyl =
      "shape = \"cylinder\"\ndiameter = 150.0\nheight = 10.0\norigin = [60.0, 40.0]\n";
  const Made m =
      make(plate_on(cyl, kDrill + "[[operation]]\ntype = \"pocket\"\nlayer = \"POCKET\"\n"
                                  "depth = 4.0\ntool = \"auto\"\n"
                                  "[[operation]]\ntype = \"profile\"\nlayer = \"OUTLINE\"\n"
                                  "depth = 10.5\ntool = 1\n"));
  EXPECT_TRUE(m.ok);
  for (const core::Diagnostic& d : m.diags.all())
    EXPECT_EQ(d.code, Code::JobCuttingLimited) << d.message;  // the machine's caps only
}

TEST(JobStockCheckMake, APlateOnACylinderOfD100LeavesItsCornerHoles) {
  const std::string cyl =
      "shape = \"cylinder\"\ndiameter = 100.0\nheight = 10.0\norigin = [60.0, 40.0]\n";
  const Made m = make(plate_on(cyl, kDrill));
  EXPECT_FALSE(m.ok);
  EXPECT_NE(find(m.diags, Code::JobOutsideStock), nullptr);
}

TEST(JobStockCheckMake, AWarningLetsTheJobBeMade) {
  // The plate's outline 20 mm wider than a 100 mm blank: cut in air there.
  const Made m = make(
      plate_on("shape = \"box\"\nsize = [100.0, 90.0, 10.0]\n",
               "[[operation]]\ntype = \"profile\"\nlayer = \"OUTLINE\"\ndepth = 10.5\ntool = 1\n"));
  EXPECT_TRUE(m.ok);
  EXPECT_FALSE(m.diags.has_errors());
  const core::Diagnostic* d = find(m.diags, Code::JobPartlyOutsideStock);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->severity, core::Severity::Warning);
  EXPECT_EQ(d->loc.line, 12u);
}

TEST(JobStockCheckMake, AnEngravingOffTheStockIsCheckedOnItsLetters) {
  const Made m = make(testing::job_text(
      "[[operation]]\ntype = \"engrave\"\ntext = \"USINA\"\nat = [100.0, 10.0]\nheight = 10.0\n"
      "depth = 0.2\nrpm = 9000\nfeed = 300\ntool = 11\n"));
  EXPECT_FALSE(m.ok);
  const core::Diagnostic* d = find(m.diags, Code::JobOutsideStock);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, 13u);  // at = [...]
}

TEST(JobStockCheckMake, AFacingThroughTheStockIsAnErrorAtItsDepth) {
  const Made m =
      make(testing::job_text("[[operation]]\ntype = \"face\"\ndepth = 10.0\ntool = \"auto\"\n"));
  EXPECT_FALSE(m.ok);
  const core::Diagnostic* d = find(m.diags, Code::JobDeeperThanStock);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->loc.line, 12u);
}

TEST(JobStockCheckMake, TheExamplesFitTheirStock) {
  for (const char* example : {"plate.toml", "ellipse_cover.toml", "nameplate.toml"}) {
    SCOPED_TRACE(example);
    core::SourceManager sources;
    core::DiagnosticList diags;
    std::string io_error;
    const auto l =
        load_job(testing::repo(std::string("examples/jobs/") + example), sources, diags, io_error);
    ASSERT_TRUE(l) << io_error;
    canon::Toolpath tp;
    EXPECT_TRUE(make_job(*l, tp, diags));
    for (const core::Diagnostic& d : diags.all()) {
      EXPECT_EQ(d.code, Code::JobCuttingLimited) << d.message;  // no stock error, no warning
    }
  }
}

// --- the command -----------------------------------------------------------

TEST(JobStockCheckCli, AWarningGoesToStandardErrorAndTheProgramIsWritten) {
  const test::TempDir dir;
  const std::string job = dir.write(
      "cutout.toml", testing::job_text("[[operation]]\ntype = \"pocket\"\nlayer = \"POCKET\"\n"
                                       "depth = 10.0\ntool = \"auto\"\n"));
  const std::string out = dir.path("part.nc");
  const test::Run r =
      test::usina("job " + test::quote(job) + " --post rs274ngc -o " + test::quote(out));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("cutout.toml:13:9: warning"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("W_JOB_CUTS_THROUGH_STOCK"), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(JobStockCheckCli, AnErrorWritesNoProgram) {
  const test::TempDir dir;
  const std::string job =
      dir.write("off.toml", testing::job_text("[[operation]]\ntype = \"ellipse_pocket\"\n"
                                              "center = [125.0, 40.0]\nrx = 20.0\nry = 10.0\n"
                                              "depth = 2.0\ntool = 3\n"));
  const std::string out = dir.path("part.nc");
  const test::Run r =
      test::usina("job " + test::quote(job) + " --post fanuc -o " + test::quote(out));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("off.toml:12:10: error"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("E_JOB_OUTSIDE_STOCK"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace usina::job
