// A program from a drawing's contours (seed 002, section 4: the CAD sketch
// whose points become the blocks of an NC program), arcs kept as arcs.
#pragma once

#include <vector>

#include "cam/path.hpp"
#include "cam/program.hpp"

namespace usina::cam {

// Where the tool centre runs: on the line, or a tool radius to its left or
// right (seen along the path's direction).
enum class Side { On, Left, Right };

struct FromDxfOptions {
  Cutting cut;
  double depth = 1.0;  // mm below the top
  Side side = Side::On;
  double tolerance = 0.001;  // mm, chords of arcs that an offset turns into polylines
};

// For each path in order: rapid over its first point, plunge to −depth, the
// path, retract. With a side, each path is first offset by the tool radius
// (offset_closed/offset_open: arcs become polylines). False, with nothing
// emitted, after an error (bad value, a contour the tool does not fit).
bool generate_from_paths(const std::vector<Path>& paths, const FromDxfOptions& o, canon::Sink& sink,
                         core::DiagnosticSink& diags);

// The tool-centre paths of `paths` for a side (the paths themselves for
// Side::On); false after E_GEN_TOOL_TOO_BIG.
bool tool_paths(const std::vector<Path>& paths, Side side, double radius, double tolerance,
                std::vector<Path>& out, core::DiagnosticSink& diags);

}  // namespace usina::cam
