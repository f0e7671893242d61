// The elliptical pocket cycle (seed 002, section 3.2): at each depth, rings
// from the centre outwards along Y, each an ellipse similar to the pocket by
// the DDA, then a finishing ring. Better than the seed: the finishing ring is
// the inward offset of the ellipse by the tool radius (along its normal, at
// every DDA point), so the wall is the programmed ellipse within the
// resolution, and the finishing pass removes ae_finish everywhere.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "canon/sink.hpp"
#include "core/vec3.hpp"

namespace usina::cam {

using core::Vec2;

struct EllipsePocket {
  Vec2 center;
  double rx = 0;
  double ry = 0;
  double depth = 0;  // below Z0, the top of the part
  double tool_diameter = 0;
  double ae = 0;         // stepover of the roughing rings
  double ap = 0;         // depth of cut of the roughing levels
  double ae_finish = 0;  // stock the finishing ring removes from the wall
  double ap_finish = 0;  // depth of the last level
  double resolution = 0.1;
  double feed = 300;         // mm/min
  double plunge_feed = 100;  // mm/min
  double rpm = 3000;
  double safe_z = 5;
  int tool = 1;
};

// A message for the first thing wrong with `p`, or nothing.
std::optional<std::string> check(const EllipsePocket& p);

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
// joined by moves along Y, the retract and the end.
void generate(const EllipsePocket& p, canon::Sink& sink);

}  // namespace usina::cam
