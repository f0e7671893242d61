// Canned cycles, move for move as LinuxCNC 2.10 makes them. The rules below
// are LinuxCNC's (src/emc/rs274ngc/interp_cycles.cc, interp_convert.cc) and
// were checked against its traces (shared/conformance/rs274ngc and the
// Debian linuxcnc-uspace rs274); the code is usina's own.
#include "gcode/interp/canned_cycles.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "gcode/interp/canned_cycle_parts.hpp"

namespace usina::gcode {
namespace {

using namespace cycle_parts;

using canon::SpindleDir;
using core::Code;
using core::Plane;

// Limits that keep a hostile block finite (DESIGN.md, "Errors and bad input").
constexpr double kMaxRepeats = 100000;  // L
constexpr long kMaxPecks = 100000;      // G73/G83 pecks in one hole
constexpr double kMaxMoves = 4e6;       // moves one block may make

int g_of(int motion) {
  return motion / 10;
}

char axis_letter(int axis) {
  return "XYZ"[axis];
}

const char* plane_name(Plane p) {
  switch (p) {
  case Plane::XY: return "the XY plane (G17)";
  case Plane::ZX: return "the ZX plane (G18)";
  case Plane::YZ: return "the YZ plane (G19)";
  }
  return "?";
}

// One block of G73/G74/G81-G89, in program units, named as in convert_cycle_xy.
struct DrillPlan {
  int motion = 810;
  Plane plane = Plane::XY;
  double cur_a = 0, cur_b = 0, cur_c = 0;          // the current point (c on the plane's normal)
  double a = 0, b = 0;                             // the hole before the first repeat's increment
  double da = 0, db = 0, dradius = 0, dtheta = 0;  // G91 increments per repeat
  double r = 0, bottom = 0, clear = 0;
  bool raise = false;           // rapid up to R first: the initial level is below it
  double middle = 0;            // G87: top of the back bore
  double off_a = 0, off_b = 0;  // G87: offsets of the tool's way in
  double dwell = 0, peck = 0, clearance = 0, retract = 0;
  long repeats = 1;
  SpindleDir spindle = SpindleDir::Off;
};

// The words of the block with the sticky ones filled in (mm, as written).
struct Resolved {
  double r = 0, bottom = 0, p = 0, q = 0;
  std::array<double, 3> ijk{};
};

InterpResult read_repeats(const CycleWords& w, int motion, long& repeats) {
  repeats = 1;
  if (!w.l) return {};
  if (*w.l > kMaxRepeats) {
    return error(Code::TooManyIterations,
                 fmt::format("G{} L{:g} repeats the cycle more than {:g} times", g_of(motion), *w.l,
                             kMaxRepeats));
  }
  const std::optional<long> l = whole_number(*w.l);
  if (!l || *l < 0) {
    return error(Code::BadWordValue,
                 fmt::format("G{} L{:g}: the number of repeats must be a positive whole number",
                             g_of(motion), *w.l));
  }
  if (*l == 0) {
    return error(Code::BadWordValue,
                 fmt::format("G{} L0: a cycle cannot run zero times; give L1 or more, or no L",
                             g_of(motion)));
  }
  repeats = *l;
  return {};
}

// R and the bottom: from the block, or kept from the last block of the same
// cycle (LinuxCNC convert_cycle: cycle_r; convert_cycle_xy: cycle_cc).
InterpResult resolve_levels(const CycleWords& w, const CycleModal& m, const CannedCycles::Sticky& s,
                            Resolved& out) {
  const int g = g_of(m.motion);
  if (!w.r && m.motion_mode_changed) {
    return error(
        Code::MissingWord,
        fmt::format("G{} needs R, the retract plane, in the block that starts the cycle", g));
  }
  const int normal = core::axes_of(m.plane).axial;
  const std::array<const std::optional<double>*, 3> axis{&w.x, &w.y, &w.z};
  const std::optional<double>& bottom = *axis[static_cast<std::size_t>(normal)];
  if (!bottom && m.motion_mode_changed) {
    return error(Code::MissingWord,
                 fmt::format("G{} in {} needs {}, the bottom of the hole, in the block that "
                             "starts the cycle",
                             g, plane_name(m.plane), axis_letter(normal)));
  }
  out.r = w.r.value_or(s.r);
  out.bottom = bottom.value_or(s.bottom);
  return {};
}

// P, Q, I, J, K as each cycle needs them (convert_cycle_xy, per cycle).
InterpResult resolve_cycle_words(const CycleWords& w, const CycleModal& m,
                                 const CannedCycles::Sticky& s, Resolved& out) {
  const int g = g_of(m.motion);
  const Units u{m.length_unit};
  const bool dwells = g == 82 || g == 86 || g == 88 || g == 89;
  if (dwells && !w.p && m.motion_mode_changed) {
    return error(Code::MissingWord,
                 fmt::format("G{} needs P, the dwell in seconds, in the block that starts the "
                             "cycle",
                             g));
  }
  out.p = w.p.value_or(s.p);  // G74/G84 dwell P (or the last P of any cycle; 0 at first)
  if (out.p < 0) {
    return error(Code::BadWordValue,
                 fmt::format("G{} P{:g}: the dwell must be 0 seconds or more", g, out.p));
  }
  if ((g == 73 || g == 83) && !w.q && m.motion_mode_changed) {
    return error(Code::MissingWord,
                 fmt::format("G{} needs Q, the peck depth, in the block that starts the cycle", g));
  }
  out.q = w.q.value_or(s.q);
  if ((g == 73 || g == 83) && out.q <= 0) {
    return error(Code::CycleBadValue,
                 fmt::format("G{} Q{:g}: the peck depth must be greater than 0", g, u.in(out.q)));
  }
  const std::array<const std::optional<double>*, 3> ijk{&w.i, &w.j, &w.k};
  const std::array<double, 3> kept{s.i, s.j, s.k};
  for (std::size_t n = 0; n < 3; ++n) {
    if (g == 87 && !*ijk[n] && m.motion_mode_changed) {
      return error(Code::MissingWord,
                   fmt::format("G87 needs I, J and K (the offset of the tool's way in and the top "
                               "of the back bore) in the block that starts the cycle; {} is "
                               "missing",
                               "IJK"[n]));
    }
    out.ijk[n] = ijk[n]->value_or(kept[n]);
  }
  return {};
}

// The hole position: G91 steps it each repeat (CYCLE_MACRO's increments, NCMS
// p. 98); G90 places it, from X Y or from @ (radius) and ^ (angle) in G17.
void plan_position(const CycleWords& w, const CycleModal& m, Units u, DrillPlan& p) {
  const core::PlaneAxes ax = core::axes_of(m.plane);
  const std::array<const std::optional<double>*, 3> axis{&w.x, &w.y, &w.z};
  const std::optional<double>& first = *axis[static_cast<std::size_t>(ax.first)];
  const std::optional<double>& second = *axis[static_cast<std::size_t>(ax.second)];
  constexpr double kRadPerDeg = std::numbers::pi / 180.0;  // LinuxCNC's D2R
  p.a = p.cur_a;
  p.b = p.cur_b;
  if (m.incremental) {
    p.da = first ? u.in(*first) : 0.0;
    p.db = second ? u.in(*second) : 0.0;
    p.dradius = w.polar_radius ? u.in(*w.polar_radius) : 0.0;
    p.dtheta = w.polar_angle ? *w.polar_angle * kRadPerDeg : 0.0;
    return;
  }
  if (first) p.a = u.in(*first);
  if (second) p.b = u.in(*second);
  if (w.polar_radius || w.polar_angle) {
    const double radius = w.polar_radius ? u.in(*w.polar_radius) : std::hypot(p.b, p.a);
    const double theta = w.polar_angle ? *w.polar_angle * kRadPerDeg : std::atan2(p.b, p.a);
    p.a = radius * std::cos(theta);
    p.b = radius * std::sin(theta);
  }
}

// convert_cycle_xy/_zx/_yz: R, the bottom and the clear level in program
// units. Under G91 R counts from the initial level and the bottom from R.
InterpResult plan_levels(const CycleModal& m, const Resolved& v, Units u, double initial,
                         DrillPlan& p) {
  const core::PlaneAxes ax = core::axes_of(m.plane);
  p.r = m.incremental ? u.in(v.r) + initial : u.in(v.r);
  p.bottom = m.incremental ? p.r + u.in(v.bottom) : u.in(v.bottom);
  if (p.r < p.bottom) {
    const char n = axis_letter(ax.axial);
    return error(Code::CycleBadValue,
                 fmt::format("G{}: the retract plane R ({}{}) is below the bottom of the hole "
                             "({}{}); R must be at or above the bottom{}",
                             g_of(m.motion), n, u.show(u.out(p.r)), n, u.show(u.out(p.bottom)),
                             m.incremental ? " (under G91 R counts from the initial level and "
                                             "the bottom from R)"
                                           : ""));
  }
  p.raise = initial < p.r;  // below the R plane: rapid straight up to it first
  p.clear = m.retract_to_r ? p.r : std::max(initial, p.r);
  const double k = u.in(v.ijk[static_cast<std::size_t>(ax.axial)]);
  p.middle = m.incremental ? p.bottom + k : k;  // G87: K from the bottom under G91
  p.off_a = u.in(v.ijk[static_cast<std::size_t>(ax.first)]);
  p.off_b = u.in(v.ijk[static_cast<std::size_t>(ax.second)]);
  return {};
}

// CYCLE_MACRO's increments for one repeat; false at the origin, where an
// incremental polar move has no direction.
bool advance(const DrillPlan& p, double& a, double& b) {
  a += p.da;
  b += p.db;
  if (p.dradius != 0.0) {
    if (a == 0.0 && b == 0.0) return false;
    const double theta = std::atan2(b, a);
    const double radius = std::hypot(b, a) + p.dradius;
    a = radius * std::cos(theta);
    b = radius * std::sin(theta);
  }
  if (p.dtheta != 0.0) {
    if (a == 0.0 && b == 0.0) return false;
    const double theta = std::atan2(b, a) + p.dtheta;
    const double radius = std::hypot(b, a);
    a = radius * std::cos(theta);
    b = radius * std::sin(theta);
  }
  return true;
}

// LinuxCNC's peck loop: from R down by Q while above the bottom. The
// repeated subtraction (not R - n Q) is what decides the last peck.
long count_pecks(const DrillPlan& p) {
  long n = 0;
  double d = p.r - p.peck;
  while (d > p.bottom && n <= kMaxPecks) {
    ++n;
    d -= p.peck;
  }
  return n;
}

// Everything that could still fail, before the first move.
InterpResult check_plan(const DrillPlan& p) {
  if (auto e = check_spindle(p.motion, p.spindle); !e) return e;
  double a = p.a;
  double b = p.b;
  for (long n = 0; n < p.repeats; ++n) {
    if (!advance(p, a, b)) {
      return error(Code::CycleBadValue,
                   fmt::format("G{}: an incremental polar step (G91 @ or ^) from X0 Y0 has no "
                               "direction; start the cycle away from the origin",
                               g_of(p.motion)));
    }
  }
  const bool pecks = p.motion == 730 || p.motion == 830;
  const long n = pecks ? count_pecks(p) : 0;
  if (n > kMaxPecks ||
      static_cast<double>(p.repeats) * static_cast<double>(3 * n + 12) > kMaxMoves) {
    return error(Code::TooManyIterations,
                 fmt::format("G{} would make more than {:g} moves (Q{:g} is too small for the "
                             "depth, or L too large)",
                             g_of(p.motion), kMaxMoves, p.peck));
  }
  return {};
}

// The moves to the hole (CYCLE_MACRO): the first repeat moves in the plane at
// the current level, raised to R if it was below, then down to R; later
// repeats move at the clear level.
void move_over(Mover& m, const DrillPlan& p, double a, double b, bool first, double current) {
  if (first && current > p.r) {
    m.traverse(a, b, current);
    m.traverse(a, b, p.r);
    return;
  }
  m.traverse(a, b, p.clear);
  if (p.clear > p.r) m.traverse(a, b, p.r);
}

// G81 drilling (convert_cycle_g81), G82 with a dwell at the bottom (_g82).
void g81_g82(Mover& m, const DrillPlan& p, double a, double b) {
  m.feed(a, b, p.bottom);
  if (p.motion == 820) m.dwell(p.dwell);
  m.traverse(a, b, p.clear);
}

// G73 chip breaking: back off by the peck retract after each peck (_g73).
void g73(Mover& m, const DrillPlan& p, double a, double b) {
  double d = p.r - p.peck;
  while (d > p.bottom) {
    m.feed(a, b, d);
    m.traverse(a, b, d + p.retract);
    d -= p.peck;
  }
  m.feed(a, b, p.bottom);
  m.traverse(a, b, p.clear);
}

// G83 peck drilling: out to R after each peck, then rapid back down to the
// peck clearance above the last depth (_g83).
void g83(Mover& m, const DrillPlan& p, double a, double b) {
  double d = p.r - p.peck;
  while (d > p.bottom) {
    m.feed(a, b, d);
    m.traverse(a, b, p.r);
    m.traverse(a, b, d + p.clearance);
    d -= p.peck;
  }
  m.feed(a, b, p.bottom);
  m.traverse(a, b, p.clear);
}

// G84 right-hand and G74 left-hand floating tapping (convert_cycle_g74_g84).
// In G18 and G19 LinuxCNC hands the hole's coordinates to cycle_feed in
// another order than every other cycle does, so both feeds go to a point off
// the hole (its traces show it: tests/interp/g84/g18, g19); usina does the same.
void g74_g84(Mover& m, const DrillPlan& p, double a, double b) {
  const bool right = p.motion == 840;
  const auto tap_feed = [&](double c) {
    switch (p.plane) {
    case Plane::XY: m.feed(a, b, c); break;
    case Plane::ZX: m.feed(b, c, a); break;
    case Plane::YZ: m.feed(c, a, b); break;
    }
  };
  tap_feed(p.bottom);
  m.spindle(SpindleDir::Off);
  m.spindle(right ? SpindleDir::Ccw : SpindleDir::Cw);
  m.dwell(p.dwell);
  tap_feed(p.clear);
  m.spindle(SpindleDir::Off);
  m.spindle(right ? SpindleDir::Cw : SpindleDir::Ccw);
}

// G85 boring, feed out to R (_g85); G89 the same with a dwell, feed out to the clear level (_g89).
void g85_g89(Mover& m, const DrillPlan& p, double a, double b) {
  m.feed(a, b, p.bottom);
  if (p.motion == 890) {
    m.dwell(p.dwell);
    m.feed(a, b, p.clear);
    return;
  }
  m.feed(a, b, p.r);
  m.traverse(a, b, p.clear);
}

// G86 boring: dwell, stop the spindle, rapid out, restart it (_g86).
void g86(Mover& m, const DrillPlan& p, double a, double b) {
  m.feed(a, b, p.bottom);
  m.dwell(p.dwell);
  m.spindle(SpindleDir::Off);
  m.traverse(a, b, p.clear);
  m.spindle(p.spindle);
}

// G87 back boring (_g87). The spindle orientations (ORIENT_SPINDLE) are not motion.
void g87(Mover& m, const DrillPlan& p, double a, double b) {
  const double oa = a + p.off_a;
  const double ob = b + p.off_b;
  m.traverse(oa, ob, p.r);
  m.spindle(SpindleDir::Off);
  m.traverse(oa, ob, p.bottom);
  m.traverse(a, b, p.bottom);
  m.spindle(p.spindle);
  m.feed(a, b, p.middle);
  m.feed(a, b, p.bottom);
  m.spindle(SpindleDir::Off);
  m.traverse(oa, ob, p.bottom);
  m.traverse(oa, ob, p.clear);
  m.traverse(a, b, p.clear);
  m.spindle(p.spindle);
}

// G88 boring: dwell, stop the spindle; the operator retracts by hand during
// LinuxCNC's PROGRAM_STOP (not motion), then the spindle restarts (_g88).
void g88(Mover& m, const DrillPlan& p, double a, double b) {
  m.feed(a, b, p.bottom);
  m.dwell(p.dwell);
  m.spindle(SpindleDir::Off);
  m.spindle(p.spindle);
}

void cycle_body(Mover& m, const DrillPlan& p, double a, double b) {
  switch (p.motion) {
  case 730: g73(m, p, a, b); break;
  case 830: g83(m, p, a, b); break;
  case 740:
  case 840: g74_g84(m, p, a, b); break;
  case 860: g86(m, p, a, b); break;
  case 870: g87(m, p, a, b); break;
  case 880: g88(m, p, a, b); break;
  case 850:
  case 890: g85_g89(m, p, a, b); break;
  default: g81_g82(m, p, a, b); break;
  }
}

// Rapid up to R if below it, then every repeat: to the hole, the cycle.
// Returns where LinuxCNC's interpreter then is (program units): over the
// last hole at the clear level.
Vec3 drill(Mover& m, const DrillPlan& p) {
  double current = p.cur_c;
  if (p.raise) {
    m.traverse(p.cur_a, p.cur_b, p.r);
    current = p.r;
  }
  double a = p.a;
  double b = p.b;
  for (long n = 0; n < p.repeats; ++n) {
    advance(p, a, b);
    move_over(m, p, a, b, n == 0, current);
    m.hole(a, b, p.r, p.bottom);
    cycle_body(m, p, a, b);
  }
  return core::from_plane({a, b}, p.clear, p.plane);
}

// What LinuxCNC keeps for the next block (convert_cycle and convert_cycle_xy).
void keep_sticky(CannedCycles::Sticky& sticky, const Resolved& v, int motion) {
  sticky.r = v.r;
  sticky.bottom = v.bottom;
  const int g = g_of(motion);
  if (g == 74 || g == 82 || g == 84 || g == 86 || g == 88 || g == 89) sticky.p = v.p;
  if (g == 73 || g == 83) sticky.q = v.q;
  if (g == 87) {
    sticky.i = v.ijk[0];
    sticky.j = v.ijk[1];
    sticky.k = v.ijk[2];
  }
}

// NaN or infinity from an expression would make moves to nowhere.
InterpResult check_finite(const CycleWords& w, int motion) {
  const std::array<std::pair<char, const std::optional<double>*>, 14> all{{{'X', &w.x},
                                                                           {'Y', &w.y},
                                                                           {'Z', &w.z},
                                                                           {'R', &w.r},
                                                                           {'Q', &w.q},
                                                                           {'I', &w.i},
                                                                           {'J', &w.j},
                                                                           {'K', &w.k},
                                                                           {'P', &w.p},
                                                                           {'L', &w.l},
                                                                           {'H', &w.h},
                                                                           {'E', &w.e},
                                                                           {'@', &w.polar_radius},
                                                                           {'^', &w.polar_angle}}};
  for (const auto& [letter, v] : all) {
    if (*v && !std::isfinite(**v)) {
      return error(Code::BadWordValue,
                   fmt::format("G{:g}: {} is not a finite number", motion / 10.0, letter));
    }
  }
  return {};
}

bool is_drilling_cycle(int motion) {
  return motion == 730 || motion == 740 || (motion >= 810 && motion <= 890 && motion % 10 == 0);
}

}  // namespace

InterpResult cycle_parts::check_spindle(int motion, SpindleDir dir) {
  const int g = g_of(motion);
  const auto turning = [](SpindleDir d) { return d == SpindleDir::Off ? "stopped" : "turning"; };
  if (g == 84 && dir != SpindleDir::Cw) {
    return error(Code::NotAllowedInMode,
                 fmt::format("G84 taps right-hand: start the spindle clockwise (M3) first; it is "
                             "{}{}",
                             turning(dir), dir == SpindleDir::Ccw ? " counter-clockwise" : ""));
  }
  if (g == 74 && dir != SpindleDir::Ccw) {
    return error(Code::NotAllowedInMode,
                 fmt::format("G74 taps left-hand: start the spindle counter-clockwise (M4) first; "
                             "it is {}{}",
                             turning(dir), dir == SpindleDir::Cw ? " clockwise" : ""));
  }
  if ((g == 86 || g == 87 || g == 88 || g == 76) && dir == SpindleDir::Off) {
    return error(Code::NotAllowedInMode,
                 fmt::format("G{} needs the spindle turning: start it with M3 or M4 first", g));
  }
  return {};
}

InterpResult CannedCycles::run(const CycleWords& words, const CycleModal& modal,
                               MotionTarget& target) {
  if (auto e = check_finite(words, modal.motion); !e) return e;
  if (modal.motion == 760) return run_threading(words, modal, target);
  if (!is_drilling_cycle(modal.motion)) {
    return error(Code::Unsupported,
                 fmt::format("G{:g} is not a canned cycle", modal.motion / 10.0));
  }
  return run_drilling(words, modal, target);
}

InterpResult CannedCycles::run_drilling(const CycleWords& words, const CycleModal& modal,
                                        MotionTarget& target) {
  if ((words.polar_radius || words.polar_angle) && modal.plane != Plane::XY) {
    return error(Code::NotAllowedInMode,
                 fmt::format("G{}: polar coordinates (@, ^) work only in the XY plane (G17)",
                             g_of(modal.motion)));
  }
  Resolved v;
  DrillPlan p;
  if (auto e = resolve_levels(words, modal, sticky_, v); !e) return e;
  if (auto e = read_repeats(words, modal.motion, p.repeats); !e) return e;
  if (auto e = resolve_cycle_words(words, modal, sticky_, v); !e) return e;
  const Units u{modal.length_unit};
  // LinuxCNC's numbers for the current point and the initial level: kept
  // from the last block when they are still the same, as 0.345 - 0.095 and
  // 0.25 differ in the last bit and decide "above R or at R".
  const bool same_unit = unit_ == u.mm;
  const Vec3 pos = target.position();
  const Vec3 pos_u = same_unit && pos == end_point_ ? end_point_u_ : u.in(pos);
  const int normal = core::axes_of(modal.plane).axial;
  const double initial =
      !initial_level_ ? pos_u[normal] : (same_unit ? initial_level_u_ : u.in(*initial_level_));
  const Vec2 cur = core::in_plane(pos_u, modal.plane);
  p.motion = modal.motion;
  p.plane = modal.plane;
  p.cur_a = cur.x;
  p.cur_b = cur.y;
  p.cur_c = pos_u[normal];
  plan_position(words, modal, u, p);
  if (auto e = plan_levels(modal, v, u, initial, p); !e) return e;
  p.dwell = v.p;
  p.peck = u.in(v.q);
  p.clearance = modal.peck_clearance / u.mm;
  p.retract = modal.peck_retract.value_or(modal.peck_clearance) / u.mm;
  p.spindle = modal.spindle;
  if (auto e = check_plan(p); !e) return e;

  Mover m(target, p.plane, u);
  end_point_u_ = drill(m, p);
  end_point_ = u.out(end_point_u_);
  initial_level_u_ = initial;  // LinuxCNC's cycle_il, kept until another motion
  initial_level_ = u.out(initial);
  unit_ = u.mm;
  keep_sticky(sticky_, v, modal.motion);
  return {};
}

}  // namespace usina::gcode
