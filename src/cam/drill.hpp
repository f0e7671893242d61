// Drilling patterns: a list of points, a bolt circle, a grid, in one of two
// forms (HoleForm):
// - Moves: each hole a Hole feature followed by its moves, all of origin
//   Cycle: the ops usina's interpreter makes of a G81 (G83 with a peck) in
//   G98 mode, so a drawing, a simulation or a trace sees every move, and a
//   post writes the moves as plain blocks (a conversion expands cycles);
// - Features: each hole a bare Hole feature (origin Program) and no moves, so
//   the post drills it: G81/G83 where the control has canned cycles, the
//   same moves where it has not. Each hole carries its feed rate (the
//   plunge feed), so the program goes from the safe Z over the first hole
//   straight into its cycle: to R at rapid, as a control's cycle does.
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

enum class HoleForm { Moves, Features };

struct DrillOptions {
  HoleForm form = HoleForm::Moves;
  Cutting cut;                  // tool_diameter is the drill's (the Hole's diameter)
  double depth = 5.0;           // mm below the top, to the drill's tip
  double retract = 1.0;         // mm above the top: the R plane each hole starts and ends at
  double peck = 0.0;            // mm per peck (G83), 0 for one feed to the bottom (G81)
  double peck_clearance = 1.0;  // mm above the last peck's bottom the drill comes back down to
  // Tapping (G84 as moves) when above 0: the thread's pitch, mm. The feed
  // is then the pitch a revolution (cut.feed is not read), the spindle
  // reverses at the bottom and the tap feeds back out to R.
  double pitch = 0.0;
  // Boring (G85) when set: the bar is fed to the bottom and fed back out to
  // R at the feed (a rapid out would drag its edge along the finished
  // wall), then rapids to the safe Z. Not pecked, not tapped.
  bool bore = false;
  // How a bore leaves the hole: Bore (G85, fed out, the default);
  // BoreDwell (G89: `dwell` s at the bottom, then fed out); BoreStop (G86:
  // the spindle stopped at the bottom, out at rapid, started again).
  canon::HoleCycle bore_cycle = canon::HoleCycle::Bore;
  double dwell = 0.0;  // s at the bottom, G89 only
};

// The longest dwell at a bore's bottom, s: a few turns of the bar clean a
// shoulder in a fraction of a second; a minute is a slip of units (ms).
constexpr double kMaxBoreDwell = 60.0;

// Checks, then the holes in the given order. False, with nothing emitted,
// after an error (bad value, no points, R plane above the safe Z).
bool generate_drill(const std::vector<Vec2>& points, const DrillOptions& o, canon::Sink& sink,
                    core::DiagnosticSink& diags);

}  // namespace usina::cam
