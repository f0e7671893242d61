#include "cli/simulate_images.hpp"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

namespace usina::cli {
namespace {

using sim::stock::HeightMap;

struct Rgb {
  double r, g, b;
};

// Uncut stock, then one colour a tool (by its order of use), then rapid red.
constexpr Rgb kStock{0.80, 0.78, 0.72};
constexpr Rgb kRapid{0.90, 0.10, 0.10};
constexpr std::array<Rgb, 6> kTools = {{{0.30, 0.55, 0.85},
                                        {0.35, 0.75, 0.40},
                                        {0.95, 0.70, 0.20},
                                        {0.65, 0.45, 0.80},
                                        {0.30, 0.75, 0.75},
                                        {0.85, 0.50, 0.65}}};

Rgb colour_of(std::uint8_t mark) {
  if (mark == sim::stock::kUncut) return kStock;
  if (mark == sim::stock::kRapidMark) return kRapid;
  return kTools[static_cast<std::size_t>(mark - 1) % kTools.size()];
}

// A coarser grid for the picture: each block's lowest height and the mark of that cell.
struct Blocks {
  std::size_t nx = 0, ny = 0, step = 1;
  double dx = 0.0, dy = 0.0;
  std::vector<double> z;
  std::vector<std::uint8_t> mark;

  double at(std::size_t i, std::size_t j) const { return z[j * nx + i]; }
};

Blocks blocks_of(const HeightMap& m, std::size_t max_side) {
  Blocks b;
  b.step = std::max<std::size_t>(1, (std::max(m.nx(), m.ny()) + max_side - 1) / max_side);
  b.nx = (m.nx() + b.step - 1) / b.step;
  b.ny = (m.ny() + b.step - 1) / b.step;
  b.dx = m.dx() * static_cast<double>(b.step);
  b.dy = m.dy() * static_cast<double>(b.step);
  b.z.assign(b.nx * b.ny, m.top());
  b.mark.assign(b.nx * b.ny, sim::stock::kUncut);
  for (std::size_t j = 0; j < m.ny(); ++j) {
    for (std::size_t i = 0; i < m.nx(); ++i) {
      const std::size_t k = (j / b.step) * b.nx + i / b.step;
      const double z = m.z(i, j);
      if (z < b.z[k] || (b.mark[k] == sim::stock::kUncut && m.mark(i, j) != 0)) {
        b.z[k] = std::min(z, b.z[k]);
        b.mark[k] = m.mark(i, j);
      }
    }
  }
  return b;
}

// Lambert shading from the slope of the heights (light from the upper left).
double shade(const Blocks& b, std::size_t i, std::size_t j) {
  const std::size_t i0 = i > 0 ? i - 1 : i, i1 = i + 1 < b.nx ? i + 1 : i;
  const std::size_t j0 = j > 0 ? j - 1 : j, j1 = j + 1 < b.ny ? j + 1 : j;
  const double gx =
      i1 > i0 ? (b.at(i1, j) - b.at(i0, j)) / (b.dx * static_cast<double>(i1 - i0)) : 0.0;
  const double gy =
      j1 > j0 ? (b.at(i, j1) - b.at(i, j0)) / (b.dy * static_cast<double>(j1 - j0)) : 0.0;
  const double n = std::sqrt(gx * gx + gy * gy + 1.0);
  const double lx = -0.45, ly = 0.45, lz = 0.77;
  const double d = (-gx * lx - gy * ly + lz) / n;
  return 0.35 + 0.65 * std::clamp(d, 0.0, 1.0);
}

void fill(cairo_t* cr, const Rgb& c, double s) {
  cairo_set_source_rgb(cr, c.r * s, c.g * s, c.b * s);
}

struct Surface {
  cairo_surface_t* p;

  ~Surface() { cairo_surface_destroy(p); }
};

struct Context {
  cairo_t* p;

  ~Context() { cairo_destroy(p); }
};

cairo_status_t write_bytes(void* closure, const unsigned char* data, unsigned int length) {
  auto* file = static_cast<std::FILE*>(closure);
  return std::fwrite(data, 1, length, file) == length ? CAIRO_STATUS_SUCCESS
                                                      : CAIRO_STATUS_WRITE_ERROR;
}

void draw_top(cairo_t* cr, const Blocks& b, double scale, double height) {
  for (std::size_t j = 0; j < b.ny; ++j) {
    for (std::size_t i = 0; i < b.nx; ++i) {
      fill(cr, colour_of(b.mark[j * b.nx + i]), shade(b, i, j));
      const double y = height - static_cast<double>(j + 1) * b.dy * scale;
      cairo_rectangle(cr, static_cast<double>(i) * b.dx * scale, y, b.dx * scale + 0.5,
                      b.dy * scale + 0.5);
      cairo_fill(cr);
    }
  }
}

// Isometric: X to the lower right, Y to the upper right, Z up.
struct Iso {
  double scale, ox, oy, top;

  void to(double x, double y, double z, double& px, double& py) const {
    px = ox + (x + y) * 0.866 * scale;
    py = oy + ((x - y) * 0.5 - (z - top)) * scale;
  }
};

void quad(cairo_t* cr, const Iso& iso, const std::array<std::array<double, 3>, 4>& p) {
  double px = 0.0, py = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    iso.to(p[k][0], p[k][1], p[k][2], px, py);
    k == 0 ? cairo_move_to(cr, px, py) : cairo_line_to(cr, px, py);
  }
  cairo_close_path(cr);
  cairo_fill(cr);
}

// The stock's front walls (the faces at Y = 0 and at X = max), then the top
// from the back to the front, each block as a flat top and its step down.
void draw_iso(cairo_t* cr, const Blocks& b, const Iso& iso, double bottom) {
  for (std::size_t j = b.ny; j-- > 0;) {
    for (std::size_t i = 0; i < b.nx; ++i) {
      const double x0 = static_cast<double>(i) * b.dx, x1 = x0 + b.dx;
      const double y0 = static_cast<double>(j) * b.dy, y1 = y0 + b.dy;
      const double z = b.at(i, j);
      const Rgb c = colour_of(b.mark[j * b.nx + i]);
      // The face towards the viewer at y0 and at x1, down to the next block or the bottom.
      const double zf = j > 0 ? b.at(i, j - 1) : bottom;
      if (zf < z) {
        fill(cr, c, 0.55);
        quad(cr, iso, {{{x0, y0, z}, {x1, y0, z}, {x1, y0, zf}, {x0, y0, zf}}});
      }
      const double zr = i + 1 < b.nx ? b.at(i + 1, j) : bottom;
      if (zr < z) {
        fill(cr, c, 0.7);
        quad(cr, iso, {{{x1, y0, z}, {x1, y1, z}, {x1, y1, zr}, {x1, y0, zr}}});
      }
      fill(cr, c, shade(b, i, j));
      quad(cr, iso, {{{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}}});
    }
  }
}
}  // namespace

tl::expected<void, std::string> write_stock_png(const HeightMap& m, StockView view,
                                                std::FILE* file) {
  constexpr double kWidth = 1600.0;
  const Blocks b = blocks_of(m, view == StockView::Top ? 800 : 320);
  const double w = m.box().width, l = m.box().length, h = m.box().height;
  double scale = 0.0, height = 0.0;
  Iso iso{};
  if (view == StockView::Top) {
    scale = kWidth / std::max(w, l);
    height = std::ceil(l * scale);
  } else {
    scale = (kWidth - 40.0) / ((w + l) * 0.866);
    height = std::ceil(((w + l) * 0.5 + h) * scale + 40.0);
    iso = {scale, 20.0, 20.0 + l * 0.5 * scale, m.top()};
  }
  const double width = view == StockView::Top ? std::ceil(w * scale) : kWidth;
  Surface surface{cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(width),
                                             static_cast<int>(height))};
  {
    Context cr{cairo_create(surface.p)};
    cairo_set_source_rgb(cr.p, 1, 1, 1);
    cairo_paint(cr.p);
    cairo_set_antialias(cr.p, CAIRO_ANTIALIAS_NONE);
    if (view == StockView::Top) {
      draw_top(cr.p, b, scale, height);
    } else {
      draw_iso(cr.p, b, iso, m.bottom());
    }
    if (cairo_status(cr.p) != CAIRO_STATUS_SUCCESS)
      return tl::unexpected(std::string(cairo_status_to_string(cairo_status(cr.p))));
  }
  const cairo_status_t s = cairo_surface_write_to_png_stream(surface.p, write_bytes, file);
  if (s != CAIRO_STATUS_SUCCESS) return tl::unexpected(std::string(cairo_status_to_string(s)));
  return {};
}

}  // namespace usina::cli
