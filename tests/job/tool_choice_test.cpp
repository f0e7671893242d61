// The tool library and the job's choice of a tool: the largest end mill the
// inside corners allow, a drill by diameter, and why none fits.
#include <cmath>

#include <gtest/gtest.h>

#include "cam/pocket.hpp"
#include "job/geometry.hpp"
#include "job/tools.hpp"
#include "job_test_util.hpp"
#include "support/files.hpp"

namespace usina::job {
namespace {

std::vector<Tool> shop() {
  core::DiagnosticList d;
  auto tools = read_tool_library(test::slurp(testing::repo("examples/tools/shop.toml")), 0, d);
  EXPECT_TRUE(tools) << (d.all().empty() ? "" : d.all()[0].message);
  return tools.value_or(std::vector<Tool>{});
}

TEST(ToolChoice, TheShopLibraryReads) {
  const auto tools = shop();
  ASSERT_EQ(tools.size(), 14u);
  const Tool* t = find_tool(tools, 5);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->type, ToolType::Drill);
  EXPECT_DOUBLE_EQ(t->diameter, 6.8);
  EXPECT_EQ(t->material, ToolMaterial::Hss);
}

TEST(ToolChoice, TheLargestEndMillWithinTheCornerRadius) {
  const auto tools = shop();
  // R4 corners: the D10 (radius 5) is refused, the D6 taken.
  EXPECT_EQ(largest_end_mill(tools, 4.0, 3.0).tool->number, 2);
  // R5 corners take the D10 (its radius equals the corner's).
  EXPECT_EQ(largest_end_mill(tools, 5.0, 3.0).tool->number, 1);
  // Deeper than the D6's 16 mm of flute: the D10 cuts 22 but is too big.
  const ToolChoice c = largest_end_mill(tools, 4.0, 18.0);
  EXPECT_EQ(c.tool, nullptr);
  EXPECT_NE(c.why.find("T1"), std::string::npos) << c.why;
}

TEST(ToolChoice, NoEndMillFitsASharpCorner) {
  const ToolChoice c = largest_end_mill(shop(), 0.0, 3.0);
  EXPECT_EQ(c.tool, nullptr);
  EXPECT_NE(c.why.find("no flat end mill fits"), std::string::npos) << c.why;
}

TEST(ToolChoice, ADrillByDiameter) {
  const auto tools = shop();
  EXPECT_EQ(drill_of(tools, 6.8, 12).tool->number, 5);
  EXPECT_EQ(drill_of(tools, 5.0, 12).tool->number, 6);
  const ToolChoice none = drill_of(tools, 6.6, 12);
  EXPECT_EQ(none.tool, nullptr);
  EXPECT_NE(none.why.find("no 6.6 mm drill"), std::string::npos) << none.why;
  const ToolChoice shallow = drill_of(tools, 5.0, 60);  // 52 mm of flute
  EXPECT_EQ(shallow.tool, nullptr);
  EXPECT_NE(shallow.why.find("52"), std::string::npos) << shallow.why;
}

TEST(ToolChoice, ALibraryErrorIsAtItsLine) {
  core::DiagnosticList d;
  const auto tools = read_tool_library(
      "[[tool]]\nnumber = 1\ntype = \"flat\"\ndiameter = 6.0\ncutting_length = 10.0\n"
      "material = \"carbide\"\n"
      "[[tool]]\nnumber = 2\ntype = \"laser\"\ndiameter = 6.0\ncutting_length = 10.0\n"
      "material = \"carbide\"\n",
      0, d);
  EXPECT_FALSE(tools);
  ASSERT_EQ(d.error_count(), 1);
  EXPECT_EQ(d.all()[0].code, core::Code::BadToolLibrary);
  EXPECT_EQ(d.all()[0].loc.line, 9u);
}

TEST(ToolChoice, ANumberTwiceIsAnError) {
  core::DiagnosticList d;
  const std::string one =
      "[[tool]]\nnumber = 1\ntype = \"flat\"\ndiameter = 6.0\ncutting_length = 10.0\n"
      "material = \"carbide\"\n";
  EXPECT_FALSE(read_tool_library(one + one, 0, d));
  EXPECT_EQ(d.all().at(0).code, core::Code::BadToolLibrary);
}

TEST(ToolChoice, CornerRadiusOfARoundedRectangle) {
  const cam::Path p = cam::rectangle({0, 0}, 50, 30, 4);
  EXPECT_NEAR(smallest_inside_radius(p, true), 4.0, 1e-9);
  // Cut outside, its convex corners hold nothing back.
  EXPECT_TRUE(std::isinf(smallest_inside_radius(p, false)));
  // Walked the other way, the same.
  EXPECT_NEAR(smallest_inside_radius(cam::reversed(p), true), 4.0, 1e-9);
}

TEST(ToolChoice, ASharpInsideCornerIsRadiusZero) {
  EXPECT_EQ(smallest_inside_radius(cam::rectangle({0, 0}, 50, 30, 0), true), 0.0);
}

// An L-shaped island, counter-clockwise: five outer corners the tool goes
// round, and its re-entrant corner at (10, 10), sharp or rounded with
// `fillet` (an arc bending round the tool, which sits outside the island).
cam::Path l_island(double fillet) {
  cam::Path p;
  p.start = {0, 0};
  p.closed = true;
  p.segs = {{{20, 0}, std::nullopt, 0}, {{20, 10}, std::nullopt, 0}};
  if (fillet > 0) {
    p.segs.push_back({{10 + fillet, 10}, std::nullopt, 0});
    p.segs.push_back({{10, 10 + fillet}, cam::Vec2{10 + fillet, 10 + fillet}, -1});
  } else {
    p.segs.push_back({{10, 10}, std::nullopt, 0});
  }
  p.segs.push_back({{10, 20}, std::nullopt, 0});
  p.segs.push_back({{0, 20}, std::nullopt, 0});
  p.segs.push_back({{0, 0}, std::nullopt, 0});
  return p;
}

TEST(ToolChoice, AnIslandsReentrantCornerBoundsThePocketsToolItsOuterCornersDoNot) {
  cam::PocketShape shape;
  shape.outline = cam::rectangle({0, 0}, 100, 80, 8);
  EXPECT_NEAR(pocket_corner(shape), 8.0, 1e-9);
  // A rectangular island: the tool goes round its sharp corners.
  shape.islands.push_back(cam::rectangle({20, 0}, 20, 10, 0));
  EXPECT_NEAR(pocket_corner(shape), 8.0, 1e-9);
  // An L-shaped island's inner corner, rounded to 3 mm, bounds the tool,
  // walked either way.
  shape.islands.push_back(l_island(3));
  EXPECT_NEAR(pocket_corner(shape), 3.0, 1e-9);
  EXPECT_NEAR(smallest_inside_radius(cam::reversed(l_island(3)), false), 3.0, 1e-9);
  // Sharp, no round tool reaches into it.
  shape.islands.push_back(l_island(0));
  EXPECT_EQ(pocket_corner(shape), 0.0);
}

TEST(ToolChoice, TheEllipsesTightestCurve) {
  EXPECT_DOUBLE_EQ(ellipse_smallest_radius(30, 15), 7.5);
  EXPECT_DOUBLE_EQ(ellipse_smallest_radius(15, 30), 7.5);
}

TEST(ToolChoice, HolesGroupedByDiameter) {
  core::DiagnosticList d;
  std::vector<cam::Path> paths{cam::circle({0, 0}, 3.4), cam::circle({10, 0}, 2.5),
                               cam::circle({20, 0}, 3.4), cam::rectangle({0, 0}, 5, 5, 0)};
  std::size_t others = 0;
  const auto groups = holes_of(paths, others);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_NEAR(groups[0].diameter, 5.0, 1e-9);
  EXPECT_NEAR(groups[1].diameter, 6.8, 1e-9);
  EXPECT_EQ(groups[1].centers.size(), 2u);
  EXPECT_EQ(others, 1u);
}

TEST(ToolChoice, AFaceMillForFacingElseTheLargestEndMill) {
  auto tools = shop();
  const ToolChoice c = face_mill(tools, 0.5);
  ASSERT_NE(c.tool, nullptr);
  EXPECT_EQ(c.tool->number, 10);  // the D50 face mill
  // Deeper a pass than its 6 mm: the D10 end mill (22 mm of flute).
  const ToolChoice deep = face_mill(tools, 8);
  ASSERT_NE(deep.tool, nullptr);
  EXPECT_EQ(deep.tool->number, 1);
  EXPECT_NE(deep.why.find("no face mill"), std::string::npos) << deep.why;
  EXPECT_EQ(face_mill(tools, 30).tool, nullptr);
}

TEST(ToolChoice, TheSmallestEngraverThatReaches) {
  auto tools = shop();
  Tool fine = *find_tool(tools, 11);
  fine.number = 13;
  fine.diameter = 2;
  tools.push_back(fine);
  EXPECT_EQ(engraver(tools, 0.2).tool->number, 13);
  const ToolChoice none = engraver(tools, 3);  // 2 mm of flute
  EXPECT_EQ(none.tool, nullptr);
  EXPECT_NE(none.why.find("no engraver"), std::string::npos) << none.why;
}

TEST(ToolChoice, ASpotDrillAtLeastAsWideAsTheHole) {
  const auto tools = shop();
  EXPECT_EQ(spot_drill(tools, 6.8, 2).tool->number, 8);  // D10
  EXPECT_EQ(spot_drill(tools, 10, 2).tool->number, 8);
  const ToolChoice wide = spot_drill(tools, 12, 2);
  EXPECT_EQ(wide.tool, nullptr);
  EXPECT_NE(wide.why.find("D12"), std::string::npos) << wide.why;
  EXPECT_EQ(spot_drill(tools, 5, 6).tool, nullptr);  // 5 mm of cutting length
}

TEST(ToolChoice, TheTapWhoseTapDrillTheHolesAre) {
  const auto tools = shop();
  const ToolChoice m8 = tap_for(tools, 6.8, 12);  // M8 x 1.25: 8 - 1.25 = 6.75
  ASSERT_NE(m8.tool, nullptr);
  EXPECT_EQ(m8.tool->number, 9);
  EXPECT_NE(m8.why.find("M8 x 1.25"), std::string::npos) << m8.why;
  EXPECT_EQ(tap_for(tools, 5.0, 12).tool, nullptr);
  const ToolChoice deep = tap_for(tools, 6.8, 25);  // 20 mm of thread
  EXPECT_EQ(deep.tool, nullptr);
  EXPECT_NE(deep.why.find("20"), std::string::npos) << deep.why;
}

TEST(ToolChoice, OnlyATapHasAPitch) {
  core::DiagnosticList d;
  const auto tools = read_tool_library(
      "[[tool]]\nnumber = 1\ntype = \"drill\"\ndiameter = 6.8\ncutting_length = 60.0\n"
      "pitch = 1.25\nmaterial = \"hss\"\n",
      0, d);
  EXPECT_FALSE(tools);
  ASSERT_EQ(d.error_count(), 1);
  EXPECT_EQ(d.all()[0].loc.line, 6u);
  EXPECT_NE(d.all()[0].message.find("only a tap"), std::string::npos);
}

}  // namespace
}  // namespace usina::job
