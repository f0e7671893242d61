// usina gen drill: holes at points, on a bolt circle or in a grid; G81/G83
// where the control has canned cycles (the post's --peck chooses G83), the
// same moves elsewhere.
#include <cmath>
#include <memory>
#include <tuple>

#include <fmt/format.h>

#include "cam/drill.hpp"
#include "cam/limits.hpp"
#include "cli/gen_cam_options.hpp"
#include "cli/post_output.hpp"

namespace usina::cli {
namespace {

struct DrillCli {
  std::vector<std::vector<double>> at;
  std::vector<double> bolt_circle;  // CX,CY,R,N[,A]
  std::vector<double> grid;         // X0,Y0,NX,NY,DX,DY
  bool expand = false;
  cam::DrillOptions gen;
  PostOutput output;
};

bool whole(double v) {
  return std::isfinite(v) && v >= 1 && v <= 100000 && v == std::floor(v);
}

bool bolt_circle_points(const std::vector<double>& b, std::vector<cam::Vec2>& pts,
                        core::DiagnosticSink& diags) {
  if (b.size() < 4 || b.size() > 5 || !whole(b[3])) {
    return cam::fail(diags, core::Code::GenBadValue,
                     "--bolt-circle is CX,CY,RADIUS,COUNT or CX,CY,RADIUS,COUNT,START_ANGLE, "
                     "COUNT a whole number from 1 to 100000");
  }
  const double start = b.size() == 5 ? b[4] : 0.0;
  bool ok = cam::check_point("the bolt circle's centre", {b[0], b[1]}, diags);
  ok = cam::check_range("the bolt circle's radius", b[2], cam::kLength, diags) && ok;
  ok = cam::check_range("the bolt circle's start angle", start, cam::kAngle, diags) && ok;
  if (!ok) return false;
  pts = cam::bolt_circle({b[0], b[1]}, b[2], static_cast<int>(b[3]), start);
  return true;
}

// A grid of NX by NY holes DX and DY apart: a spacing of 0 along a row of
// more than one hole would drill them all in one place.
bool grid_points(const std::vector<double>& g, std::vector<cam::Vec2>& pts,
                 core::DiagnosticSink& diags) {
  if (g.size() != 6 || !whole(g[2]) || !whole(g[3]) || g[2] * g[3] > 100000) {
    return cam::fail(diags, core::Code::GenBadValue,
                     "--grid is X0,Y0,NX,NY,DX,DY, NX and NY whole numbers, at most 100000 "
                     "holes");
  }
  for (const auto& [n, d, name] : {std::tuple{g[2], g[4], "DX"}, std::tuple{g[3], g[5], "DY"}}) {
    if (n > 1 && (!std::isfinite(d) || d == 0.0)) {
      return cam::fail(diags, core::Code::GenBadValue,
                       fmt::format("--grid's {} is {:g} with {:g} holes that way: they would all "
                                   "be drilled in one place; give the spacing",
                                   name, d, n));
    }
  }
  pts = cam::grid({g[0], g[1]}, static_cast<int>(g[2]), static_cast<int>(g[3]), g[4], g[5]);
  return true;
}

// The points of whichever pattern was given; false after an error. Each
// point is checked against the coordinate range by the generator.
bool points_of(const DrillCli& o, std::vector<cam::Vec2>& pts, core::DiagnosticSink& diags) {
  for (const auto& p : o.at)
    pts.push_back({p.at(0), p.at(1)});
  if (!o.bolt_circle.empty()) return bolt_circle_points(o.bolt_circle, pts, diags);
  if (!o.grid.empty()) return grid_points(o.grid, pts, diags);
  return true;
}

}  // namespace

void add_gen_drill(CLI::App& gen) {
  auto o = std::make_shared<DrillCli>();
  CLI::App* cmd = gen.add_subcommand("drill", "drill holes: points, a bolt circle, a grid");
  CLI::Option_group* pattern = cmd->add_option_group("pattern", "exactly one of");
  pattern->add_option("--at", o->at, "a hole at X,Y (repeat for more)")
      ->delimiter(',')
      ->expected(2)
      ->allow_extra_args(false);
  pattern
      ->add_option("--bolt-circle", o->bolt_circle,
                   "CX,CY,RADIUS,COUNT[,START_ANGLE]: COUNT holes equally spaced "
                   "counter-clockwise from START_ANGLE degrees (default 0, +X)")
      ->delimiter(',');
  pattern->add_option("--grid", o->grid, "X0,Y0,NX,NY,DX,DY: NX by NY holes, rows walked in turn")
      ->delimiter(',');
  pattern->require_option(1);
  cmd->add_option("--depth", o->gen.depth, "depth of the drill's tip below Z0, mm")->required();
  cmd->add_option("--retract", o->gen.retract, "the R plane above Z0, mm")->capture_default_str();
  cmd->add_flag("--expand", o->expand,
                "write every hole's moves, not G81/G83, whatever the control");
  add_cutting_options(*cmd, o->gen.cut);
  add_post_options(*cmd, o->output);
  cmd->callback([o] {
    o->gen.form = o->expand ? cam::HoleForm::Moves : cam::HoleForm::Features;
    o->gen.peck = o->output.options.peck;
    o->gen.peck_clearance = o->output.options.peck_clearance;
    run_generator("drill", o->output, [&](canon::Sink& sink, core::DiagnosticSink& diags) {
      std::vector<cam::Vec2> pts;
      return points_of(*o, pts, diags) && cam::generate_drill(pts, o->gen, sink, diags);
    });
  });
}

}  // namespace usina::cli
