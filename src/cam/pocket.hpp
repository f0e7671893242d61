// Pocket milling (seed 004, table 7.5, "usinagem de cavidade"): the area
// inside an outline and outside its islands cleared by contour-parallel
// rings a stepover apart, in equal depth passes, each level finished by a
// pass along the walls.
#pragma once

#include <vector>

#include "cam/offset.hpp"
#include "cam/path.hpp"
#include "cam/program.hpp"

namespace usina::cam {

struct PocketShape {
  Path outline;               // closed
  std::vector<Path> islands;  // closed, inside the outline: left standing
};

// A rectangle centred on `center`, its corners rounded with `corner_radius`
// (0 for sharp corners), counter-clockwise from the middle of its bottom side.
Path rectangle(Vec2 center, double width, double height, double corner_radius);

// A circle, counter-clockwise from its rightmost point.
Path circle(Vec2 center, double radius);

// A drawing's chained paths as a pocket: the closed path of the largest area
// is the outline, every other closed path an island inside it. Nullopt after
// an error: an open path (E_GEN_OPEN_OUTLINE), a closed path outside the
// outline or crossing it (E_GEN_BAD_VALUE), no path at all.
std::optional<PocketShape> pocket_shape(const std::vector<Path>& paths,
                                        core::DiagnosticSink& diags);

struct PocketOptions {
  Cutting cut;
  double depth = 1.0;             // mm below the top
  double step_down = 1.0;         // largest depth of one pass (ap)
  double stepover = 2.0;          // mm between rings (ae), at most the tool diameter
  double finish_allowance = 0.2;  // mm the roughing leaves on the walls for the finishing pass
  double tolerance = 0.001;       // mm, chords of arcs and of the offsets' round corners
};

// The rings of one depth level, innermost first, then the walls' finishing
// rings; empty `finish` when the tool does not fit. Exposed for tests.
struct PocketRings {
  std::vector<Ring> roughing;  // innermost first
  std::vector<Ring> finish;    // the walls: outline and islands at a tool radius
};

PocketRings pocket_rings(const PocketShape& shape, const PocketOptions& o);

// Checks, then emits a Pocket feature of the outline and the moves (origin
// Cycle, the feature's expansion). False, with nothing emitted, after an error.
bool generate_pocket(const PocketShape& shape, const PocketOptions& o, canon::Sink& sink,
                     core::DiagnosticSink& diags);

}  // namespace usina::cam
