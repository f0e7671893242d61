// usina gen pocket: a rectangle, a circle or a drawing's closed outline with
// islands, cleared by contour-parallel rings (seed 004, table 7.5).
#include <memory>

#include "cam/pocket.hpp"
#include "cli/gen_cam_options.hpp"
#include "cli/post_output.hpp"

namespace usina::cli {
namespace {

struct PocketCli {
  ShapeOptions shape;
  cam::PocketOptions gen;
  PostOutput output;
};

}  // namespace

void add_gen_pocket(CLI::App& gen) {
  auto o = std::make_shared<PocketCli>();
  CLI::App* cmd = gen.add_subcommand("pocket", "clear a pocket, islands left standing");
  add_shape_options(*cmd, o->shape);
  cmd->add_option("--depth", o->gen.depth, "depth below Z0 (the top of the part), mm")->required();
  cmd->add_option("--stepover", o->gen.stepover, "mm between rings, at most the tool diameter")
      ->required();
  cmd->add_option("--step-down", o->gen.step_down, "largest depth of one pass, mm")
      ->capture_default_str();
  cmd->add_option("--finish-allowance", o->gen.finish_allowance,
                  "mm the roughing leaves on the walls for the finishing pass")
      ->capture_default_str();
  add_cutting_options(*cmd, o->gen.cut);
  add_post_options(*cmd, o->output);
  cmd->callback([o, cmd] {
    run_generator(
        "pocket", o->output,
        [&](canon::Sink& sink, core::DiagnosticSink& diags) {
          warn_unused_shape_options(*cmd, o->shape, diags);
          const auto paths = shape_paths(o->shape, diags);
          if (!paths) return false;
          const auto shape = cam::pocket_shape(*paths, diags);
          return shape && cam::generate_pocket(*shape, o->gen, sink, diags);
        },
        &o->shape);
  });
}

}  // namespace usina::cli
