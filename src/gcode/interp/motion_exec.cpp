// Motion: targets in program coordinates (units, G90/G91, polar words, G53,
// lathe diameter mode), straight moves, arcs (centre and radius formats),
// probing, splines; canned cycles and cutter compensation are modules of
// their own driven from here.
#include <cmath>
#include <cstdint>
#include <string_view>

#include <fmt/format.h>

#include "canon/limits.hpp"
#include "core/spline.hpp"
#include "gcode/interp/block_words.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {
namespace {

bool is_rotary(int axis) {
  return axis >= 3 && axis <= 5;
}

// The words of the axes after X, Y and Z: A B C U V W.
constexpr std::uint32_t kRotaryAndUvw = [] {
  std::uint32_t bits = 0;
  for (const char c : std::string_view("ABCUVW"))
    bits |= 1u << BlockWords::slot(c);
  return bits;
}();

}  // namespace

Axes Interpreter::target(const BlockWords& w, bool machine_coords) const {
  const ModalState& s = state_;
  // Under cutter compensation the programmed point, not the tool centre, is
  // where incremental and omitted words start from (LinuxCNC find_ends).
  Axes base = s.pos;
  if (auto programmed = comp_.programmed_position()) set_xyz(base, *programmed);
  Axes end = base;
  if (machine_coords) {
    // G53: the words are machine coordinates of the controlled point.
    Vec3 abs = machine_.to_absolute(xyz(s.pos)) + xyz(s.tool_offset);
    for (int a = 0; a < 3; ++a) {
      if (w.has(kAxisLetters[a])) abs[a] = mm(w.get(kAxisLetters[a]));
    }
    set_xyz(end, machine_.to_program(abs - xyz(s.tool_offset)));
  }
  for (int a = machine_coords ? 3 : 0; a < kAxisCount; ++a) {
    const char letter = kAxisLetters[a];
    if (!w.has(letter)) {
      // Most blocks name X, Y or Z only: the rest is asked at once.
      if (a >= 3 && (w.present & kRotaryAndUvw) == 0) break;
      continue;
    }
    double v = is_rotary(a) ? w.get(letter) : mm(w.get(letter));
    if (a == 0 && s.lathe_diameter) v /= 2.0;  // G7: X words are diameters
    const auto i = static_cast<std::size_t>(a);
    end[i] = s.incremental || w.incremental(letter) ? base[i] + v : v;
  }
  if (w.has_polar()) {
    // LinuxCNC polar words: @ radius and ^ angle (degrees) about the origin;
    // under G91 both add to the current point's polar coordinates.
    const double r0 = std::hypot(base[0], base[1]);
    const double t0 = core::rad_to_deg(std::atan2(base[1], base[0]));
    const double r = w.has('@') ? (s.incremental ? r0 + mm(w.get('@')) : mm(w.get('@'))) : r0;
    const double t = w.has('^') ? (s.incremental ? t0 + w.get('^') : w.get('^')) : t0;
    end[0] = r * std::cos(core::deg_to_rad(t));
    end[1] = r * std::sin(core::deg_to_rad(t));
  }
  return end;
}

bool Interpreter::require_feed(const BlockWords& w) {
  const ModalState& s = state_;
  if (s.feed_mode == FeedMode::InverseTime && !w.has('F')) {
    return error(core::Code::NoFeedRate, 0, "inverse time feed (G93) needs F on every feed move");
  }
  if (s.feed <= 0.0) {
    return error(core::Code::NoFeedRate, 0,
                 fmt::format("{} with no feed rate: give F", g_name(w.motion).data()));
  }
  return true;
}

bool Interpreter::motion(BlockWords& w) {
  const GCode g = w.motion;
  if (w.has_polar() && (w.has('X') || w.has('Y'))) {
    return error(core::Code::AxisWordsConflict, w.col_of('X') != 0 ? w.col_of('X') : w.col_of('Y'),
                 "polar words (@ ^) and X/Y in one block");
  }
  if (w.has_polar() && state_.plane != core::Plane::XY) {
    return error(core::Code::NotAllowedInMode, 0, "polar words need the XY plane (G17)");
  }
  const GCode previous = state_.motion;
  state_.motion = g;
  const bool drilling = g == 730 || g == 740 || (g >= 810 && g <= 890);
  if (!drilling) cycles_.note_other_motion();
  if (g == 800) return true;
  const bool g53 = w.g[kGroupNonModal] == 530;
  if (g == 0 || g == 10 || g == 330 || g == 331) return straight(w, g, target(w, g53));
  if (g == 20 || g == 30) return arc(w, g, target(w, false));
  if (g >= 382 && g <= 385) return probe(w, target(w, false));
  if ((g >= 50 && g <= 53) || g == 62) return spline(w, g, target(w, false));
  return cycle(w, g, previous);
}

bool Interpreter::straight(BlockWords& w, GCode g, const Axes& end) {
  // G33/G33.1 move with the spindle (K per revolution), not at F.
  if (g == 10 && !require_feed(w)) return false;
  if ((comp_.active() || !comp_.arc_allowed()) && (g == 0 || g == 10)) {
    if (auto e = comp_.straight(xyz(end), g == 0, run_.loc(), machine_); !e)
      return error(e.error());
    return true;
  }
  if (g == 0) {
    machine_.traverse_axes(end);
  } else if (g == 331) {
    // G33.1 rigid tapping: in to the depth and back out, synchronised.
    const Axes start = state_.pos;
    machine_.feed_axes(end);
    machine_.feed_axes(start);
  } else {
    machine_.feed_axes(end);
  }
  return true;
}

bool Interpreter::arc(BlockWords& w, GCode g, const Axes& end) {
  if (!require_feed(w)) return false;
  const core::Plane plane = state_.plane;
  const core::PlaneAxes ax = core::axes_of(plane);
  Vec3 start3 = xyz(state_.pos);
  if (auto programmed = comp_.programmed_position()) start3 = *programmed;
  const Vec2 start = core::in_plane(start3, plane);
  const Vec2 stop = core::in_plane(xyz(end), plane);
  const bool ccw = g == 30;
  const char first = "IJK"[ax.first];
  const char second = "IJK"[ax.second];
  // LinuxCNC convert_arc: a centre word of the plane's axis is an error.
  const char axial = "IJK"[ax.axial];
  if (w.has(axial)) {
    return error(
        core::Code::UnusedWord, w.col_of(axial),
        fmt::format("{} word in a {} arc: its plane's centre words are {} and {}", axial,
                    plane == core::Plane::XY ? "G17" : (plane == core::Plane::ZX ? "G18" : "G19"),
                    first, second));
  }
  int turns = 1;
  if (w.has('P')) {
    auto p = whole(w, 'P', 1, 1000000);
    if (!p) return false;
    turns = *p;
  }
  const std::optional<Vec2> center = w.has('R')
                                         ? radius_arc_center(w, start, stop, ccw, first, second)
                                         : offset_arc_center(w, g, start, stop, first, second);
  if (!center || !arc_in_range(w, start, stop, *center, ax.first, ax.second)) return false;
  Vec3 c3 = core::from_plane(*center, start3[ax.axial], plane);
  if (comp_.active() || !comp_.arc_allowed()) {
    if (auto e = comp_.arc(xyz(end), c3, ccw ? turns : -turns, run_.loc(), machine_); !e)
      return error(e.error());
    return true;
  }
  machine_.arc_axes(end, c3, ccw ? turns : -turns);
  return true;
}

// The arc's centre within canon's range, and its angle large enough to
// tell from a full circle: with a radius a billion times its chord the back
// ends (core::arc_sweep) would close it into a full turn of that radius.
// The diagnostic points at R or at the centre word that made it.
bool Interpreter::arc_in_range(const BlockWords& w, Vec2 start, Vec2 stop, Vec2 center,
                               int first_axis, int second_axis) {
  const char first = "IJK"[first_axis];
  const char second = "IJK"[second_axis];
  const std::uint32_t col =
      w.has('R') ? w.col_of('R') : (w.has(first) ? w.col_of(first) : w.col_of(second));
  const double coords[] = {center.x, center.y};
  const int axes[] = {first_axis, second_axis};
  for (int k = 0; k < 2; ++k) {
    const std::string what = fmt::format("the arc's centre {}", "XYZ"[axes[k]]);
    if (auto in_range = canon::check_length(what.c_str(), coords[k]); !in_range) {
      return error(core::Code::ValueOutOfRange, col,
                   fmt::format("{} (usina's range: docs/rs274ngc.md, Numbers)", in_range.error()));
    }
  }
  const double radius = core::distance(start, center);
  const double chord = core::distance(start, stop);
  // A centre-format arc whose end is within the geometry tolerance of its
  // start is a full circle; an R-format arc never is.
  const bool meant_open = w.has('R') || chord > 1e-6;
  if (meant_open && chord < 1e-9 * radius) {
    return error(core::Code::ValueOutOfRange, col,
                 fmt::format("arc radius {:g} mm is too large for its chord {:g} mm: it turns "
                             "{:g} rad, which usina cannot tell from a full circle; program a "
                             "straight move (G1)",
                             radius, chord, chord / radius));
  }
  return true;
}

// The centre of an R-format arc: of the two circles of radius |R| through
// start and end, the one R's sign picks (core::arc_center_from_radius).
// Half the chord may exceed |R| by LinuxCNC's RADIUS_TOLERANCE (0.00005 in,
// 0.00127 mm, in either unit: interp_arc.cc arc_data_r); the arc is then a
// half circle.
std::optional<Vec2> Interpreter::radius_arc_center(const BlockWords& w, Vec2 start, Vec2 stop,
                                                   bool ccw, char first, char second) {
  constexpr double kRadiusTolerance = 0.00005 * 25.4;
  if (w.has(first) || w.has(second)) {
    error(core::Code::ArcMissingCenter, w.col_of('R'), "an arc takes R or I/J/K, not both");
    return std::nullopt;
  }
  const double r = mm(w.get('R'));
  if (core::distance(start, stop) < 1e-12) {
    error(core::Code::ArcZeroLength, w.col_of('R'),
          "R-format arc with its end at its start: use I/J/K for a full circle");
    return std::nullopt;
  }
  auto c = core::arc_center_from_radius(start, stop, r, ccw, kRadiusTolerance);
  if (!c) {
    error(core::Code::ArcRadiusTooSmall, w.col_of('R'),
          fmt::format("arc radius {:.4f} mm is smaller than half the chord {:.4f} mm", std::fabs(r),
                      core::distance(start, stop) / 2));
    return std::nullopt;
  }
  return *c;
}

// The centre of a centre-format arc: I J K from the start (or, under G90.1,
// absolute), checked to lie as far from the end as from the start.
std::optional<Vec2> Interpreter::offset_arc_center(const BlockWords& w, GCode g, Vec2 start,
                                                   Vec2 stop, char first, char second) {
  if (!w.has(first) && !w.has(second)) {
    error(core::Code::ArcMissingCenter, 0,
          fmt::format("{} needs the centre ({} and/or {}) or R", g_name(g).data(), first, second));
    return std::nullopt;
  }
  const Vec2 off{w.has(first) ? mm(w.get(first)) : 0.0, w.has(second) ? mm(w.get(second)) : 0.0};
  const Vec2 center = state_.arc_absolute ? off : start + off;
  const double r1 = core::distance(start, center);
  const double r2 = core::distance(stop, center);
  if (const double least = rules_.min_arc_radius_mm; r1 < least || r2 < least) {
    error(core::Code::ArcZeroLength, 0,
          fmt::format("arc of zero radius: the centre is {:.4f} mm from the start and {:.4f} mm "
                      "from the end, less than LinuxCNC's {:.5f} mm",
                      r1, r2, least));
    return std::nullopt;
  }
  // LinuxCNC accepts a small difference (a spiral): up to 2·0.001·√2 in
  // (2·0.01·√2 mm), or 0.1 % of the larger radius.
  const double abs_tol =
      (state_.units == core::LengthUnit::Inch ? 0.002 * 25.4 : 0.02) * std::sqrt(2.0);
  const double diff = std::fabs(r1 - r2);
  if (diff > abs_tol && diff > 0.001 * std::max(r1, r2)) {
    error(core::Code::ArcRadiusMismatch, 0,
          fmt::format("arc end ({:.4f}, {:.4f}) is {:.4f} mm off the circle of radius {:.4f} about "
                      "({:.4f}, {:.4f}); use R, or correct {}/{}",
                      stop.x, stop.y, std::fabs(r1 - r2), r1, center.x, center.y, first, second));
    return std::nullopt;
  }
  if (r1 < 1e-9) {
    error(core::Code::ArcZeroLength, 0, "arc of zero radius: the centre is at the start point");
    return std::nullopt;
  }
  return center;
}

bool Interpreter::probe(BlockWords& w, const Axes& end) {
  if (!require_feed(w)) return false;
  if (state_.comp != CompSideState::Off) {
    return error(core::Code::ProbeBadMove, 0, "probing with cutter compensation on");
  }

  // No probe in a trace: the move is traced to its target and the probe
  // result is what LinuxCNC's stand-alone interpreter reports, a stop short
  // of the target, not tripped (#5070 = 0); the current point is that stop
  // (its conformance traces, smartprobe.ngc, x-trim.ngc). saicanon.cc backs
  // off 0.01 under G20 and 0.254 under G21: 0.254 mm in either unit.
  constexpr double kProbeBackOffMm = 0.254;
  // Along the move the canon makes: from where its last move ended, which is
  // not the current point when a tool length offset or a work offset has
  // changed since (G43 H12, then G38.4: the probe goes down as it goes
  // over, and backs off up along that line; differential fuzzer, seed
  // 8114888).
  const Vec3 dir = xyz(end) - machine_.last_emitted();
  const double length = core::norm(dir);
  const Vec3 stop = length > 0.0 ? xyz(end) - dir * (kProbeBackOffMm / length) : xyz(end);
  machine_.probe_axes(end, stop);
  Axes result = end;
  set_xyz(result, stop);
  set_xyz(state_.pos, stop);
  for (int a = 0; a < kAxisCount; ++a) {
    const double v = result[static_cast<std::size_t>(a)];
    params_.set(5061 + a, is_rotary(a) ? v : v / core::mm_per(state_.units));
  }
  params_.set(5070, 0.0);
  return true;
}

}  // namespace usina::gcode
