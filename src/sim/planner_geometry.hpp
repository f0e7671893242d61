// The geometry the planner needs: rates along a move from per-axis limits,
// the speed through a corner (grbl's junction deviation), and arcs (length,
// tangents, true extent).
#pragma once

#include <array>

#include "canon/op.hpp"
#include "sim/machine_profile.hpp"

namespace usina::sim {

using core::Vec3;

// Machine axes X Y Z A B C (rotary in degrees).
using Axes6 = std::array<double, 6>;

// Per-axis share of a move: |Δaxis| per mm of path. A move of path length L
// that moves axis i by Δi runs at path speed v only if |Δi| / L × v stays
// within axis i's rate, so each axis limits the path rate to rate_i / share_i.
struct AxisShare {
  Axes6 share{};
};

// Which per-axis figure limits the move.
enum class AxisRate { Rapid, MaxFeed, Accel, Jerk };

// The most the path may have of `rate` given every present axis's limit
// (a move of axes the profile lacks only: the slowest linear axis's figure;
// for Jerk, 0 when a moving axis has jerk 0 — a trapezoidal profile). `limiting` gets the index of
// the axis that sets it (or -1).
double along_path(const MachineProfile& m, const AxisShare& s, AxisRate rate,
                  int* limiting = nullptr);

// Every rate along_path gives, in one pass over the axes (a straight move
// asks for all of them): the same values.
struct PathRates {
  double rapid = 0.0;
  double max_feed = 0.0;
  int max_feed_axis = -1;  // the axis that sets max_feed (or -1)
  double accel = 0.0;
  double jerk = 0.0;
};

PathRates path_rates(const MachineProfile& m, const AxisShare& s);

// The share of a straight move from `from` to `to` over `length`.
AxisShare straight_share(const Axes6& from, const Axes6& to, double length);

// The highest speed (mm/s) through the corner between a move leaving along
// unit vector `in` and the next one starting along unit vector `out`, so
// that a circle `deviation` mm inside the sharp corner, taken at centripetal
// acceleration `accel`, stays tangent to both (grbl's junction deviation):
// v² = a·δ·sin(θ/2) / (1 − sin(θ/2)), θ the angle between the moves'
// directions seen from the corner. Infinity for collinear moves, 0 for a
// reversal or a zero vector.
double junction_speed(const Vec3& in, const Vec3& out, double deviation, double accel);

// An arc or helix from a start point, as a path.
struct ArcPath {
  Vec3 center;          // in the plane of the start
  Vec3 normal;          // unit
  Vec3 u;               // unit, from the centre towards the start
  Vec3 v;               // normal × u
  double radius = 0.0;  // mm, at the start
  double sweep = 0.0;   // radians, > 0 counter-clockwise about `normal`
  double axial = 0.0;   // mm moved along `normal`
  double length = 0.0;  // mm along the helix
  Vec3 start_tangent;   // unit direction of travel at the start
  Vec3 end_tangent;     // and at the end

  // The point `angle` radians (signed as sweep) from the start.
  Vec3 at(double angle) const;
};

// Nullopt for a degenerate arc (zero radius): the caller moves straight.
std::optional<ArcPath> arc_path(const Vec3& from, const canon::Arc& arc);

// Grows [lo, hi] to hold the whole arc: its end points and the points where
// a coordinate turns back (those inside the sweep).
void arc_extent(const ArcPath& p, Vec3& lo, Vec3& hi);

}  // namespace usina::sim
