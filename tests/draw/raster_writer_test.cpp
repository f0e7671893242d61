// PNG and PDF through cairo: a valid PNG of the asked size with ink where
// the drawing's line is and none in the margin; a PDF file; bad sizes and
// paths are errors.
#include "draw/raster_writer.hpp"

#include <cairo.h>
#include <unistd.h>

#include <array>
#include <fstream>
#include <memory>
#include <sstream>

#include <gtest/gtest.h>

#include "draw/layer_style.hpp"

namespace usina::draw {
namespace {

std::string temp_name(const char* suffix) {
  char name[] = "/tmp/usina_raster_test_XXXXXX";
  const int fd = mkstemp(name);
  EXPECT_GE(fd, 0);
  close(fd);
  unlink(name);
  return std::string(name) + suffix;
}

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};

using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;

// Whether the pixel at (x, y) of an RGB24 image is not white.
bool inked(cairo_surface_t* s, int x, int y) {
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  const unsigned char* p = data + static_cast<std::ptrdiff_t>(y) * stride + 4 * x;
  return p[0] < 200 || p[1] < 200 || p[2] < 200;
}

// A horizontal line through the middle of the drawing.
Drawing one_line() {
  Drawing d;
  d.add_line(d.layer(kContourLayer), {0, 0}, {100, 0});
  return d;
}

TEST(PngWriter, IsAPngOfTheAskedSizeWithTheLineDrawn) {
  const std::string path = temp_name(".png");
  ASSERT_TRUE(write_png_file(one_line(), path, {640, 480}));
  Surface s(cairo_image_surface_create_from_png(path.c_str()));
  ASSERT_EQ(cairo_surface_status(s.get()), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(s.get()), 640);
  EXPECT_EQ(cairo_image_surface_get_height(s.get()), 480);
  cairo_surface_flush(s.get());
  // The middle column crosses the line above the legend band.
  bool line_found = false;
  for (int y = 0; y < 400; ++y)
    line_found = line_found || inked(s.get(), 320, y);
  EXPECT_TRUE(line_found);
  // The top left corner is paper.
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      EXPECT_FALSE(inked(s.get(), x, y)) << x << "," << y;
  unlink(path.c_str());
}

// The colour of the first inked pixel of the middle column above the legend.
std::array<unsigned char, 3> middle_ink(const Drawing& d) {
  const std::string path = temp_name(".png");
  EXPECT_TRUE(write_png_file(d, path, {640, 480}));
  Surface s(cairo_image_surface_create_from_png(path.c_str()));
  unlink(path.c_str());
  EXPECT_EQ(cairo_surface_status(s.get()), CAIRO_STATUS_SUCCESS);
  cairo_surface_flush(s.get());
  for (int y = 0; y < 400; ++y) {
    if (!inked(s.get(), 320, y)) continue;
    const unsigned char* p =
        cairo_image_surface_get_data(s.get()) +
        static_cast<std::ptrdiff_t>(y) * cairo_image_surface_get_stride(s.get()) + 4 * 320;
    return {p[2], p[1], p[0]};  // RGB24 is stored B, G, R on little-endian machines
  }
  ADD_FAILURE() << "no ink";
  return {};
}

TEST(PngWriter, ContourIsBlackWithoutToolAndInTheToolsColourWithOne) {
  Drawing d = one_line();
  const auto black = middle_ink(d);
  EXPECT_LT(black[0], 100);
  EXPECT_LT(black[1], 100);
  d.layer(kContourLayer).tool_runs.push_back({0, 1});  // T1: red
  const auto red = middle_ink(d);
  EXPECT_GT(red[0], 150);
  EXPECT_LT(red[1], 100);
  EXPECT_LT(red[2], 100);
}

TEST(PngWriter, EmptyDrawingIsAWhitePictureWithItsScaleBar) {
  const std::string path = temp_name(".png");
  ASSERT_TRUE(write_png_file(Drawing{}, path, {200, 100}));
  Surface s(cairo_image_surface_create_from_png(path.c_str()));
  ASSERT_EQ(cairo_surface_status(s.get()), CAIRO_STATUS_SUCCESS);
  EXPECT_EQ(cairo_image_surface_get_width(s.get()), 200);
  unlink(path.c_str());
}

TEST(PngWriter, SizeOutOfRangeIsAnError) {
  EXPECT_FALSE(write_png_file(one_line(), temp_name(".png"), {0, 10}));
  EXPECT_FALSE(write_png_file(one_line(), temp_name(".png"), {100000, 100000}));
}

TEST(PngWriter, UnwritablePathIsAnError) {
  const auto r = write_png_file(one_line(), "/nonexistent/usina/x.png", {10, 10});
  ASSERT_FALSE(r);
  EXPECT_FALSE(r.error().empty());
}

TEST(PdfWriter, WritesAPdf) {
  const std::string path = temp_name(".pdf");
  ASSERT_TRUE(write_pdf_file(one_line(), path));
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_TRUE(ss.str().starts_with("%PDF")) << ss.str().substr(0, 16);
  EXPECT_GT(ss.str().size(), 500u);
  unlink(path.c_str());
}

TEST(PdfWriter, UnwritablePathIsAnError) {
  EXPECT_FALSE(write_pdf_file(one_line(), "/nonexistent/usina/x.pdf"));
}

}  // namespace
}  // namespace usina::draw
