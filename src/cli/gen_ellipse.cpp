// usina gen ellipse-pocket: the elliptical pocket cycle of seed 002 by DDA.
#include <cstdio>
#include <memory>

#include <fmt/format.h>

#include "cam/ellipse_pocket.hpp"
#include "cli/gen.hpp"
#include "cli/post_output.hpp"
#include "cli/verbs.hpp"

namespace usina::cli {
namespace {

struct EllipseOptions {
  cam::EllipsePocket pocket;
  std::vector<double> center;
  PostOutput output;
};

void add_pocket_options(CLI::App& cmd, EllipseOptions& o) {
  cam::EllipsePocket& p = o.pocket;
  cmd.add_option("--center", o.center, "centre of the ellipse, X,Y (mm)")
      ->required()
      ->delimiter(',')
      ->expected(2);
  cmd.add_option("--rx", p.rx, "radius along X, mm")->required();
  cmd.add_option("--ry", p.ry, "radius along Y, mm")->required();
  cmd.add_option("--depth", p.depth, "depth below Z0 (the top of the part), mm")->required();
  cmd.add_option("--tool-diameter", p.tool_diameter, "mm")->required();
  cmd.add_option("--ae", p.ae, "roughing stepover (penetração de trabalho), mm")->required();
  cmd.add_option("--ap", p.ap, "roughing depth of cut (profundidade de corte), mm")->required();
  cmd.add_option("--ae-finish", p.ae_finish, "stock the finishing ring removes from the wall, mm")
      ->capture_default_str();
  cmd.add_option("--ap-finish", p.ap_finish, "depth of cut of the last level, mm")
      ->capture_default_str();
  cmd.add_option("--resolution", p.resolution, "the DDA increment, mm")->capture_default_str();
  cmd.add_option("--feed", p.feed, "mm/min")->capture_default_str();
  cmd.add_option("--plunge-feed", p.plunge_feed, "mm/min")->capture_default_str();
  cmd.add_option("--rpm", p.rpm, "spindle speed")->capture_default_str();
  cmd.add_option("--safe-z", p.safe_z, "rapid level above the part, mm")->capture_default_str();
  cmd.add_option("--tool", p.tool, "tool number")
      ->check(CLI::Range(0, 99999))
      ->capture_default_str();
}

}  // namespace

void add_gen_ellipse(CLI::App& gen) {
  auto opts = std::make_shared<EllipseOptions>();
  CLI::App* cmd = gen.add_subcommand("ellipse-pocket", "elliptical pocket by DDA (seed 002)");
  add_pocket_options(*cmd, *opts);
  add_post_options(*cmd, opts->output);
  cmd->callback([opts] {
    opts->pocket.center = {opts->center.at(0), opts->center.at(1)};
    if (auto bad = cam::check(opts->pocket)) {
      fmt::print(stderr, "usina: error: ellipse-pocket: {}\n", *bad);
      set_exit_status(2);
      return;
    }
    set_exit_status(write_program(opts->output, [&](canon::Sink& sink, PostDiagnostics&) {
      cam::generate(opts->pocket, sink);
      return 0;
    }));
  });
}

}  // namespace usina::cli
