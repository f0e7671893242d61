// Drilling patterns: a list of points, a bolt circle, a grid. Each hole is a
// Hole feature followed by its moves (origin Cycle), the moves LinuxCNC's
// G81 (or G83 with a peck) makes in G98 mode: so a post writes the canned
// cycle when the control has it, and the moves when it has not.
#pragma once

#include <vector>

#include "cam/program.hpp"

namespace usina::cam {

// `count` points on a circle, the first at `start_deg` (counter-clockwise
// from +X), equally spaced counter-clockwise.
std::vector<Vec2> bolt_circle(Vec2 center, double radius, int count, double start_deg);

// `nx` × `ny` points from `origin`, `dx` and `dy` apart, row by row, every
// other row walked back (the shorter travel between rows).
std::vector<Vec2> grid(Vec2 origin, int nx, int ny, double dx, double dy);

struct DrillOptions {
  Cutting cut;                  // tool_diameter is the drill's (the Hole's diameter)
  double depth = 5.0;           // mm below the top, to the drill's tip
  double retract = 1.0;         // mm above the top: the R plane each hole starts and ends at
  double peck = 0.0;            // mm per peck (G83), 0 for one feed to the bottom (G81)
  double peck_clearance = 1.0;  // mm above the last peck's bottom the drill comes back down to
};

// Checks, then the holes in the given order. False, with nothing emitted,
// after an error (bad value, no points, R plane above the safe Z).
bool generate_drill(const std::vector<Vec2>& points, const DrillOptions& o, canon::Sink& sink,
                    core::DiagnosticSink& diags);

}  // namespace usina::cam
