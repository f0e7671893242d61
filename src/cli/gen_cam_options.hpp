// What the cam generators' subcommands share (usina gen from-dxf, pocket,
// profile, drill, engrave): the cutting options, a shape given as a
// rectangle, a circle or a DXF drawing, and running a generator into the
// post (cli/post_output.hpp: --post, -o, and the program's options).
#pragma once

#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cam/path.hpp"
#include "cam/program.hpp"
#include "canon/sink.hpp"
#include "core/diagnostic.hpp"

namespace usina::cli {

// --tool-diameter --feed --plunge-feed --rpm --safe-z --tool --max-moves
void add_cutting_options(CLI::App& cmd, cam::Cutting& c);

// One of --rect W,H (with --corner-radius), --circle R (both about --center
// X,Y) or --dxf FILE (with --layer, --spline-tolerance).
struct ShapeOptions {
  std::vector<double> rect;
  double circle = 0.0;
  std::vector<double> center{0.0, 0.0};
  double corner_radius = 0.0;
  std::string dxf;
  std::string layer;
  double spline_tolerance = 0.01;
};

void add_shape_options(CLI::App& cmd, ShapeOptions& s);
// --layer and --spline-tolerance only (from-dxf names its drawing itself).
void add_dxf_options(CLI::App& cmd, ShapeOptions& s);

// W_GEN_NO_EFFECT for each option of `names` given on `cmd` when `used` is
// false: an option that changes nothing is said, not silently ignored.
void warn_unused(const CLI::App& cmd, std::initializer_list<const char*> names, bool used,
                 std::string_view why, core::DiagnosticSink& diags);

// The same for the shape's options that the shape given does not use
// (--corner-radius without --rect, --center or --layer with --dxf ...).
void warn_unused_shape_options(const CLI::App& cmd, const ShapeOptions& s,
                               core::DiagnosticSink& diags);

// The shape's contours: the rectangle or circle, or the drawing's entities
// chained; nullopt after an error (reported).
std::optional<std::vector<cam::Path>> shape_paths(const ShapeOptions& s,
                                                  core::DiagnosticSink& diags);

// Runs `generate` (it returns whether it succeeded, its errors reported)
// into the post chosen by the PostOutput options; sets the exit status:
// 0, or 2 when the generator failed (a value out of range, a shape the tool
// cannot cut, too much work: usage errors, docs/gen.md). The generator's
// own diagnostics read "usina: error: gen NAME: message [CODE]".
// `shape`, when given, names the drawing the generator reads, which the
// output may never be.
struct PostOutput;
void run_generator(std::string_view name, PostOutput out,
                   const std::function<bool(canon::Sink&, core::DiagnosticSink&)>& generate,
                   const ShapeOptions* shape = nullptr);

}  // namespace usina::cli
