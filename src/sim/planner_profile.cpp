#include "sim/planner_profile.hpp"

#include <algorithm>
#include <cmath>

namespace usina::sim {

double change_time(double dv, const Kinematics& k) {
  dv = std::abs(dv);
  if (k.jerk <= 0.0) return dv / k.accel;
  if (dv * k.jerk <= k.accel * k.accel) return 2.0 * std::sqrt(dv / k.jerk);
  return dv / k.accel + k.accel / k.jerk;
}

double change_distance(double v_a, double v_b, const Kinematics& k) {
  return 0.5 * (v_a + v_b) * change_time(v_b - v_a, k);
}

namespace {

// S-curve, acceleration below its limit: with s = sqrt(dv), the distance
// d = (2 v + s²) s / sqrt(j), i.e. f(s) = s³ + 2 v s − d sqrt(j) = 0. f is
// convex and rising for s ≥ 0, so Newton's method from above (q/p and
// cbrt(q) both are: take the smaller) falls monotonically onto the root.
double jerk_limited_rise(double v_end, double length, double jerk) {
  const double p = 2.0 * v_end;
  const double q = length * std::sqrt(jerk);
  double s = p * p * p >= q * q ? q / p : std::cbrt(q);
  for (int i = 0; i < 100; ++i) {
    const double f = s * s * s + p * s - q;
    const double step = f / (3.0 * s * s + p);
    if (!(step > 1e-15 * s)) break;  // at the root (or a rounding step upwards)
    s -= step;
  }
  return std::max(0.0, s * s);
}

// S-curve reaching the acceleration limit: d = (v + dv/2)(dv/a + a/j), a
// quadratic in dv: dv²/(2a) + dv (v/a + a/(2j)) + (v a/j − d) = 0.
double accel_limited_rise(double v_end, double length, const Kinematics& k) {
  const double a2 = 1.0 / (2.0 * k.accel);
  const double b = v_end / k.accel + k.accel / (2.0 * k.jerk);
  const double c = v_end * k.accel / k.jerk - length;
  return (-b + std::sqrt(std::max(0.0, b * b - 4.0 * a2 * c))) / (2.0 * a2);
}

}  // namespace

double reachable_speed(double v_end, double length, const Kinematics& k, double cap) {
  if (length <= 0.0) return std::min(v_end, cap);
  if (k.jerk <= 0.0) return std::min(cap, std::sqrt(v_end * v_end + 2.0 * k.accel * length));
  if (cap <= v_end) return cap;
  if (cap < std::numeric_limits<double>::infinity() && change_distance(v_end, cap, k) <= length) {
    return cap;
  }
  // The change that just reaches the acceleration limit, dv = a²/j, takes
  // 2a/j and covers (v + a²/2j)·2a/j: a longer move is in the quadratic's range.
  const double a2_j = k.accel * k.accel / k.jerk;
  if (length >= (v_end + 0.5 * a2_j) * 2.0 * k.accel / k.jerk) {
    return std::min(cap, v_end + accel_limited_rise(v_end, length, k));
  }
  return std::min(cap, v_end + jerk_limited_rise(v_end, length, k.jerk));
}

namespace {

// Distance to rise from both ends to `peak` and back.
double up_and_down(double v_entry, double v_exit, double peak, const Kinematics& k) {
  return change_distance(v_entry, peak, k) + change_distance(peak, v_exit, k);
}

// d/dpeak of change_distance(v_low, peak): T/2 + (v_low + peak)/2 · dT/ddv.
double change_distance_slope(double v_low, double peak, const Kinematics& k) {
  const double dv = peak - v_low;
  const double slope_t = dv * k.jerk <= k.accel * k.accel
                             ? 1.0 / std::sqrt(std::max(dv, 1e-300) * k.jerk)
                             : 1.0 / k.accel;
  return 0.5 * change_time(dv, k) + 0.5 * (v_low + peak) * slope_t;
}

// The peak speed of a move too short to cruise: the closed form for a
// trapezoid; for an S-curve Newton's method on the distance (which rises
// with the peak), kept inside a bracket that bisection narrows when a step
// leaves it.
double peak_speed(double length, double v_entry, double v_exit, double v_cruise,
                  const Kinematics& k) {
  if (k.jerk <= 0.0) {
    const double peak2 = (2.0 * k.accel * length + v_entry * v_entry + v_exit * v_exit) / 2.0;
    return std::clamp(std::sqrt(peak2), std::max(v_entry, v_exit), v_cruise);
  }
  double lo = std::max(v_entry, v_exit);
  double hi = v_cruise;
  double x = 0.5 * (lo + hi);
  for (int i = 0; i < 100 && hi - lo > 1e-12 * hi; ++i) {
    const double g = up_and_down(v_entry, v_exit, x, k) - length;
    if (std::abs(g) <= 1e-12 * length) return x;
    (g > 0.0 ? hi : lo) = x;
    const double slope = change_distance_slope(v_entry, x, k) + change_distance_slope(v_exit, x, k);
    const double next = x - g / slope;
    x = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
  }
  return lo;
}

}  // namespace

double move_time(double length, double v_entry, double v_exit, double v_cruise,
                 const Kinematics& k) {
  if (length <= 0.0) return 0.0;
  v_cruise = std::max({v_cruise, v_entry, v_exit});
  const double ramps = up_and_down(v_entry, v_exit, v_cruise, k);
  if (ramps <= length) {
    return change_time(v_cruise - v_entry, k) + change_time(v_cruise - v_exit, k) +
           (length - ramps) / v_cruise;
  }
  const double low = std::max(v_entry, v_exit);
  if (up_and_down(v_entry, v_exit, low, k) >= length) {
    // Only the speed change fits (entry and exit planned at the limit).
    return v_entry + v_exit > 0.0 ? 2.0 * length / (v_entry + v_exit) : 0.0;
  }
  const double peak = peak_speed(length, v_entry, v_exit, v_cruise, k);
  return change_time(peak - v_entry, k) + change_time(peak - v_exit, k);
}

}  // namespace usina::sim
