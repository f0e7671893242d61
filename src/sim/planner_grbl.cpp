#include "sim/planner_grbl.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace usina::sim {

using core::Vec3;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Rotates `v` by `angle` about unit axis `n` (Rodrigues).
Vec3 rotate(const Vec3& v, const Vec3& n, double angle) {
  return v * std::cos(angle) + cross(n, v) * std::sin(angle) +
         n * (dot(n, v) * (1.0 - std::cos(angle)));
}

Vec3 unit(const Vec3& v) {
  const double n = norm(v);
  return n > 0.0 ? v / n : Vec3{};
}

}  // namespace

GrblPlanner::GrblPlanner(const MachineProfile& machine)
    : machine_(machine), look_(PlannerSettings{machine.junction_deviation, kGrblBlockBuffer}) {
  for (std::size_t i = 0; i < 3; ++i) {
    accel_[i] = machine.axes[i].present ? machine.axes[i].accel : 0.0;
    rate_[i] = machine.axes[i].present ? machine.axes[i].max_feed / 60.0 : 0.0;
  }
}

double GrblPlanner::along(const Vec3& u, const double limits[3]) {
  double best = kInf;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(u[i]) > 1e-12 && limits[i] > 0.0)
      best = std::min(best, limits[i] / std::abs(u[i]));
  }
  return best;
}

// motion_control.c mc_arc: segments = floor(½·|sweep|·r / √(tol·(2r − tol))).
std::uint64_t GrblPlanner::arc_segments(double radius, double sweep, double tolerance) {
  if (!(tolerance > 0.0) || !(radius > tolerance / 2.0)) return 1;
  const double n = std::floor(0.5 * std::abs(sweep) * radius /
                              std::sqrt(tolerance * (2.0 * radius - tolerance)));
  return n >= 1.0 ? static_cast<std::uint64_t>(std::min(n, 1e7)) : 1;
}

void GrblPlanner::add(const PlannedMove& move) {
  if (!(move.length > 0.0 && move.cruise > 0.0 && std::isfinite(move.length))) return;
  if (exact_stop_.size() <= move.account) exact_stop_.resize(move.account + 1);
  const double t = move_time(move.length, 0.0, 0.0, move.cruise, move.kin);
  if (t >= 0.0 && std::isfinite(t)) exact_stop_[move.account].exact_stop_s += t;
  if (move.radius <= 0.0) {
    block(move);
    return;
  }
  // The arc as mc_arc sends it: chords at the programmed feed.
  const std::uint64_t n = arc_segments(move.radius, move.sweep, machine_.arc_tolerance);
  const double step = move.sweep / static_cast<double>(n);
  const double planar = 2.0 * move.radius * std::sin(std::abs(step) / 2.0);
  const double rise = move.axial / static_cast<double>(n);
  // The tangent at the start, without its rise, turned through half a step
  // is the first chord's planar direction.
  const Vec3 normal = unit(move.normal);
  const Vec3 flat = unit(move.start_dir - normal * dot(move.start_dir, normal));
  const double feed = move.uncapped > 0.0 ? move.uncapped : move.cruise;
  for (std::uint64_t k = 0; k < n; ++k) {
    const double angle = step * (static_cast<double>(k) + 0.5);
    const Vec3 chord = rotate(flat, normal, angle) * planar + normal * rise;
    PlannedMove c = move;
    c.length = norm(chord);
    c.start_dir = c.end_dir = unit(chord);
    c.radius = 0.0;
    c.cruise = std::min(feed, along(c.start_dir, rate_));
    c.kin.accel = along(c.start_dir, accel_);
    block(c);
  }
}

// planner.c plan_buffer_line: the entry speed the corner allows.
void GrblPlanner::block(const PlannedMove& move) {
  PlannedMove m = move;
  m.kin.jerk = 0.0;  // grbl has trapezoids only
  double max_entry = 0.0;
  if (moving_) {
    const double cos_theta = -dot(prev_dir_, m.start_dir);
    double v2 = 0.0;
    if (cos_theta < -0.999999) {
      v2 = kInf;  // straight on
    } else if (cos_theta <= 0.999999) {
      const Vec3 junction = unit(m.start_dir - prev_dir_);
      const double a = along(junction, accel_);
      const double sin_half = std::sqrt(0.5 * (1.0 - cos_theta));
      v2 = a * machine_.junction_deviation * sin_half / (1.0 - sin_half);
    }
    max_entry = std::min({std::sqrt(v2), prev_cruise_, m.cruise});
  }
  look_.add_joined(m, max_entry);
  prev_dir_ = m.end_dir;
  prev_cruise_ = m.cruise;
  moving_ = true;
}

void GrblPlanner::stop() {
  look_.stop();
  moving_ = false;
}

void GrblPlanner::wait(double seconds, std::uint32_t account) {
  look_.wait(seconds, account);
  moving_ = false;
}

const std::vector<AccountTime>& GrblPlanner::accounts() const {
  merge_exact_stop(look_.accounts(), exact_stop_, merged_);
  return merged_;
}

}  // namespace usina::sim
