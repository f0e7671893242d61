// Shared options of the cam generators; see gen_cam_options.hpp.
#include "cli/gen_cam_options.hpp"

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "cam/chain.hpp"
#include "cam/dxf_import.hpp"
#include "cam/limits.hpp"
#include "cam/pocket.hpp"
#include "cli/post_output.hpp"
#include "cli/verbs.hpp"

namespace usina::cli {
namespace {

// A generator's own diagnostics have no place in a file: they are rendered
// with the verb's name. Those with a place (a drawing's) go to the post's sink.
class GenDiagnostics final : public core::DiagnosticSink {
 public:
  GenDiagnostics(std::string_view name, PostDiagnostics& located)
      : name_(name), located_(located) {}

  void report(core::Diagnostic d) override {
    if (d.loc.file != 0 || d.loc.line != 0) return located_.report(std::move(d));
    fmt::print(stderr, "usina: {}: gen {}: {} [{}]\n", core::severity_name(d.severity), name_,
               d.message, core::code_name(d.code));
  }

 private:
  std::string_view name_;
  PostDiagnostics& located_;
};

bool check_rectangle(const ShapeOptions& s, core::DiagnosticSink& diags) {
  const double w = s.rect.at(0);
  const double h = s.rect.at(1);
  bool ok = cam::check_range("the rectangle's width (--rect W,H)", w, cam::kLength, diags);
  ok = cam::check_range("the rectangle's height (--rect W,H)", h, cam::kLength, diags) && ok;
  ok = cam::check_range("the corner radius (--corner-radius)", s.corner_radius, cam::kLengthOrZero,
                        diags) &&
       ok;
  if (ok && 2 * s.corner_radius > std::min(w, h)) {
    ok = cam::fail(diags, core::Code::GenBadValue,
                   fmt::format("the corner radius {:g} mm is more than half the rectangle's "
                               "side {:g} mm",
                               s.corner_radius, std::min(w, h)));
  }
  return ok;
}

}  // namespace

void add_cutting_options(CLI::App& cmd, cam::Cutting& c) {
  cmd.add_option("--tool-diameter", c.tool_diameter, "mm")->capture_default_str();
  cmd.add_option("--feed", c.feed, "mm/min in the plane")->capture_default_str();
  cmd.add_option("--plunge-feed", c.plunge_feed, "mm/min down into the part")
      ->capture_default_str();
  cmd.add_option("--rpm", c.rpm, "spindle speed, rev/min, clockwise")->capture_default_str();
  cmd.add_option("--safe-z", c.safe_z, "rapid level above the top of the part (Z0), mm")
      ->capture_default_str();
  cmd.add_option("--tool", c.tool, "tool number")
      ->check(CLI::Range(0, 99999))
      ->capture_default_str();
  cmd.add_option("--max-moves", c.max_moves,
                 "refuse to generate more moves than this (about 18 bytes of G-code each)")
      ->default_str(fmt::format("{:.0f}", c.max_moves));
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

void warn_unused(const CLI::App& cmd, std::initializer_list<const char*> names, bool used,
                 std::string_view why, core::DiagnosticSink& diags) {
  if (used) return;
  for (const char* name : names) {
    if (cmd.count(name) == 0) continue;
    diags.report({core::Code::GenNoEffect,
                  core::Severity::Warning,
                  {},
                  fmt::format("{} changes nothing {}", name, why)});
  }
}

void warn_unused_shape_options(const CLI::App& cmd, const ShapeOptions& s,
                               core::DiagnosticSink& diags) {
  warn_unused(cmd, {"--corner-radius"}, !s.rect.empty(), "without --rect", diags);
  warn_unused(cmd, {"--center"}, s.dxf.empty(), "with --dxf (the drawing has its own place)",
              diags);
  warn_unused(cmd, {"--layer", "--spline-tolerance"}, !s.dxf.empty(), "without --dxf", diags);
}

std::optional<std::vector<cam::Path>> shape_paths(const ShapeOptions& s,
                                                  core::DiagnosticSink& diags) {
  const cam::Vec2 c{s.center.at(0), s.center.at(1)};
  if (!cam::check_point("the centre (--center)", c, diags)) return std::nullopt;
  if (!s.rect.empty()) {
    if (!check_rectangle(s, diags)) return std::nullopt;
    return std::vector<cam::Path>{cam::rectangle(c, s.rect.at(0), s.rect.at(1), s.corner_radius)};
  }
  if (s.dxf.empty()) {
    if (!cam::check_range("the circle's radius (--circle)", s.circle, cam::kLength, diags)) {
      return std::nullopt;
    }
    return std::vector<cam::Path>{cam::circle(c, s.circle)};
  }
  cam::DxfOptions o;
  if (!s.layer.empty()) o.layer = s.layer;
  o.spline_tolerance = s.spline_tolerance;
  if (!cam::check_range("the spline tolerance (--spline-tolerance)", o.spline_tolerance,
                        cam::kTolerance, diags)) {
    return std::nullopt;
  }
  auto entities = cam::read_dxf(s.dxf, o, diags);
  if (!entities) return std::nullopt;
  return cam::chain(std::move(*entities));
}

void run_generator(std::string_view name, PostOutput out,
                   const std::function<bool(canon::Sink&, core::DiagnosticSink&)>& generate,
                   const ShapeOptions* shape) {
  if (shape != nullptr) out.inputs.push_back(shape->dxf);  // never written over
  set_exit_status(write_program(out, [&](canon::Sink& sink, PostDiagnostics& post_diags) {
    GenDiagnostics diags(name, post_diags);
    return generate(sink, diags) ? 0 : 2;
  }));
}

}  // namespace usina::cli
