// The SVG writer: the y flip, the arc flags after it, the viewBox, layers
// as groups, dashed rapids, circles.
#include "draw/svg_writer.hpp"

#include <unistd.h>

#include <fstream>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>

#include "draw/layer_style.hpp"

namespace usina::draw {
namespace {

constexpr double kPi = std::numbers::pi;

std::string svg(const Drawing& d) {
  std::ostringstream out;
  EXPECT_TRUE(write_svg(d, out));
  return out.str();
}

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

TEST(SvgNumber, FourDecimalsAtMostNoTrailingZerosNoMinusZero) {
  EXPECT_EQ(svg_number(12.0), "12");
  EXPECT_EQ(svg_number(-0.5), "-0.5");
  EXPECT_EQ(svg_number(1.23456), "1.2346");
  EXPECT_EQ(svg_number(-0.00001), "0");
  EXPECT_EQ(svg_number(100.10), "100.1");
}

TEST(SvgWriter, YIsWrittenNegated) {
  Drawing d;
  d.add_line(d.layer(kContourLayer), {1, 2}, {3, 4});
  EXPECT_TRUE(contains(svg(d), R"(<line x1="1" y1="-2" x2="3" y2="-4"/>)")) << svg(d);
}

TEST(SvgWriter, CounterClockwiseQuarterArcHasSweepZeroSmallArc) {
  Drawing d;
  // From (10, 0) to (0, 10) about the origin, counter-clockwise (y up): on
  // the flipped screen still counter-clockwise, SVG's negative direction.
  d.add_arc(d.layer(kContourLayer), {{0, 0}, 10, 0, kPi / 2, true});
  EXPECT_TRUE(contains(svg(d), R"(<path d="M10 0A10 10 0 0 0 0 -10"/>)")) << svg(d);
}

TEST(SvgWriter, ClockwiseThreeQuarterArcHasSweepOneLargeArc) {
  Drawing d;
  // From (10, 0) clockwise to (0, 10): 270° through the bottom.
  d.add_arc(d.layer(kContourLayer), {{0, 0}, 10, 0, kPi / 2, false});
  EXPECT_TRUE(contains(svg(d), R"(<path d="M10 0A10 10 0 1 1 0 -10"/>)")) << svg(d);
}

TEST(SvgWriter, CounterClockwiseLongArcAndClockwiseShortArc) {
  Drawing d;
  d.add_arc(d.layer(kContourLayer), {{0, 0}, 10, kPi / 2, 0, true});   // 270°
  d.add_arc(d.layer(kContourLayer), {{0, 0}, 10, kPi / 2, 0, false});  // 90°
  const std::string s = svg(d);
  EXPECT_TRUE(contains(s, R"(<path d="M0 -10A10 10 0 1 0 10 0"/>)")) << s;
  EXPECT_TRUE(contains(s, R"(<path d="M0 -10A10 10 0 0 1 10 0"/>)")) << s;
}

TEST(SvgWriter, ViewBoxFitsTheDrawingWithAMarginAndSizeIsInMillimetres) {
  Drawing d;
  d.add_line(d.layer(kContourLayer), {0, 0}, {200, 50});
  // Bounds (0,0)-(200,50), margin 10: x from -10, top edge at y = -60 after the flip.
  EXPECT_TRUE(contains(svg(d), R"(width="220mm" height="70mm" viewBox="-10 -60 220 70")"))
      << svg(d);
}

TEST(SvgWriter, EmptyDrawingIsTheTenMillimetreSquareAboutTheOrigin) {
  const std::string s = svg(Drawing{});
  EXPECT_TRUE(contains(s, R"(width="10mm" height="10mm" viewBox="-5 -5 10 10")")) << s;
  EXPECT_TRUE(s.ends_with("</svg>\n"));
}

TEST(SvgWriter, OneGroupPerLayerWithItsIdRapidsDashedHolesAsCircles) {
  Drawing d;
  d.add_line(d.layer(kRapidLayer), {0, 0}, {10, 0});
  d.add_circle(d.layer(kHolesLayer), {{5, 5}, 2});
  d.layer(kContourLayer);
  const std::string s = svg(d);
  EXPECT_TRUE(contains(s, R"(<g id="CONTOUR" )")) << s;
  const auto rapid = s.find(R"(<g id="RAPID" )");
  ASSERT_NE(rapid, std::string::npos);
  EXPECT_NE(s.find("stroke-dasharray", rapid), std::string::npos);
  EXPECT_LT(s.find(R"(<g id="CONTOUR" )"), rapid);
  EXPECT_TRUE(contains(s, R"(<circle cx="5" cy="-5" r="2"/>)")) << s;
  EXPECT_FALSE(contains(s.substr(0, rapid), "stroke-dasharray"));
}

TEST(SvgWriter, PolylinePointsAreFlippedToo) {
  Drawing d;
  d.add_polyline(d.layer(kContourLayer), {{0, 0}, {1, 1}, {2, 0}});
  EXPECT_TRUE(contains(svg(d), R"(<polyline points="0,0 1,-1 2,0"/>)")) << svg(d);
}

TEST(SvgWriter, UnwritablePathIsAnError) {
  const auto r = write_svg_file(Drawing{}, "/nonexistent/usina/x.svg");
  ASSERT_FALSE(r);
  EXPECT_FALSE(r.error().empty());
}

TEST(SvgWriter, WritesTheFile) {
  char name[] = "/tmp/usina_svg_test_XXXXXX";
  const int fd = mkstemp(name);
  ASSERT_GE(fd, 0);
  close(fd);
  Drawing d;
  d.add_line(d.layer(kContourLayer), {0, 0}, {1, 0});
  ASSERT_TRUE(write_svg_file(d, name));
  std::ifstream in(name);
  std::stringstream got;
  got << in.rdbuf();
  EXPECT_EQ(got.str(), svg(d));
  unlink(name);
}

}  // namespace
}  // namespace usina::draw
