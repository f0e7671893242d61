#include "sim/planner_linuxcnc.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/units.hpp"
#include "sim/planner_profile.hpp"

namespace usina::sim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// blendmath.h: BLEND_ACC_RATIO_TANGENTIAL 0.5, BLEND_ACC_RATIO_NORMAL √(1 − 0.5²).
constexpr double kTangentialRatio = 0.5;
const double kNormalRatio = std::sqrt(1.0 - kTangentialRatio * kTangentialRatio);
// tp.c, tpSetupTangent: a corner sharper than 178° is a reversal (exact stop).
constexpr double kSharpCornerDeg = 2.0;
// tc.c, tcFindBlendTolerance: without P a blend may leave the path by a
// quarter of the shorter move; blendmath.c: a line gives at most half its
// length to one blend (BLEND_DIST_FRACTION), an arc a third of its sweep
// at its start and two thirds at its end.
constexpr double kToleranceRatio = 0.25;
constexpr double kBlendDistFraction = 0.5;
constexpr double kMinArcLength = 1e-6;  // mm, TP_MIN_ARC_LENGTH
constexpr std::size_t kMaxChain = 100;  // emccanon: points merged into one line at most

using Mode = canon::PathMode::Mode;

double accel_of(const LinuxcncPlanner::Segment& s) {
  const double kink = 1.0 - std::max(s.kink_prev, s.kink_next);
  return s.base_accel * kink * (s.parabolic ? 0.5 : 1.0);
}

double distance_to_line(const Vec3& p, const Vec3& end) {
  const double len2 = dot(end, end);
  if (len2 <= 0.0) return norm(p);
  const double t = std::clamp(dot(p, end) / len2, 0.0, 1.0);
  return norm(p - end * t);
}

}  // namespace

LinuxcncPlanner::LinuxcncPlanner(const MachineProfile& machine, std::size_t lookahead)
    : machine_(machine),
      settings_(machine.linuxcnc),
      look_(PlannerSettings{machine.junction_deviation,
                            std::min(lookahead, machine.linuxcnc.optimization_depth),
                            machine.linuxcnc.servo_period}) {
  // Before the program's first G61, G61.1 or G64 LinuxCNC 2.9 is not in the
  // G64 that word gives: its corners nearly stop (measured: two lines with a
  // right angle take the time of a stop less 0.03 s, the same with G64 the
  // time of a blend arc; tests/programs/timing/README.md). It behaves like
  // G64 with a tolerance of a few µm, which is how it is modelled.
  mode_.tolerance = settings_.startup_tolerance;
}

// The limits a move gets when task queues it (emccanon.cc, tc.c
// tcUpdateArcLimits): the machine's speed along the move capped by [TRAJ]
// MAX_LINEAR_VELOCITY; an arc whose machine speed would need more than
// √3/2 of the acceleration towards its centre runs at √(√3/2·a·r) and keeps
// half the acceleration along the path, otherwise what the centripetal part
// leaves: a·√(1 − (v²/(r·a))²).
LinuxcncPlanner::Segment LinuxcncPlanner::segment_of(const PlannedMove& move) const {
  Segment s;
  s.move = move;
  s.mode = mode_;
  s.nominal = move.length;
  double maxvel = move.max_speed > 0.0 ? move.max_speed : kInf;
  if (settings_.max_velocity > 0.0) maxvel = std::min(maxvel, settings_.max_velocity);
  double accel = move.kin.accel;
  double cruise = move.radius > 0.0 ? move.uncapped : move.cruise;
  if (move.radius > 0.0) {
    const double a_n_cutoff = kNormalRatio * accel;
    const double a_n = maxvel * maxvel / move.radius;
    if (a_n > a_n_cutoff) {
      maxvel = std::sqrt(a_n_cutoff * move.radius);
      accel *= kTangentialRatio;
    } else {
      accel *= std::sqrt(1.0 - (a_n / accel) * (a_n / accel));
    }
  }
  s.requested = cruise;
  s.move.cruise = std::min(cruise, maxvel);
  s.base_accel = accel;
  s.move.kin.accel = accel;
  s.move.kin.jerk = 0.0;  // tpmod has no jerk limit
  return s;
}

void LinuxcncPlanner::path_mode(const canon::PathMode& mode) {
  flush_chain();
  mode_ = mode;
}

void LinuxcncPlanner::add(const PlannedMove& move) {
  if (!(move.length > 0.0 && move.cruise > 0.0 && std::isfinite(move.length))) return;
  AccountTime& a = exact_stop_.size() > move.account
                       ? exact_stop_[move.account]
                       : (exact_stop_.resize(move.account + 1), exact_stop_[move.account]);
  const double t = move_time(move.length, 0.0, 0.0, move.cruise, move.kin);
  if (t >= 0.0 && std::isfinite(t)) a.exact_stop_s += t;
  naive_cam(segment_of(move));
}

// emccanon.cc (see_segment, linkable): under G64 with a Q tolerance, feed
// moves in a row whose corners all stay within Q of the line from the
// first start to the last end are sent to the planner as that one line.
void LinuxcncPlanner::naive_cam(const Segment& s) {
  const bool mergeable =
      s.mode.mode == Mode::Blend && s.mode.naive_cam > 0.0 && !s.move.rapid && s.move.radius == 0.0;
  if (!mergeable) {
    flush_chain();
    queue(s);
    return;
  }
  if (have_chain_) {
    const Vec3 end = chain_points_.back() + s.move.start_dir * s.move.length;
    if (links(s, end)) {
      chain_points_.push_back(end);
      chain_.move.cruise = std::min(chain_.move.cruise, s.move.cruise);
      chain_.requested = std::min(chain_.requested, s.requested);
      chain_.base_accel = std::min(chain_.base_accel, s.base_accel);
      chain_.move.max_speed = std::min(chain_.move.max_speed, s.move.max_speed);
      chain_.move.op = s.move.op;  // the merged line ends where this move ends
      return;
    }
    flush_chain();
  }
  chain_ = s;
  chain_points_.assign(1, s.move.start_dir * s.move.length);
  have_chain_ = true;
}

bool LinuxcncPlanner::links(const Segment& s, const Vec3& end) const {
  if (chain_points_.size() >= kMaxChain || s.move.account != chain_.move.account ||
      s.requested != chain_.requested) {
    return false;
  }
  for (const Vec3& p : chain_points_) {
    if (distance_to_line(p, end) > s.mode.naive_cam) return false;
  }
  return true;
}

void LinuxcncPlanner::flush_chain() {
  if (!have_chain_) return;
  have_chain_ = false;
  const Vec3 end = chain_points_.back();
  const double length = norm(end);
  if (length <= 0.0) return;
  Segment s = chain_;
  s.move.length = s.nominal = length;
  s.move.start_dir = s.move.end_dir = end / length;
  s.move.kin.accel = s.base_accel;
  queue(s);
}

// tc.c tcClampVelocityByLength: a move is at least one servo cycle long.
void LinuxcncPlanner::update_last() {
  PlannedMove& m = look_.last_move();
  m.length = last_.move.length;
  m.kin.accel = accel_of(last_);
  m.cruise = last_.move.cruise;
  if (m.length > 0.0) m.cruise = std::min(m.cruise, m.length / settings_.servo_period);
  look_.replan_last();
}

void LinuxcncPlanner::queue(Segment s) {
  double entry = 0.0;
  if (have_last_) entry = corner(s);
  s.move.kin.accel = accel_of(s);
  PlannedMove m = s.move;
  if (m.length > 0.0) m.cruise = std::min(m.cruise, m.length / settings_.servo_period);
  if (look_.has_last()) entry = std::min({entry, look_.last_move().cruise, m.cruise});
  look_.add_joined(m, entry);
  last_ = s;
  have_last_ = true;
}

// tp.c tpSetupTangent and tpHandleBlendArc: how the newest queued move
// joins the next one. Returns the highest speed through the corner (0: a
// stop); lowers either move's acceleration where the rule says so.
double LinuxcncPlanner::corner(Segment& next) {
  Segment& prev = last_;
  if (prev.mode.mode == Mode::ExactStop) return 0.0;  // G61.1: TC_TERM_COND_STOP
  const Vec3 u1 = prev.move.end_dir;
  const Vec3 u2 = next.move.start_dir;
  if (norm(u1) < 0.5 || norm(u2) < 0.5) return 0.0;  // rotary axes only: no tangency test
  // tp.c handleModeChange: no blend between a rapid and a feed move.
  if (prev.move.rapid != next.move.rapid) return 0.0;
  if (dot(u1, u2) < std::cos(core::kPi * (1.0 - kSharpCornerDeg / 180.0))) return 0.0;
  // The acceleration the change of direction needs if taken within one
  // servo cycle at full speed, as a share of each axis's.
  const double v_max = std::min(prev.move.cruise, next.move.cruise);
  // (plus the next move's acceleration: it speeds up within that cycle)
  const Vec3 jump = (u2 - u1) * (v_max / settings_.servo_period + next.move.kin.accel);
  double share = 0.0;
  for (int i = 0; i < 3; ++i) {
    const AxisLimits& a = machine_.axes[static_cast<std::size_t>(i)];
    if (a.present && a.accel > 0.0) share = std::max(share, std::abs(jump[i]) / a.accel);
  }
  if (prev.move.radius > 0.0 || next.move.radius > 0.0) share /= kTangentialRatio;
  if (share < settings_.kink_ratio) {
    // Tangent enough: no blend; both lose that share (tcSetKinkProperties).
    prev.kink_next = next.kink_prev = share;
    update_last();
    return v_max;
  }
  const double kink_vel = v_max * settings_.kink_ratio / share;
  prev.kink_next = next.kink_prev = settings_.kink_ratio;
  if (prev.mode.mode == Mode::ExactPath) {
    update_last();  // G61: the stop keeps the kink's lower acceleration
    return 0.0;
  }
  // tp.c tpChooseBestBlend: the fastest of a parabolic blend (its speed
  // halved: both moves lose half their acceleration), the kink taken as
  // tangent, and a blend arc; on a tie the first of these.
  const double parabolic = parabolic_speed(next) / 2.0;
  const Arc arc = settings_.arc_blend ? blend_arc(next) : Arc{};
  if (arc.ok && arc.move.cruise > std::max(parabolic, kink_vel)) {
    join_by_arc(next, arc);
    return kInf;
  }
  if (kink_vel > parabolic) {
    update_last();  // tangent: through the corner at the kink speed, 10 % less acceleration
    return kink_vel;
  }
  // Parabolic: the moves overlap at half their acceleration and no kink;
  // LinuxCNC 2.9 takes about as long as with a stop there (measured:
  // tests/programs/timing/helix_2turns), so it is one.
  prev.kink_next = next.kink_prev = 0.0;
  prev.parabolic = next.parabolic = true;
  update_last();
  return 0.0;
}

// tp.c tpComputeBlendVelocity: the speed of a parabolic blend, both moves
// changing speed at once within half of the shorter's length.
double LinuxcncPlanner::parabolic_speed(const Segment& next) const {
  const Segment& prev = last_;
  const auto reach = [](const Segment& s, double a) {
    return std::min(std::sqrt(a * s.move.length), s.move.cruise);
  };
  const double a1 = accel_of(prev);
  const double a2 = accel_of(next);
  const double v1 = reach(prev, a1);
  const double v2 = reach(next, a2);
  if (!(v1 > 0.0 && v2 > 0.0)) return 0.0;
  const double t_blend =
      std::min(std::min(prev.move.length / v1, next.move.length / v2), std::max(v1 / a1, v2 / a2));
  double b1 = std::min(v1, t_blend * a1);
  double b2 = std::min(v2, t_blend * a2);
  const double theta =
      std::acos(std::clamp(-dot(prev.move.end_dir, next.move.start_dir), -1.0, 1.0)) / 2.0;
  if (prev.mode.tolerance > 0.0 && std::cos(theta) > 1e-9) {
    const double v_tol = 2.0 * std::sqrt(a1 * prev.mode.tolerance / std::cos(theta));
    b1 = std::min(b1, v_tol);
    b2 = std::min(b2, v_tol);
  }
  return std::sin(theta) * (b1 + b2) / 2.0;
}

// blendmath.c (blendInit3From*, blendParamKinematics, blendComputeParameters,
// blendCheckConsume): the arc that replaces a corner under G64. It stays
// within the tolerance (P, else a quarter of the shorter move) and takes at
// most half a line (a third of an arc's sweep at its start, two thirds at
// its end); its radius is what the speed needs, or what a parabolic blend
// at half acceleration would take, whichever is larger.
LinuxcncPlanner::Arc LinuxcncPlanner::blend_arc(const Segment& next) const {
  const Segment& prev = last_;
  Arc out;
  const Vec3 u1 = prev.move.end_dir;
  const Vec3 u2 = next.move.start_dir;
  const double theta = std::acos(std::clamp(-dot(u1, u2), -1.0, 1.0)) / 2.0;
  if (theta < 1e-6 || core::kPi / 2.0 - theta < 1e-6 || !coplanar(prev, next)) return out;
  const double phi = core::kPi - 2.0 * theta;
  const auto tol_of = [](const Segment& s) {
    return s.mode.tolerance > 0.0 ? s.mode.tolerance : s.nominal * kToleranceRatio;
  };
  const double tol = std::min(
      {tol_of(prev), tol_of(next), prev.nominal * kToleranceRatio, next.nominal * kToleranceRatio});
  const double l1 =
      prev.move.radius > 0.0
          ? std::min(std::abs(prev.move.sweep) * 2.0 / 3.0, core::kPi / 2.0) * prev.move.radius
          : std::min(prev.move.length, prev.nominal * kBlendDistFraction);
  const double l2 =
      next.move.radius > 0.0
          ? std::min(std::abs(next.move.sweep) / 3.0, core::kPi / 2.0) * next.move.radius
          : next.move.length * kBlendDistFraction;
  const double a_max = plane_limit(u1, u2, false);
  const double a_n = a_max * kNormalRatio;
  const double v_req = std::max(prev.requested, next.requested);
  const double v_goal = std::min(v_req * settings_.max_feed_scale, plane_limit(u1, u2, true));
  const double d_tol = std::cos(theta) * tol / (1.0 - std::sin(theta));
  const double d_geom = std::min({std::min(l1, prev.move.length), l2, d_tol});
  const double r_geom = std::tan(theta) * d_geom;
  const double v_plan = std::min(std::sqrt(a_n * r_geom), v_goal);
  const double a_parabolic = 0.5 * a_max;
  const double v_triangle = std::sqrt(2.0 * a_parabolic * d_geom);
  const double s_blend = std::min(v_triangle, v_plan) / a_parabolic * v_plan;
  const double r_plan = std::max(v_plan * v_plan / a_n, std::min(s_blend / phi, r_geom));
  if (!(r_plan > 1e-12) || r_plan * phi < kMinArcLength || !(v_plan > 0.0)) return out;
  out.ok = true;
  out.trim = r_plan / std::tan(theta);
  out.move.length = r_plan * phi;
  out.move.start_dir = u1;
  out.move.end_dir = u2;
  out.move.cruise = std::min(v_plan, v_req);
  out.move.radius = r_plan;
  // tpInitBlendArcFromPrev: a blend arc keeps half the acceleration along
  // its path (BLEND_ACC_RATIO_TANGENTIAL), however slow it is.
  out.move.kin.accel = a_max * kTangentialRatio;
  out.move.account = prev.move.account;
  out.move.op = prev.move.op;  // the corner ends prev's op
  out.v_plan = v_plan;
  return out;
}

// tp.c tpCreate*Blend: the moves are trimmed where the arc meets them.
void LinuxcncPlanner::join_by_arc(Segment& next, Arc arc) {
  Segment& prev = last_;
  prev.move.length = std::max(0.0, prev.move.length - arc.trim);
  next.move.length = std::max(0.0, next.move.length - arc.trim);
  prev.kink_next = next.kink_prev = 0.0;  // a blend arc leaves no kink
  double entry = kInf;
  if (prev.move.radius == 0.0 &&
      prev.move.length < arc.v_plan * settings_.gap_cycles * settings_.servo_period) {
    // A line left shorter than the gap cycles take is taken into the arc
    // (blendCheckConsume): one queue entry less.
    arc.move.length += prev.move.length;
    entry = std::min(look_.drop_last(), prev.move.cruise);
  } else {
    update_last();
    entry = look_.last_move().cruise;
  }
  arc.move.cruise = std::min(arc.move.cruise, arc.move.length / settings_.servo_period);
  look_.add_joined(arc.move, std::min(entry, arc.move.cruise));
}

// tp.c tpCreate*Blend: a blend arc lies in one plane with both moves (a
// helix has none).
bool LinuxcncPlanner::coplanar(const Segment& prev, const Segment& next) const {
  if (prev.move.helix || next.move.helix) return false;
  Vec3 binormal = cross(prev.move.end_dir, next.move.start_dir);
  const double len = norm(binormal);
  if (len < 1e-12) return false;
  binormal = binormal / len;
  for (const Segment* s : {&prev, &next}) {
    if (s->move.radius > 0.0 && std::abs(std::abs(dot(binormal, s->move.normal)) - 1.0) > 1e-6) {
      return false;
    }
  }
  return true;
}

// blendmath.c calculateInscribedDiameter: the acceleration (or speed) every
// direction in the plane of the corner gets from the axes' limits.
double LinuxcncPlanner::plane_limit(const Vec3& u1, const Vec3& u2, bool speed) const {
  Vec3 n = cross(u1, u2);
  const double len = norm(n);
  n = len > 1e-12 ? n / len : Vec3{};
  double best = kInf;
  for (int i = 0; i < 3; ++i) {
    const AxisLimits& a = machine_.axes[static_cast<std::size_t>(i)];
    const double in_plane = std::sqrt(std::max(0.0, 1.0 - n[i] * n[i]));
    if (!a.present || in_plane < 1e-9) continue;
    best = std::min(best, (speed ? a.rapid / 60.0 : a.accel) / in_plane);
  }
  if (speed && settings_.max_velocity > 0.0) best = std::min(best, settings_.max_velocity);
  return best;
}

// tp.c: a move nothing follows keeps its parabolic end (G64) and runs at
// half its acceleration (tcGetOverallMaxAccel).
void LinuxcncPlanner::finish_last() {
  flush_chain();
  if (!have_last_) return;
  if (last_.mode.mode == Mode::Blend) {
    last_.parabolic = true;
    update_last();
  }
  have_last_ = false;
}

void LinuxcncPlanner::stop() {
  finish_last();
  look_.stop();
}

void LinuxcncPlanner::wait(double seconds, std::uint32_t account) {
  finish_last();
  look_.wait(seconds, account);
}

const std::vector<AccountTime>& LinuxcncPlanner::accounts() const {
  merge_exact_stop(look_.accounts(), exact_stop_, merged_);
  return merged_;
}

}  // namespace usina::sim
