// Velocity profiles of one move along its path: trapezoidal (constant
// acceleration) when jerk is 0, otherwise S-curve (jerk-limited, the
// acceleration ramping at ±jerk). Speeds in mm/s, lengths in mm,
// accelerations in mm/s², jerk in mm/s³.
//
// An S-curve speed change of dv is symmetric about its middle, so it covers
// (v_start + v_end) / 2 × its time; its time is 2·sqrt(dv / jerk) when the
// acceleration never reaches its limit (dv ≤ a² / j), else dv / a + a / j.
#pragma once

#include <limits>

namespace usina::sim {

struct Kinematics {
  double accel = 0.0;  // mm/s², above zero
  double jerk = 0.0;   // mm/s³; 0 = trapezoidal
};

// Time to change speed by |dv|.
double change_time(double dv, const Kinematics& k);

// Distance covered while changing speed between `v_a` and `v_b` (either order).
double change_distance(double v_a, double v_b, const Kinematics& k);

// The highest speed from which the move can change to `v_end` within `length`
// (by symmetry also the highest speed reachable from `v_end`), at most `cap`:
// a cap the move can reach is returned at the cost of one distance, without
// solving for the speed (the planner's usual case, and the S-curve's costly one).
double reachable_speed(double v_end, double length, const Kinematics& k,
                       double cap = std::numeric_limits<double>::infinity());

// Time of a move of `length` entering at `v_entry`, leaving at `v_exit`,
// cruising at most at `v_cruise`: accelerate, cruise, decelerate, the
// cruise left out (a triangular profile) when the move is too short.
// The entry and exit must be reachable from each other within `length`.
double move_time(double length, double v_entry, double v_exit, double v_cruise,
                 const Kinematics& k);

}  // namespace usina::sim
