// Shared options of the cam generators; see gen_cam_options.hpp. Needs the
// post module's cli/post_output.hpp (issue 5's other half): until it is in
// the tree, this file and the generators' subcommands compile to nothing.
#include "cli/gen_cam_options.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "cam/chain.hpp"
#include "cam/dxf_import.hpp"
#include "cam/pocket.hpp"
#include "cli/post_output.hpp"
#include "cli/verbs.hpp"

namespace usina::cli {

void add_cutting_options(CLI::App& cmd, cam::Cutting& c) {
  cmd.add_option("--tool-diameter", c.tool_diameter, "mm")->capture_default_str();
  cmd.add_option("--feed", c.feed, "mm/min")->capture_default_str();
  cmd.add_option("--plunge-feed", c.plunge_feed, "mm/min")->capture_default_str();
  cmd.add_option("--rpm", c.rpm, "spindle speed, rev/min")->capture_default_str();
  cmd.add_option("--safe-z", c.safe_z, "rapid level above the top of the part (Z0), mm")
      ->capture_default_str();
  cmd.add_option("--tool", c.tool, "tool number")
      ->check(CLI::Range(0, 99999))
      ->capture_default_str();
}

void add_dxf_options(CLI::App& cmd, ShapeOptions& s) {
  cmd.add_option("--layer", s.layer, "only this layer of the drawing");
  cmd.add_option("--spline-tolerance", s.spline_tolerance, "mm between a SPLINE and its chords")
      ->capture_default_str();
}

void add_shape_options(CLI::App& cmd, ShapeOptions& s) {
  CLI::Option_group* shape = cmd.add_option_group("shape", "exactly one of");
  shape->add_option("--rect", s.rect, "a rectangle W,H (mm)")->delimiter(',')->expected(2);
  shape->add_option("--circle", s.circle, "a circle of this radius (mm)");
  shape->add_option("--dxf", s.dxf, "the contours of a DXF drawing");
  shape->require_option(1);
  cmd.add_option("--center", s.center, "centre of the rectangle or circle, X,Y (mm)")
      ->delimiter(',')
      ->expected(2)
      ->capture_default_str();
  cmd.add_option("--corner-radius", s.corner_radius, "the rectangle's corners, mm")
      ->capture_default_str();
  add_dxf_options(cmd, s);
}

std::optional<std::vector<cam::Path>> shape_paths(const ShapeOptions& s,
                                                  core::DiagnosticSink& diags) {
  const cam::Vec2 c{s.center.at(0), s.center.at(1)};
  if (!s.rect.empty()) {
    const double w = s.rect.at(0);
    const double h = s.rect.at(1);
    bool ok = cam::check_positive("the rectangle's width", w, "mm", diags);
    ok = cam::check_positive("the rectangle's height", h, "mm", diags) && ok;
    ok = cam::check_positive("the corner radius", s.corner_radius, "mm", diags, true) && ok;
    if (ok && 2 * s.corner_radius > std::min(w, h)) {
      ok = cam::fail(diags, core::Code::GenBadValue,
                     fmt::format("the corner radius {:g} mm is more than half the rectangle's "
                                 "side {:g} mm",
                                 s.corner_radius, std::min(w, h)));
    }
    if (!ok) return std::nullopt;
    return std::vector<cam::Path>{cam::rectangle(c, w, h, s.corner_radius)};
  }
  if (s.dxf.empty()) {
    if (!cam::check_positive("the circle's radius", s.circle, "mm", diags)) return std::nullopt;
    return std::vector<cam::Path>{cam::circle(c, s.circle)};
  }
  cam::DxfOptions o;
  if (!s.layer.empty()) o.layer = s.layer;
  o.spline_tolerance = s.spline_tolerance;
  if (!cam::check_positive("the spline tolerance", o.spline_tolerance, "mm", diags)) {
    return std::nullopt;
  }
  auto entities = cam::read_dxf(s.dxf, o, diags);
  if (!entities) return std::nullopt;
  return cam::chain(std::move(*entities));
}

void run_generator(const PostOutput& out,
                   const std::function<bool(canon::Sink&, core::DiagnosticSink&)>& generate) {
  set_exit_status(write_program(out, [&](canon::Sink& sink, PostDiagnostics& diags) {
    return generate(sink, diags) ? 0 : 2;
  }));
}

}  // namespace usina::cli
