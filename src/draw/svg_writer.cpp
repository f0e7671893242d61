#include "draw/svg_writer.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <numbers>

#include <fmt/format.h>

#include "core/file_ostream.hpp"
#include "draw/finite.hpp"

namespace usina::draw {
namespace {

// Lines are drawn 1/1000 of the picture's larger side wide, so that a large
// part and a small one look alike on screen.
constexpr double kStrokeFraction = 1e-3;

std::string hex(Rgb c) {
  return fmt::format("#{:02x}{:02x}{:02x}", c.r, c.g, c.b);
}

class SvgEntities {
 public:
  explicit SvgEntities(fmt::memory_buffer& buf) : buf_(buf) {}

  void operator()(const Line& l) {
    fmt::format_to(std::back_inserter(buf_), "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"/>\n",
                   svg_number(l.from.x), svg_number(-l.from.y), svg_number(l.to.x),
                   svg_number(-l.to.y));
  }

  // After the flip a counter-clockwise arc stays counter-clockwise on the
  // screen, which is SVG's negative-angle direction: sweep-flag 0.
  void operator()(const Arc& a) {
    const Vec2 s = arc_start(a);
    const Vec2 e = arc_end(a);
    const int large = arc_sweep(a) > std::numbers::pi ? 1 : 0;
    const int sweep = a.ccw ? 0 : 1;
    const std::string r = svg_number(a.radius);
    fmt::format_to(std::back_inserter(buf_), "<path d=\"M{} {}A{} {} 0 {} {} {} {}\"/>\n",
                   svg_number(s.x), svg_number(-s.y), r, r, large, sweep, svg_number(e.x),
                   svg_number(-e.y));
  }

  void operator()(const Circle& c) {
    fmt::format_to(std::back_inserter(buf_), "<circle cx=\"{}\" cy=\"{}\" r=\"{}\"/>\n",
                   svg_number(c.center.x), svg_number(-c.center.y), svg_number(c.radius));
  }

  void operator()(const Polyline& p) {
    fmt::format_to(std::back_inserter(buf_), "<{} points=\"", p.closed ? "polygon" : "polyline");
    for (std::size_t i = 0; i < p.points.size(); ++i)
      fmt::format_to(std::back_inserter(buf_), "{}{},{}", i == 0 ? "" : " ",
                     svg_number(p.points[i].x), svg_number(-p.points[i].y));
    fmt::format_to(std::back_inserter(buf_), "\"/>\n");
  }

 private:
  fmt::memory_buffer& buf_;
};

void flush(fmt::memory_buffer& buf, std::ostream& out) {
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
  buf.clear();
}

}  // namespace

std::string svg_number(double v) {
  std::string s = fmt::format("{:.4f}", v);
  while (s.back() == '0')
    s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

WriteResult write_svg(const Drawing& drawing, std::ostream& out) {
  const Box box = finite_view_box(drawing);
  const double w = box.width();
  const double h = box.height();
  const double stroke = std::max(w, h) * kStrokeFraction;
  fmt::memory_buffer buf;
  auto it = std::back_inserter(buf);
  fmt::format_to(it, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
  fmt::format_to(it, "<!-- usina draw: 1 unit = 1 mm, y up (y is written negated) -->\n");
  fmt::format_to(it,
                 "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}mm\" height=\"{}mm\" "
                 "viewBox=\"{} {} {} {}\">\n",
                 svg_number(w), svg_number(h), svg_number(box.min.x), svg_number(-box.max.y),
                 svg_number(w), svg_number(h));
  for (const Layer* layer : drawing.layers()) {
    fmt::format_to(it,
                   "<g id=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" "
                   "stroke-linecap=\"round\" stroke-linejoin=\"round\"",
                   layer->name, hex(layer->style.rgb), svg_number(stroke));
    if (layer->style.dashed)
      fmt::format_to(it, " stroke-dasharray=\"{} {}\"", svg_number(stroke * 8),
                     svg_number(stroke * 5));
    fmt::format_to(it, ">\n");
    SvgEntities entities(buf);
    for (const Entity& e : layer->entities) {
      if (is_finite(e)) std::visit(entities, e);
      if (buf.size() > (1u << 16)) flush(buf, out);
    }
    fmt::format_to(std::back_inserter(buf), "</g>\n");
  }
  fmt::format_to(std::back_inserter(buf), "</svg>\n");
  flush(buf, out);
  if (auto error = drawing.read_error()) return tl::unexpected(*error);
  return {};
}

WriteResult write_svg_file(const Drawing& drawing, const std::string& path,
                           const std::vector<std::string>& inputs) {
  return write_to_file(path, inputs, [&](std::FILE* file) -> WriteResult {
    core::FileOstream out(file);
    const WriteResult written = write_svg(drawing, out);
    out.flush();
    return written;
  });
}

}  // namespace usina::draw
