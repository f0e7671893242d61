#include "sim/planner_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/arc.hpp"
#include "core/units.hpp"

namespace usina::sim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double figure(const AxisLimits& a, AxisRate rate) {
  switch (rate) {
  case AxisRate::Rapid: return a.rapid / 60.0;
  case AxisRate::MaxFeed: return a.max_feed / 60.0;
  case AxisRate::Accel: return a.accel;
  case AxisRate::Jerk: return a.jerk;
  }
  return 0.0;
}

// along_path's minimum for one rate, an axis at a time.
class RateLimit {
 public:
  explicit RateLimit(AxisRate rate) : rate_(rate) {}

  void add(const AxisLimits& a, double share, std::size_t i) {
    const double f = figure(a, rate_);
    if (rate_ == AxisRate::Jerk && f <= 0.0) {
      any_zero_jerk_ = true;
      return;
    }
    const double limit = f / share;
    if (limit < best_) {
      best_ = limit;
      axis_ = static_cast<int>(i);
    }
  }

  int axis() const { return axis_; }

  double result(const MachineProfile& m) const {
    double best = best_;
    // Axes the profile lacks (a rotary axis of a three-axis profile) move at
    // the rate of the slowest linear axis rather than without limit.
    if (best == kInf && rate_ != AxisRate::Jerk) {
      for (std::size_t i = 0; i < 3; ++i) {
        if (m.axes[i].present) best = std::min(best, figure(m.axes[i], rate_));
      }
    }
    // One axis without jerk limit makes the move trapezoidal: the S-curve
    // needs every moving axis to ramp its acceleration.
    if (rate_ == AxisRate::Jerk && (any_zero_jerk_ || best == kInf)) return 0.0;
    return best;
  }

 private:
  AxisRate rate_;
  double best_ = kInf;
  int axis_ = -1;
  bool any_zero_jerk_ = false;
};

// An axis that limits nothing: absent, or not moving.
bool limits_nothing(const AxisLimits& a, double share) {
  return !a.present || share <= 1e-12;
}

}  // namespace

double along_path(const MachineProfile& m, const AxisShare& s, AxisRate rate, int* limiting) {
  RateLimit r(rate);
  for (std::size_t i = 0; i < 6; ++i) {
    if (!limits_nothing(m.axes[i], s.share[i])) r.add(m.axes[i], s.share[i], i);
  }
  if (limiting != nullptr) *limiting = r.axis();
  return r.result(m);
}

PathRates path_rates(const MachineProfile& m, const AxisShare& s) {
  RateLimit rapid(AxisRate::Rapid);
  RateLimit feed(AxisRate::MaxFeed);
  RateLimit accel(AxisRate::Accel);
  RateLimit jerk(AxisRate::Jerk);
  for (std::size_t i = 0; i < 6; ++i) {
    const AxisLimits& a = m.axes[i];
    if (limits_nothing(a, s.share[i])) continue;
    rapid.add(a, s.share[i], i);
    feed.add(a, s.share[i], i);
    accel.add(a, s.share[i], i);
    jerk.add(a, s.share[i], i);
  }
  return {rapid.result(m), feed.result(m), feed.axis(), accel.result(m), jerk.result(m)};
}

AxisShare straight_share(const Axes6& from, const Axes6& to, double length) {
  AxisShare s;
  if (length <= 0.0) return s;
  for (std::size_t i = 0; i < 6; ++i)
    s.share[i] = std::abs(to[i] - from[i]) / length;
  return s;
}

double junction_speed(const Vec3& in, const Vec3& out, double deviation, double accel) {
  if (norm(in) < 0.5 || norm(out) < 0.5) return 0.0;
  const double cos_theta = -dot(in, out);
  if (cos_theta > 0.999999) return 0.0;    // reversal
  if (cos_theta < -0.999999) return kInf;  // straight on
  const double sin_half = std::sqrt(0.5 * (1.0 - cos_theta));
  return std::sqrt(accel * deviation * sin_half / (1.0 - sin_half));
}

Vec3 ArcPath::at(double angle) const {
  const double t = sweep != 0.0 ? angle / sweep : 0.0;
  return center + (u * std::cos(angle) + v * std::sin(angle)) * radius + normal * (axial * t);
}

namespace {

Vec3 unit(const Vec3& a) {
  const double n = norm(a);
  return n > 0.0 ? a / n : Vec3{};
}

// Direction of travel at `angle`: d/dθ of at(θ), signed as the sweep.
Vec3 tangent(const ArcPath& p, double angle) {
  const Vec3 d = (p.v * std::cos(angle) - p.u * std::sin(angle)) * p.radius +
                 p.normal * (p.sweep != 0.0 ? p.axial / p.sweep : 0.0);
  return unit(p.sweep >= 0.0 ? d : -d);
}

}  // namespace

std::optional<ArcPath> arc_path(const Vec3& from, const canon::Arc& arc) {
  ArcPath p;
  p.normal = unit(arc.normal);
  if (norm(p.normal) == 0.0) return std::nullopt;
  const Vec3 r0 = from - arc.center;
  const Vec3 radial = r0 - p.normal * dot(r0, p.normal);
  p.radius = norm(radial);
  if (p.radius < 1e-9) return std::nullopt;
  p.center = from - radial;
  p.u = radial / p.radius;
  p.v = cross(p.normal, p.u);
  const Vec3 r1 = arc.to - p.center;
  p.axial = dot(r1, p.normal);
  const core::Vec2 end{dot(r1, p.u), dot(r1, p.v)};
  p.sweep = core::arc_sweep({p.radius, 0.0}, end, {0.0, 0.0}, arc.turn > 0, std::abs(arc.turn));
  p.length = core::helix_length(p.radius, p.sweep, p.axial);
  p.start_tangent = tangent(p, 0.0);
  p.end_tangent = tangent(p, p.sweep);
  return p;
}

void arc_extent(const ArcPath& p, Vec3& lo, Vec3& hi) {
  const auto grow = [&](const Vec3& q) {
    for (int i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], q[i]);
      hi[i] = std::max(hi[i], q[i]);
    }
  };
  grow(p.at(0.0));
  grow(p.at(p.sweep));
  const double two_pi = 2.0 * core::kPi;
  for (int i = 0; i < 3; ++i) {
    // Coordinate i turns back where d/dθ (u_i cos θ + v_i sin θ) = 0.
    if (std::hypot(p.u[i], p.v[i]) < 1e-12) continue;
    const double phi = std::atan2(p.v[i], p.u[i]);
    for (const double base : {phi, phi + core::kPi}) {
      // The first angle of the sweep's direction at which base recurs.
      double a = std::fmod(base, two_pi);
      if (p.sweep >= 0.0) {
        if (a < 0.0) a += two_pi;
      } else if (a > 0.0) {
        a -= two_pi;
      }
      if (std::abs(a) <= std::abs(p.sweep)) grow(p.at(a));
    }
  }
}

}  // namespace usina::sim
