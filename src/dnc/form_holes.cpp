// The forms of the point cycles: a grid of holes, a bolt circle (usina gen
// drill --grid / --bolt-circle, the holes drilled by the post's G81/G83)
// and engraved text (usina gen engrave).
#include <algorithm>
#include <tuple>

#include <fmt/format.h>

#include "cam/drill.hpp"
#include "cam/engrave.hpp"
#include "cam/hershey.hpp"
#include "dnc/form_reading.hpp"

namespace usina::dnc {
namespace {

// A grid spacing may be negative (rows walked the other way).
constexpr cam::Range kSpacing{-cam::kMaxCoordinate, cam::kMaxCoordinate, true, "mm"};
constexpr int kMaxHoles = 100000;

// Depth, R plane and peck; the holes are bare features the post drills.
cam::DrillOptions read_drill_options(FormFields& f, post::PostOptions& post) {
  cam::DrillOptions o;
  o.form = cam::HoleForm::Features;
  o.depth = f.number("depth", "the depth", cam::kLength, std::nullopt);
  o.retract = f.number("retract", "the retract height", cam::kLengthOrZero, 1.0);
  o.peck = f.number("peck", "the peck", cam::kLengthOrZero, 0.0);
  o.cut = read_cutting(f);
  post.peck = o.peck;
  return o;
}

Reading drill_reading(std::vector<cam::Vec2> points, cam::DrillOptions o,
                      std::string_view holes_field) {
  return {[points = std::move(points), o](canon::Sink& sink, core::DiagnosticSink& diags) {
            return cam::generate_drill(points, o, sink, diags);
          },
          {{"retract height", "retract"}, {"peck", "peck"}, {"hole", holes_field}},
          holes_field};
}

// As usina gen drill --grid checks it (gen_drill.cpp).
void check_grid(FormFields& f, int nx, int ny, double dx, double dy) {
  if (!f.ok()) return;
  if (static_cast<double>(nx) * ny > kMaxHoles) {
    f.fail("nx", fmt::format("{} × {} holes are more than {}", nx, ny, kMaxHoles));
    return;
  }
  for (const auto& [n, d, name] : {std::tuple{nx, dx, "dx"}, std::tuple{ny, dy, "dy"}}) {
    if (n > 1 && d == 0.0) {
      f.fail(name, fmt::format("the spacing is 0 with {} holes that way: they would all be "
                               "drilled in one place; give the spacing",
                               n));
    }
  }
}

// A font of /usr/share/hershey-fonts by its name only: never a path.
bool font_name(std::string_view s) {
  return std::all_of(s.begin(), s.end(), [](char ch) {
    return (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_';
  });
}

}  // namespace

Reading read_drill_grid(FormFields& f, post::PostOptions& post) {
  const cam::Vec2 origin = read_point(f, "x0", "y0", "the first hole");
  const int nx = f.whole("nx", "the holes along X", 1, kMaxHoles, std::nullopt);
  const int ny = f.whole("ny", "the holes along Y", 1, kMaxHoles, std::nullopt);
  const double dx = f.number("dx", "the spacing along X", kSpacing, std::nullopt);
  const double dy = f.number("dy", "the spacing along Y", kSpacing, std::nullopt);
  const cam::DrillOptions o = read_drill_options(f, post);
  check_grid(f, nx, ny, dx, dy);
  if (!f.ok()) return {};
  return drill_reading(cam::grid(origin, nx, ny, dx, dy), o, "nx");
}

Reading read_bolt_circle(FormFields& f, post::PostOptions& post) {
  const cam::Vec2 c = read_point(f, "center_x", "center_y", "the bolt circle's centre");
  const double r = f.number("radius", "the bolt circle's radius", cam::kLength, std::nullopt);
  const int n = f.whole("count", "the count of holes", 1, kMaxHoles, std::nullopt);
  const double start = f.number("start_angle", "the start angle", cam::kAngle, 0.0);
  const cam::DrillOptions o = read_drill_options(f, post);
  if (!f.ok()) return {};
  return drill_reading(cam::bolt_circle(c, r, n, start), o, "count");
}

Reading read_engrave(FormFields& f, post::PostOptions&) {
  cam::EngraveOptions o;
  o.text = f.text("text", "the text", static_cast<std::size_t>(cam::kMaxPasses), std::nullopt);
  o.height = f.number("height", "the text height", cam::kLength, std::nullopt);
  o.at = read_point(f, "at_x", "at_y", "the baseline's start");
  o.depth = f.number("depth", "the depth", cam::kLength, 0.2);
  const std::string font = f.text("font", "the font", 40, std::string("rowmans"));
  o.cut = read_cutting(f);
  if (f.ok() && !font_name(font)) {
    f.fail("font",
           "the font is a name of /usr/share/hershey-fonts (rowmans, futural, scripts "
           "...), never a path");
  }
  return {[o, font](canon::Sink& sink, core::DiagnosticSink& diags) {
            const auto face = cam::read_hershey(cam::hershey_file(font), diags);
            return face && cam::generate_engrave(*face, o, sink, diags);
          },
          {{"text's", "at_x"}, {"text height", "height"}, {"text", "text"}},
          "text"};
}

}  // namespace usina::dnc
