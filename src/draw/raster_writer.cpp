#include "draw/raster_writer.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <cairo-pdf.h>
#include <fmt/format.h>

#include "draw/finite.hpp"
#include "draw/layer_style.hpp"
#include "draw/raster_render.hpp"

namespace usina::draw {
namespace {

// Entities added to a cairo path before it is stroked, so that the path of a
// big layer stays small.
constexpr std::size_t kStrokeBatch = 4096;
// A4 in PostScript points.
constexpr double kA4Long = 841.89;
constexpr double kA4Short = 595.28;

// Drawing coordinates (mm, y up) → device coordinates (y down).
class Frame {
 public:
  Frame(const Box& box, double left, double top, double width, double height) {
    const double bw = std::max(box.width(), 1e-9);
    const double bh = std::max(box.height(), 1e-9);
    scale_ = std::min(width / bw, height / bh);
    // Centred in the area.
    ox_ = left + (width - bw * scale_) / 2.0 - box.min.x * scale_;
    oy_ = top + (height + bh * scale_) / 2.0 + box.min.y * scale_;
  }

  Vec2 device(Vec2 p) const { return {ox_ + p.x * scale_, oy_ - p.y * scale_}; }

  // Device units per mm.
  double scale() const { return scale_; }

 private:
  double scale_ = 1.0;
  double ox_ = 0.0;
  double oy_ = 0.0;
};

// Adds entities to the current path; a line that starts where the path is
// goes on from it, so that a chain of segments is one stroke (joins, not a
// cap at every end: much faster to stroke).
struct PathOf {
  cairo_t* cr;
  const Frame& frame;

  void operator()(const Line& l) const {
    const Vec2 a = frame.device(l.from);
    const Vec2 b = frame.device(l.to);
    double x = 0.0;
    double y = 0.0;
    if (cairo_has_current_point(cr)) cairo_get_current_point(cr, &x, &y);
    if (!cairo_has_current_point(cr) || std::fabs(x - a.x) > 1e-6 || std::fabs(y - a.y) > 1e-6)
      cairo_move_to(cr, a.x, a.y);
    cairo_line_to(cr, b.x, b.y);
  }

  // The flip of y turns counter-clockwise into cairo's negative direction.
  void operator()(const Arc& a) const {
    const Vec2 c = frame.device(a.center);
    const Vec2 s = frame.device(arc_start(a));
    cairo_new_sub_path(cr);
    cairo_move_to(cr, s.x, s.y);
    if (a.ccw) {
      cairo_arc_negative(cr, c.x, c.y, a.radius * frame.scale(), -a.start_angle, -a.end_angle);
    } else {
      cairo_arc(cr, c.x, c.y, a.radius * frame.scale(), -a.start_angle, -a.end_angle);
    }
  }

  void operator()(const Circle& c) const {
    const Vec2 d = frame.device(c.center);
    cairo_new_sub_path(cr);
    cairo_arc(cr, d.x, d.y, c.radius * frame.scale(), 0.0, 2.0 * std::numbers::pi);
    cairo_close_path(cr);
  }

  void operator()(const Polyline& p) const {
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      const Vec2 d = frame.device(p.points[i]);
      if (i == 0) {
        cairo_move_to(cr, d.x, d.y);
      } else {
        cairo_line_to(cr, d.x, d.y);
      }
    }
    if (p.closed) cairo_close_path(cr);
  }
};

// Sizes of the picture's furniture, in device units.
struct Furniture {
  double margin;
  double font;
  double line_width;
  double band;  // height of the legend and scale bar strip at the bottom
};

Furniture furniture_for(double width, double height, double line_width) {
  const double small = std::min(width, height);
  const double font = std::max(8.0, small / 60.0);
  return {0.03 * small, font, line_width, 2.5 * font};
}

void set_style(cairo_t* cr, const LayerStyle& style, const Furniture& f) {
  cairo_set_source_rgb(cr, style.rgb.r / 255.0, style.rgb.g / 255.0, style.rgb.b / 255.0);
  cairo_set_line_width(cr, f.line_width);
  if (style.dashed) {
    const double dashes[2] = {6.0 * f.line_width, 4.0 * f.line_width};
    cairo_set_dash(cr, dashes, 2, 0.0);
  } else {
    cairo_set_dash(cr, nullptr, 0, 0.0);
  }
}

// A stretch of a layer's entities drawn in one style: a whole layer, or on
// CONTOUR the entities one tool cut (in the tool's colour; T0, no tool, in
// the layer's).
struct Piece {
  const Layer* layer;
  std::size_t first;
  std::size_t last;  // one past
  LayerStyle style;
  std::string label;
};

std::vector<Piece> pieces_of(const Drawing& drawing) {
  std::vector<Piece> out;
  for (const Layer* layer : drawing.layers()) {
    const std::size_t n = layer->entities.size();
    const auto& runs = layer->tool_runs;
    const std::size_t untooled = runs.empty() ? n : std::min(runs.front().first, n);
    if (untooled > 0) out.push_back({layer, 0, untooled, layer->style, layer->name});
    for (std::size_t i = 0; i < runs.size(); ++i) {
      const std::size_t first = std::min(runs[i].first, n);
      const std::size_t last = i + 1 < runs.size() ? std::min(runs[i + 1].first, n) : n;
      if (first >= last) continue;
      const int tool = runs[i].tool;
      LayerStyle style = layer->style;
      if (tool != 0) {
        style = style_of(toolpath_layer(tool));
        style.dashed = layer->style.dashed;
      }
      out.push_back({layer, first, last, style,
                     tool == 0 ? layer->name : fmt::format("{} T{}", layer->name, tool)});
    }
  }
  return out;
}

void draw_pieces(cairo_t* cr, const std::vector<Piece>& pieces, const Frame& frame,
                 const Furniture& f) {
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  // A layer's pieces follow one another in the order of its entities
  // (pieces_of), which are read once, in order (entity_list.hpp: they may
  // be in a temporary file).
  const Layer* layer = nullptr;
  std::optional<EntityList::Cursor> at;
  std::size_t index = 0;
  for (const Piece& piece : pieces) {
    if (piece.layer != layer) {
      layer = piece.layer;
      at.emplace(layer->entities.begin());
      index = 0;
    }
    set_style(cr, piece.style, f);
    // A cursor ends early only when the file cannot be read back; the
    // writer then says so (Drawing::read_error).
    for (; index < piece.last && *at != std::default_sentinel; ++index, ++*at) {
      if (is_finite(**at)) std::visit(PathOf{cr, frame}, **at);
      if ((index + 1 - piece.first) % kStrokeBatch == 0) cairo_stroke(cr);
    }
    cairo_stroke(cr);
  }
}

// A sample and the label of each piece (once a label), left to right.
void draw_legend(cairo_t* cr, const std::vector<Piece>& pieces, const Furniture& f, double left,
                 double y) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, f.font);
  double x = left + f.margin;
  std::vector<std::string> shown;
  for (const Piece& piece : pieces) {
    if (std::find(shown.begin(), shown.end(), piece.label) != shown.end()) continue;
    shown.push_back(piece.label);
    set_style(cr, piece.style, f);
    cairo_move_to(cr, x, y - f.font / 3.0);
    cairo_line_to(cr, x + 2.0 * f.font, y - f.font / 3.0);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_move_to(cr, x + 2.5 * f.font, y);
    cairo_show_text(cr, piece.label.c_str());
    cairo_text_extents_t ext;
    cairo_text_extents(cr, piece.label.c_str(), &ext);
    x += 3.5 * f.font + ext.x_advance;
  }
}

// The largest 1, 2 or 5 × 10^k not above `x`.
double nice_length(double x) {
  const double p = std::pow(10.0, std::floor(std::log10(x)));
  for (const double m : {5.0, 2.0, 1.0})
    if (m * p <= x) return m * p;
  return p;
}

// A bar of a round number of mm at the bottom right, its length above it.
void draw_scale_bar(cairo_t* cr, const Frame& frame, const Furniture& f, double left, double right,
                    double y) {
  const double mm = nice_length(0.25 * (right - left - f.margin) / frame.scale());
  const double len = mm * frame.scale();
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  cairo_set_line_width(cr, f.line_width);
  cairo_move_to(cr, right - len, y - f.font / 2.0);
  cairo_line_to(cr, right - len, y);
  cairo_line_to(cr, right, y);
  cairo_line_to(cr, right, y - f.font / 2.0);
  cairo_stroke(cr);
  const std::string label = fmt::format("{:g} mm", mm);
  cairo_set_font_size(cr, f.font);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, label.c_str(), &ext);
  cairo_move_to(cr, right - len / 2.0 - ext.x_advance / 2.0, y - f.font * 0.7);
  cairo_show_text(cr, label.c_str());
}

void render(cairo_t* cr, const Drawing& drawing, double width, double height, double line_width) {
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  render_drawing(cr, drawing, {0.0, 0.0, width, height}, line_width);
}

}  // namespace

WriteResult finish_surface(cairo_surface_t* surface) {
  cairo_surface_finish(surface);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
    return tl::unexpected(status_text(cairo_surface_status(surface)));
  return {};
}

void render_drawing(cairo_t* cr, const Drawing& drawing, const Area& area, double line_width) {
  cairo_save(cr);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_rectangle(cr, area.left, area.top, area.width, area.height);
  cairo_fill(cr);
  const Furniture f = furniture_for(area.width, area.height, line_width);
  const Frame frame(finite_view_box(drawing), area.left + f.margin, area.top + f.margin,
                    area.width - 2.0 * f.margin, area.height - 2.0 * f.margin - f.band);
  const std::vector<Piece> pieces = pieces_of(drawing);
  draw_pieces(cr, pieces, frame, f);
  const double baseline = area.top + area.height - f.margin;
  draw_legend(cr, pieces, f, area.left, baseline);
  draw_scale_bar(cr, frame, f, area.left, area.left + area.width - f.margin, baseline);
  cairo_restore(cr);
}

// The bytes to the FILE, whose error flag OutputFile::commit() reads.
cairo_status_t write_to_stream(void* file, const unsigned char* data, unsigned int length) {
  const std::size_t n = std::fwrite(data, 1, length, static_cast<std::FILE*>(file));
  return n == length ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

WriteResult write_png(const Drawing& drawing, std::FILE* file, PixelSize size) {
  if (size.width < 1 || size.height < 1 ||
      static_cast<long>(size.width) * size.height > kMaxPngPixels)
    return tl::unexpected(fmt::format("image size {}x{} is out of range (at most {} pixels)",
                                      size.width, size.height, kMaxPngPixels));
  Surface surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, size.width, size.height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    return tl::unexpected(status_text(cairo_surface_status(surface.get())));
  {
    Context cr(cairo_create(surface.get()));
    render(cr.get(), drawing, size.width, size.height, 1.5);
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
      return tl::unexpected(status_text(cairo_status(cr.get())));
  }
  if (auto error = drawing.read_error()) return tl::unexpected(*error);
  const cairo_status_t s = cairo_surface_write_to_png_stream(surface.get(), write_to_stream, file);
  if (s != CAIRO_STATUS_SUCCESS) return tl::unexpected(status_text(s));
  return {};
}

WriteResult write_pdf(const Drawing& drawing, std::FILE* file) {
  const Box box = finite_view_box(drawing);
  const bool landscape = box.width() >= box.height();
  const double w = landscape ? kA4Long : kA4Short;
  const double h = landscape ? kA4Short : kA4Long;
  Surface surface(cairo_pdf_surface_create_for_stream(write_to_stream, file, w, h));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    return tl::unexpected(status_text(cairo_surface_status(surface.get())));
  {
    Context cr(cairo_create(surface.get()));
    render(cr.get(), drawing, w, h, 0.6);
    cairo_show_page(cr.get());
    if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
      return tl::unexpected(status_text(cairo_status(cr.get())));
  }
  if (auto error = drawing.read_error()) return tl::unexpected(*error);
  return finish_surface(surface.get());
}

WriteResult write_png_file(const Drawing& drawing, const std::string& path, PixelSize size,
                           const std::vector<std::string>& inputs) {
  return write_to_file(path, inputs,
                       [&](std::FILE* file) { return write_png(drawing, file, size); });
}

WriteResult write_pdf_file(const Drawing& drawing, const std::string& path,
                           const std::vector<std::string>& inputs) {
  return write_to_file(path, inputs, [&](std::FILE* file) { return write_pdf(drawing, file); });
}

}  // namespace usina::draw
