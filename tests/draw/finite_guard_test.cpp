// The writers' defensive guard (draw/finite.hpp): canon's range keeps NaN and
// infinities out of a drawing, but if one got in, no writer aborts (cairo
// asserts on a NaN arc angle) or writes "nan"/"inf" into a file.
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "draw/drawing.hpp"
#include "draw/dxf_writer.hpp"
#include "draw/finite.hpp"
#include "draw/raster_writer.hpp"
#include "draw/svg_writer.hpp"

namespace usina::draw {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string temp_name(const char* suffix) {
  char name[] = "/tmp/usina_finite_test_XXXXXX";
  const int fd = mkstemp(name);
  EXPECT_GE(fd, 0);
  close(fd);
  unlink(name);
  return std::string(name) + suffix;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A square, and the arc of the G2 R[10**200] as the builder made it
// before canon's range: its centre (-nan, -inf).
Drawing poisoned() {
  Drawing d;
  Layer& l = d.layer("CONTOUR");
  d.add_line(l, {0, 0}, {10, 0});
  d.add_line(l, {10, 0}, {10, 10});
  l.entities.push_back(Arc{{kNan, -kInf}, 1.0, kNan, 0.0, false});
  l.entities.push_back(Line{{0, 0}, {kInf, 1}});
  l.entities.push_back(Polyline{{{0, 0}, {1, kNan}, {2, 2}}, false});
  return d;
}

TEST(FiniteGuard, EntitiesWithNonFiniteNumbersAreRecognised) {
  EXPECT_TRUE(is_finite(Entity{Line{{0, 0}, {1, 1}}}));
  EXPECT_FALSE(is_finite(Entity{Line{{0, 0}, {kInf, 1}}}));
  EXPECT_FALSE(is_finite(Entity{Arc{{0, 0}, 1.0, kNan, 0.0, true}}));
  EXPECT_FALSE(is_finite(Entity{Circle{{0, 0}, kInf}}));
  EXPECT_FALSE(is_finite(Entity{Polyline{{{0, 0}, {kNan, 0}}, false}}));
  EXPECT_TRUE(is_finite(Entity{Polyline{{{0, 0}, {1, 0}}, true}}));
}

TEST(FiniteGuard, PngOfANanArcDoesNotAbort) {
  const std::string path = temp_name(".png");
  ASSERT_TRUE(write_png_file(poisoned(), path, {200, 150}).has_value());
  EXPECT_GT(read_all(path).size(), 8u);
  unlink(path.c_str());
}

TEST(FiniteGuard, PdfOfANanArcDoesNotAbort) {
  const std::string path = temp_name(".pdf");
  ASSERT_TRUE(write_pdf_file(poisoned(), path).has_value());
  EXPECT_GT(read_all(path).size(), 8u);
  unlink(path.c_str());
}

TEST(FiniteGuard, SvgAndDxfHoldNoNan) {
  std::ostringstream svg;
  write_svg(poisoned(), svg);
  EXPECT_EQ(svg.str().find("nan"), std::string::npos) << svg.str();
  EXPECT_EQ(svg.str().find("inf"), std::string::npos) << svg.str();
  EXPECT_NE(svg.str().find("<line"), std::string::npos);  // the good lines are kept
  const std::string path = temp_name(".dxf");
  ASSERT_TRUE(write_dxf_file(poisoned(), path).has_value());
  const std::string dxf = read_all(path);
  unlink(path.c_str());
  EXPECT_EQ(dxf.find("nan"), std::string::npos);
  EXPECT_EQ(dxf.find("inf"), std::string::npos);
}

TEST(FiniteGuard, NonFiniteBoundsShowTheEmptyView) {
  Drawing d;
  Layer& l = d.layer("CONTOUR");
  d.add_line(l, {0, 0}, {kInf, 0});  // bounds become infinite
  const Box b = finite_view_box(d);
  EXPECT_TRUE(std::isfinite(b.min.x) && std::isfinite(b.max.x));
  std::ostringstream svg;
  write_svg(d, svg);
  EXPECT_EQ(svg.str().find("inf"), std::string::npos) << svg.str();
}

}  // namespace
}  // namespace usina::draw
