// The elliptical pocket cycle (seed 002, section 3.2): at each depth, rings
// from the centre outwards along Y, each an ellipse similar to the pocket by
// the DDA, then a finishing ring. Better than the seed: the finishing ring is
// the inward offset of the ellipse by the tool radius (along its normal, at
// every DDA point), so the wall is the programmed ellipse within the
// resolution, and the finishing pass removes ae_finish everywhere.
#pragma once

#include <vector>

#include "cam/program.hpp"
#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "core/vec3.hpp"

namespace usina::cam {

using core::Vec2;

// The seed's names: ae the stepover, ap the step down (docs/gen.md gives the
// options' names).
struct EllipsePocket {
  Vec2 center;
  double rx = 0;
  double ry = 0;
  double depth = 0;         // below Z0, the top of the part
  double ae = 0;            // stepover of the roughing rings
  double ap = 1.0;          // depth of cut of the roughing levels
  double ae_finish = 0.2;   // stock the finishing ring removes from the wall
  double ap_finish = 0;     // depth of the last level (stock left on the floor)
  double resolution = 0.1;  // the DDA increment, mm
  Cutting cut;              // tool, feeds, spindle, safe Z, the bound on moves
};

// Reports every value out of its range, then the first thing that makes the
// pocket impossible (E_GEN_BAD_VALUE, E_GEN_TOOL_TOO_BIG), then work beyond
// p.cut.max_moves (E_GEN_TOO_MUCH_WORK); true when the pocket can be made.
bool check(const EllipsePocket& p, core::DiagnosticSink& diags);

// The moves of a checked pocket, from above (every DDA clock that steps
// counted as a point), without making any: what check() bounds.
double estimate_moves(const EllipsePocket& p);

enum class RingKind { Roughing, Transition, Finishing };

struct Ring {
  RingKind kind;
  std::vector<Vec2> points;  // absolute, closed, starting on the +Y side of the centre
};

// The passes of a checked pocket (equation 4 with every roughing pass equal).
struct EllipsePlan {
  int roughing_rings = 0;  // I, similar ellipses
  double ae_used = 0;      // their spacing along the major axis (≤ ae)
  double ae_y = 0;         // and along Y (the seed's recomputed ae)
  int transition_rings = 0;
  std::vector<double> z_levels;  // negative, the last at −depth
  double ap_used = 0;            // the roughing levels' step (≤ ap)
};

EllipsePlan plan(const EllipsePocket& p);

// The rings of one level in cutting order: roughing, transition, finishing.
std::vector<Ring> rings(const EllipsePocket& p, const EllipsePlan& plan);

// The whole program as canon ops: tool, spindle, for each level the rings
// joined by moves along Y, the retract and the end. `p` must be checked.
void generate(const EllipsePocket& p, canon::Sink& sink);

// check(), then generate(); false, with nothing emitted, after an error.
bool generate_ellipse_pocket(const EllipsePocket& p, canon::Sink& sink,
                             core::DiagnosticSink& diags);

}  // namespace usina::cam
