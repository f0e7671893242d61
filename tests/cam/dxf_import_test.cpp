#include "cam/dxf_import.hpp"

#include <cmath>
#include <sstream>

#include <gtest/gtest.h>

#include "core/spline.hpp"

namespace usina::cam {
namespace {

std::string fixture(const char* name) {
  return std::string(USINA_TEST_DIR) + "/programs/dxf/" + name;
}

int count(const core::DiagnosticList& d, core::Code code) {
  int n = 0;
  for (const auto& x : d.all())
    n += x.code == code ? 1 : 0;
  return n;
}

TEST(DxfImport, LinesInDrawingOrderOnTheChosenLayer) {
  core::DiagnosticList d;
  DxfOptions o;
  o.layer = "cut";  // layer names are case-insensitive
  const auto paths = read_dxf(fixture("square_lines.dxf"), o, d);
  ASSERT_TRUE(paths) << (d.all().empty() ? "" : d.all()[0].message);
  ASSERT_EQ(paths->size(), 4u);  // the NOTES line left out
  EXPECT_EQ((*paths)[0].start, (Vec2{0, 0}));
  EXPECT_EQ((*paths)[1].start, (Vec2{20, 10.004}));
  EXPECT_EQ((*paths)[3].segs[0].to, (Vec2{0, 10}));
  EXPECT_TRUE(d.all().empty());
}

TEST(DxfImport, EveryLayerWithoutAFilter) {
  core::DiagnosticList d;
  const auto paths = read_dxf(fixture("square_lines.dxf"), {}, d);
  ASSERT_TRUE(paths);
  EXPECT_EQ(paths->size(), 5u);
}

TEST(DxfImport, LwpolylineBulgesArcsCircleAndOldPolyline) {
  core::DiagnosticList d;
  const auto paths = read_dxf(fixture("arcs_bulges.dxf"), {}, d);
  ASSERT_TRUE(paths);
  ASSERT_EQ(paths->size(), 4u);
  const Path& slot = (*paths)[0];
  EXPECT_TRUE(slot.closed);
  ASSERT_EQ(slot.segs.size(), 4u);
  ASSERT_TRUE(slot.segs[1].center);
  EXPECT_NEAR(slot.segs[1].center->x, 20, 1e-12);
  EXPECT_NEAR(slot.segs[1].center->y, 5, 1e-12);
  EXPECT_EQ(slot.segs[1].turn, 1);
  EXPECT_EQ(slot.segs[3].to, (Vec2{0, 0}));  // the closing segment, with its bulge
  ASSERT_TRUE(slot.segs[3].center);
  EXPECT_NEAR(slot.segs[3].center->y, 5, 1e-12);
  EXPECT_NEAR(path_length(slot), 40 + 10 * std::numbers::pi, 1e-9);

  const Path& circle = (*paths)[1];
  EXPECT_TRUE(circle.closed);
  EXPECT_EQ(circle.start, (Vec2{53, 5}));
  EXPECT_NEAR(path_length(circle), 6 * std::numbers::pi, 1e-9);

  const Path& arc = (*paths)[2];
  EXPECT_NEAR(arc.start.x, 75, 1e-12);
  EXPECT_NEAR(arc.segs[0].to.y, 5, 1e-12);
  EXPECT_EQ(arc.segs[0].turn, 1);

  const Path& poly = (*paths)[3];
  EXPECT_FALSE(poly.closed);
  ASSERT_EQ(poly.segs.size(), 2u);
  ASSERT_TRUE(poly.segs[0].center);
  EXPECT_NEAR(poly.segs[0].center->x, 90, 1e-6);
  EXPECT_NEAR(poly.segs[0].center->y, 0, 1e-6);
  EXPECT_EQ(poly.segs[0].turn, -1);
  EXPECT_FALSE(poly.segs[1].center);
}

TEST(DxfImport, SplineWithinTheToleranceAndUnsupportedEntitiesWarn) {
  core::DiagnosticList d;
  DxfOptions o;
  o.spline_tolerance = 0.005;
  const auto paths = read_dxf(fixture("spline_and_text.dxf"), o, d);
  ASSERT_TRUE(paths);
  ASSERT_EQ(paths->size(), 1u);
  EXPECT_EQ(count(d, core::Code::DxfUnsupportedEntity), 2);  // TEXT, ELLIPSE
  EXPECT_FALSE(d.has_errors());
  const auto pts = linearize((*paths)[0], 0.001);
  EXPECT_EQ(pts.front(), (Vec2{0, 0}));
  EXPECT_EQ(pts.back(), (Vec2{40, 0}));
  const core::CubicBezier b{{0, 0}, {10, 20}, {30, 20}, {40, 0}};
  // Every point on the curve, and the curve near every chord: sample the curve.
  for (const Vec2& p : pts) {
    double best = 1e9;
    for (int i = 0; i <= 4000; ++i)
      best = std::min(best, core::distance(p, core::point(b, i / 4000.0)));
    EXPECT_LT(best, 0.01);
  }
  for (int i = 0; i <= 100; ++i) {
    const Vec2 q = core::point(b, i / 100.0);
    double best = 1e9;
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
      const Vec2 a = pts[k];
      const Vec2 e = pts[k + 1] - a;
      const double t = std::clamp(core::dot(q - a, e) / core::dot(e, e), 0.0, 1.0);
      best = std::min(best, core::distance(q, a + e * t));
    }
    EXPECT_LE(best, 0.005 + 1e-9);
  }
}

TEST(DxfImport, MissingFileIsAnError) {
  core::DiagnosticList d;
  EXPECT_FALSE(read_dxf(fixture("no_such_file.dxf"), {}, d));
  EXPECT_EQ(count(d, core::Code::DxfUnreadable), 1);
}

TEST(DxfImport, NothingToCutIsAnError) {
  core::DiagnosticList d;
  EXPECT_FALSE(read_dxf(fixture("not_a_drawing.dxf"), {}, d));
  EXPECT_EQ(count(d, core::Code::DxfNoEntities), 1);
  EXPECT_EQ(count(d, core::Code::DxfUnsupportedEntity), 1);
}

TEST(DxfImport, EmptyLayerIsAnErrorNamingIt) {
  core::DiagnosticList d;
  DxfOptions o;
  o.layer = "NO_SUCH_LAYER";
  EXPECT_FALSE(read_dxf(fixture("square_lines.dxf"), o, d));
  ASSERT_EQ(count(d, core::Code::DxfNoEntities), 1);
  EXPECT_NE(d.all().back().message.find("NO_SUCH_LAYER"), std::string::npos);
}

TEST(DxfImport, TextThatIsNoDxfIsAnError) {
  core::DiagnosticList d;
  std::istringstream in("G0 X10 Y10\nG1 X20\nM30\n");
  EXPECT_FALSE(read_dxf(in, "prog.ngc", {}, d));
  EXPECT_TRUE(d.has_errors());
}

TEST(DxfImport, BinaryGarbageIsAnErrorNotACrash) {
  core::DiagnosticList d;
  std::string junk;
  for (int i = 0; i < 4096; ++i)
    junk.push_back(static_cast<char>((i * 7919) % 256));
  std::istringstream in(junk);
  EXPECT_FALSE(read_dxf(in, "junk", {}, d));
  EXPECT_TRUE(d.has_errors());
}

TEST(DxfImport, BadSplineIsAWarningAndLeftOut) {
  // Degree 3 with 4 control points needs 8 knots; this one has 5.
  core::DiagnosticList d;
  std::istringstream in(
      "0\nSECTION\n2\nENTITIES\n"
      "0\nSPLINE\n8\n0\n70\n8\n71\n3\n72\n5\n73\n4\n74\n0\n"
      "40\n0\n40\n0\n40\n0\n40\n1\n40\n1\n"
      "10\n0\n20\n0\n30\n0\n10\n1\n20\n1\n30\n0\n10\n2\n20\n1\n30\n0\n10\n3\n20\n0\n30\n0\n"
      "0\nLINE\n8\n0\n10\n0\n20\n0\n30\n0\n11\n1\n21\n0\n31\n0\n"
      "0\nENDSEC\n0\nEOF\n");
  const auto paths = read_dxf(in, "bad_spline", {}, d);
  ASSERT_TRUE(paths);
  EXPECT_EQ(paths->size(), 1u);
  ASSERT_EQ(count(d, core::Code::DxfUnsupportedEntity), 1);
  EXPECT_NE(d.all()[0].message.find("5 knots"), std::string::npos) << d.all()[0].message;
}

TEST(DxfImport, HugeOrBadCoordinatesAndEmptyCirclesAreLeftOut) {
  // (dxflib reads a value that is not a number, "nan" too, as 0.)
  core::DiagnosticList d;
  std::istringstream in(
      "0\nSECTION\n2\nENTITIES\n"
      "0\nLINE\n8\n0\n10\n0\n20\n0\n30\n0\n11\n1e300\n21\n0\n31\n0\n"
      "0\nLINE\n8\n0\n10\n-2e5\n20\n0\n30\n0\n11\n1\n21\n0\n31\n0\n"
      "0\nCIRCLE\n8\n0\n10\n0\n20\n0\n30\n0\n40\n0\n"
      "0\nLINE\n8\n0\n10\n0\n20\n0\n30\n0\n11\n1\n21\n0\n31\n0\n"
      "0\nENDSEC\n0\nEOF\n");
  const auto paths = read_dxf(in, "hostile", {}, d);
  ASSERT_TRUE(paths);
  EXPECT_EQ(paths->size(), 1u);
  EXPECT_EQ(count(d, core::Code::DxfUnsupportedEntity), 3);
}

TEST(DxfImport, MirroredArcTurnsClockwise) {
  // Extrusion (0, 0, -1): the arc's X axis is the world's -X.
  core::DiagnosticList d;
  std::istringstream in(
      "0\nSECTION\n2\nENTITIES\n"
      "0\nARC\n8\n0\n10\n10\n20\n0\n30\n0\n40\n5\n210\n0\n220\n0\n230\n-1\n50\n0\n51\n90\n"
      "0\nENDSEC\n0\nEOF\n");
  const auto paths = read_dxf(in, "mirrored", {}, d);
  ASSERT_TRUE(paths);
  const Path& a = (*paths)[0];
  EXPECT_NEAR(a.start.x, -15, 1e-12);
  EXPECT_NEAR(a.segs[0].to.x, -10, 1e-12);
  EXPECT_NEAR(a.segs[0].to.y, 5, 1e-12);
  EXPECT_NEAR(a.segs[0].center->x, -10, 1e-12);
  EXPECT_EQ(a.segs[0].turn, -1);
}

}  // namespace
}  // namespace usina::cam
