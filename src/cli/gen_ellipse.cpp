// usina gen ellipse-pocket: the elliptical pocket cycle of seed 002 by DDA.
#include <memory>

#include "cam/ellipse_pocket.hpp"
#include "cli/deprecated_option.hpp"
#include "cli/gen.hpp"
#include "cli/gen_cam_options.hpp"
#include "cli/post_output.hpp"

namespace usina::cli {
namespace {

struct EllipseOptions {
  cam::EllipsePocket pocket;
  std::vector<double> center{0.0, 0.0};
  PostOutput output;
};

// The seed's names (ae, ap) are the old spellings of the stepover and the
// step down (docs/gen.md, "Names").
void add_pocket_options(CLI::App& cmd, EllipseOptions& o) {
  cam::EllipsePocket& p = o.pocket;
  cmd.add_option("--center", o.center, "centre of the ellipse, X,Y (mm)")
      ->delimiter(',')
      ->expected(2)
      ->capture_default_str();
  cmd.add_option("--rx", p.rx, "radius along X, mm")->required();
  cmd.add_option("--ry", p.ry, "radius along Y, mm")->required();
  cmd.add_option("--depth", p.depth, "depth below Z0 (the top of the part), mm")->required();
  CLI::Option* stepover = cmd.add_option(
      "--stepover", p.ae, "mm between roughing rings, at most the tool diameter (required)");
  add_deprecated_option(cmd, "--ae", stepover, p.ae);
  CLI::Option* step_down =
      cmd.add_option("--step-down", p.ap, "largest depth of one roughing pass, mm")
          ->capture_default_str();
  add_deprecated_option(cmd, "--ap", step_down, p.ap);
  CLI::Option* finish = cmd.add_option("--finish-allowance", p.ae_finish,
                                       "mm the roughing leaves on the wall for the finishing ring")
                            ->capture_default_str();
  add_deprecated_option(cmd, "--ae-finish", finish, p.ae_finish);
  CLI::Option* floor =
      cmd.add_option("--floor-allowance", p.ap_finish,
                     "mm the roughing leaves on the floor for a last level (0: none)")
          ->capture_default_str();
  add_deprecated_option(cmd, "--ap-finish", floor, p.ap_finish);
  cmd.add_option("--resolution", p.resolution, "the DDA increment, mm")->capture_default_str();
  add_cutting_options(cmd, p.cut);
}

}  // namespace

void add_gen_ellipse(CLI::App& gen) {
  auto opts = std::make_shared<EllipseOptions>();
  CLI::App* cmd = gen.add_subcommand("ellipse-pocket",
                                     "clear an elliptical pocket: rings by a DDA interpolator");
  add_pocket_options(*cmd, *opts);
  add_post_options(*cmd, opts->output);
  cmd->callback([opts, cmd] {
    // Required, but under either name: CLI11 cannot require one of two options.
    if (cmd->count("--stepover") + cmd->count("--ae") == 0) {
      throw CLI::RequiredError("--stepover");
    }
    opts->pocket.center = {opts->center.at(0), opts->center.at(1)};
    run_generator("ellipse-pocket", opts->output,
                  [&](canon::Sink& sink, core::DiagnosticSink& diags) {
                    return cam::generate_ellipse_pocket(opts->pocket, sink, diags);
                  });
  });
}

}  // namespace usina::cli
