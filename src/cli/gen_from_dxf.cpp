// usina gen from-dxf: a program from a drawing's contours (seed 002,
// section 4), arcs kept as G2/G3.
#include <memory>

#include "cam/chain.hpp"
#include "cam/dxf_import.hpp"
#include "cam/from_dxf.hpp"
#include "cli/deprecated_option.hpp"
#include "cli/gen_cam_options.hpp"
#include "cli/post_output.hpp"

namespace usina::cli {
namespace {

struct FromDxfCli {
  std::string drawing;  // the old positional spelling of --dxf
  ShapeOptions shape;
  cam::FromDxfOptions gen;
  std::string side = "on";
  PostOutput output;
};

}  // namespace

void add_gen_from_dxf(CLI::App& gen) {
  auto o = std::make_shared<FromDxfCli>();
  CLI::App* cmd =
      gen.add_subcommand("from-dxf", "cut the contours of a DXF drawing, arcs kept as arcs");
  cmd->add_option("--dxf", o->shape.dxf, "the DXF drawing (required)");
  // Pocket and profile name their drawing with --dxf; a positional is the
  // old spelling (docs/gen.md, "Names"), taken from the extras so that it
  // stays out of --help.
  cmd->allow_extras();
  add_dxf_options(*cmd, o->shape);
  cmd->add_option("--depth", o->gen.depth, "depth below Z0 (the top of the part), mm")
      ->capture_default_str();
  cmd->add_option("--side", o->side,
                  "where the tool centre runs: on the line, or a tool radius to its left or "
                  "right (offset by Clipper: arcs become lines)")
      ->check(CLI::IsMember({"on", "left", "right"}))
      ->capture_default_str();
  add_cutting_options(*cmd, o->gen.cut);
  add_post_options(*cmd, o->output);
  cmd->callback([o, cmd] {
    const std::vector<std::string> extras = cmd->remaining();
    if (extras.size() > 1 || (extras.size() == 1 && extras[0].starts_with("-"))) {
      throw CLI::ExtrasError(extras);
    }
    if (extras.size() == 1) o->drawing = extras[0];
    if (!o->drawing.empty()) {
      if (!o->shape.dxf.empty()) {
        throw CLI::ValidationError("DRAWING", "the drawing is given twice (--dxf and before it)");
      }
      warn_deprecated("the drawing as a positional argument", "--dxf DRAWING");
      o->shape.dxf = o->drawing;
    }
    if (o->shape.dxf.empty()) throw CLI::RequiredError("--dxf");
    o->gen.side = o->side == "left"    ? cam::Side::Left
                  : o->side == "right" ? cam::Side::Right
                                       : cam::Side::On;
    run_generator(
        "from-dxf", o->output,
        [&](canon::Sink& sink, core::DiagnosticSink& diags) {
          const auto paths = shape_paths(o->shape, diags);
          return paths && cam::generate_from_paths(*paths, o->gen, sink, diags);
        },
        &o->shape);
  });
}

}  // namespace usina::cli
