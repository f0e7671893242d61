// usina gen profile: around a contour, inside or outside, with lead arcs and
// tabs (seed 004, table 7.5).
#include <memory>

#include "cam/profile.hpp"
#include "cli/gen_cam_options.hpp"
#include "cli/post_output.hpp"

namespace usina::cli {
namespace {

struct ProfileCli {
  ShapeOptions shape;
  cam::ProfileOptions gen;
  std::string side = "outside";
  PostOutput output;
};

}  // namespace

void add_gen_profile(CLI::App& gen) {
  auto o = std::make_shared<ProfileCli>();
  CLI::App* cmd = gen.add_subcommand("profile", "cut around a contour, with leads and tabs");
  add_shape_options(*cmd, o->shape);
  cmd->add_option("--depth", o->gen.depth, "depth below Z0 (the top of the part), mm")->required();
  cmd->add_option("--side", o->side,
                  "outside or inside a closed contour; auto: outside the outlines and inside "
                  "the holes (by nesting); left or right of an open one (along its drawn "
                  "direction); on the line")
      ->check(CLI::IsMember({"outside", "inside", "left", "right", "on", "auto"}))
      ->capture_default_str();
  cmd->add_option("--step-down", o->gen.step_down, "largest depth of one pass, mm")
      ->capture_default_str();
  cmd->add_option("--lead-radius", o->gen.lead_radius, "tangent lead-in/out arcs, mm (0: none)")
      ->capture_default_str();
  cmd->add_option("--tabs", o->gen.tabs.count, "tabs holding the part (0: none)")
      ->capture_default_str();
  cmd->add_option("--tab-width", o->gen.tabs.width, "mm of material along the contour")
      ->capture_default_str();
  cmd->add_option("--tab-height", o->gen.tabs.height, "mm of material above the bottom")
      ->capture_default_str();
  add_cutting_options(*cmd, o->gen.cut);
  add_post_options(*cmd, o->output);
  cmd->callback([o, cmd] {
    o->gen.side = cam::profile_side(o->side).value_or(cam::ProfileSide::Outside);
    run_generator(
        "profile", o->output,
        [&](canon::Sink& sink, core::DiagnosticSink& diags) {
          warn_unused_shape_options(*cmd, o->shape, diags);
          warn_unused(*cmd, {"--tab-width", "--tab-height"}, o->gen.tabs.count > 0,
                      "without --tabs", diags);
          const auto paths = shape_paths(o->shape, diags);
          return paths && cam::generate_profile(*paths, o->gen, sink, diags);
        },
        &o->shape);
  });
}

}  // namespace usina::cli
