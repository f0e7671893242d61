// The romi dialect's cycles and patterns: G81 drilling (modal until G80),
// G25 grid, G24 bolt circle and G26 pocket (spec/romi.md, "Cycles and
// patterns"). Their moves are marked Origin::Cycle, and each hole or pocket
// is also emitted as a feature, so a part drawing shows it.
#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "gcode/romi/translate.hpp"

namespace usina::gcode::romi {
namespace {

constexpr long kMaxPatternPoints = 100'000;

}  // namespace

bool Translator::h_cycle(int code) {
  if (code == 800) {
    work_.drill.active = false;
    return true;
  }
  if (work_.comp_on) {
    return error(core::Code::CompNotAllowed, 0,
                 "G81 with cutter radius compensation on: G40 first");
  }
  if (const auto r = words_.take('R')) work_.drill.r = mm(*r);
  if (const auto z = words_.take('Z')) {
    if (*z < 0) {
      note(core::Code::DepthSignIgnored, core::Severity::Note, words_.col('Z'),
           fmt::format("G81 depth Z{}: the hole is {} mm deep (the sign is ignored)", *z,
                       std::fabs(mm(*z))));
    }
    work_.drill.depth = std::fabs(mm(*z));
    work_.drill.defined = true;
  }
  if (const auto d = words_.take('D')) {
    if (*d < 0) return error(core::Code::BadWordValue, words_.col('D'), "negative dwell");
    work_.drill.dwell = *d;
  }
  if (!work_.drill.defined)
    return error(core::Code::MissingWord, 0, "G81 needs Z: the hole's depth");
  work_.drill.active = true;
  return true;
}

// One hole at the programmed point p: approach to the R plane, feed to the
// depth, dwell, retract (G99: to the R plane; G98: to where it started).
bool Translator::drill_at(Vec2 p) {
  // G81 refuses compensation; a G41/G42 after it would offset nothing of
  // the hole but its approach.
  if (work_.comp_on) {
    return error(core::Code::CompNotAllowed, 0,
                 "a G81 hole with cutter radius compensation on: G40 first");
  }
  if (!require_feed("G81")) return false;
  if (work_.tool_diameter <= 0.0) {
    return error(core::Code::UnknownToolDiameter, 0,
                 "a drilled hole needs the tool's diameter: change the tool with T<n> M06 first");
  }
  if (!hand()) return false;  // the block's words before its first hole
  const Vec2 m = work_.tf.apply(p);
  const Vec3 now = machine_position();
  const double zr = work_.drill.r;
  const double clear = std::max(now.z, zr);
  const OpOrigin origin(interp_, canon::Origin::Cycle);
  if (now.z < zr && !hand_move(0, {now.x, now.y, zr})) return false;
  if (std::hypot(m.x - now.x, m.y - now.y) > 1e-9 && !hand_move(0, {m.x, m.y, clear})) return false;
  if (clear > zr && !hand_move(0, {m.x, m.y, zr})) return false;
  interp_.hole(run_.loc(), {m.x, m.y, 0.0}, work_.drill.depth);
  if (!hand_move(1, {m.x, m.y, -work_.drill.depth})) return false;
  if (work_.drill.dwell > 0) {
    give('G', 4);
    give('P', work_.drill.dwell);
    if (!hand()) return false;
  }
  const double back = work_.machine.retract == RetractMode::RPlane ? zr : clear;
  if (!hand_move(0, {m.x, m.y, back})) return false;
  work_.pos = {p.x, p.y, back};
  return true;
}

// A pattern's point: drilled when G81 is on, else only reached. Each
// counts against the run's iteration budget, so a loop of patterns ends.
bool Translator::at_pattern_point(Vec2 p) {
  if (!run_.count_jump(kJumps)) return false;
  if (work_.drill.active) return drill_at(p);
  return emit_line({p.x, p.y, work_.pos.z}, true);
}

bool Translator::h_grid(int) {
  moved_by_handler_ = true;
  const auto dx = words_.take('X');
  const auto dy = words_.take('Y');
  const auto nx = take_whole('I', 1, 100000);
  if (run_.failed()) return false;
  const auto ny = take_whole('J', 1, 100000);
  if (run_.failed()) return false;
  if (!nx || !ny || (!dx && !dy)) {
    return error(core::Code::MissingWord, 0,
                 "G25 needs X and/or Y (the spacing) and I, J (the number of points per row and "
                 "of rows)");
  }
  const long cols = static_cast<long>(*nx);
  const long rows = static_cast<long>(*ny);
  if (cols * rows > kMaxPatternPoints) {
    return error(core::Code::BadWordValue, words_.col('I'),
                 fmt::format("a grid of {} points: more than {}", cols * rows, kMaxPatternPoints));
  }
  const Vec2 p0{work_.pos.x, work_.pos.y};
  const Vec2 step{dx ? mm(*dx) : 0.0, dy ? mm(*dy) : 0.0};
  for (long j = 0; j < rows; ++j) {
    for (long k = 0; k < cols; ++k) {
      // Row by row, in alternating direction.
      const long i = (j % 2 == 0) ? k : cols - 1 - k;
      const Vec2 p{p0.x + static_cast<double>(i) * step.x, p0.y + static_cast<double>(j) * step.y};
      if (!at_pattern_point(p)) return false;
    }
  }
  return true;
}

bool Translator::h_bolt_circle(int) {
  moved_by_handler_ = true;
  const auto xc = words_.take('I');
  const auto yc = words_.take('J');
  const auto total = take_whole('K', 1, kMaxPatternPoints);
  if (run_.failed()) return false;
  const auto count = take_whole('L', 1, kMaxPatternPoints);
  if (run_.failed()) return false;
  const auto start = words_.take('C');
  if (!xc || !yc || !total || !count) {
    return error(core::Code::MissingWord, 0,
                 "G24 needs I J (the centre), K (points in the full circle) and L (holes)");
  }
  const Vec2 c{mm(*xc), mm(*yc)};
  const double r = std::hypot(work_.pos.x - c.x, work_.pos.y - c.y);
  if (r < 1e-9) {
    return error(core::Code::BadWordValue, words_.col('I'),
                 "G24: the current point is the circle's centre; the circle has no radius");
  }
  const double a0 =
      start ? *start : core::rad_to_deg(std::atan2(work_.pos.y - c.y, work_.pos.x - c.x));
  for (long k = 0; k < static_cast<long>(*count); ++k) {
    const double a = core::deg_to_rad(a0 + 360.0 * static_cast<double>(k) / *total);
    if (!at_pattern_point({c.x + r * std::cos(a), c.y + r * std::sin(a)})) return false;
  }
  return true;
}

canon::Outline rounded_rectangle(Vec2 c, double a, double b, double rr) {
  rr = std::min({rr, a, b});
  canon::Outline out;
  out.start = {c.x + a, c.y};
  Vec2 at = out.start;

  struct Corner {
    double sx, sy;
  };

  const std::array<Corner, 4> corners = {{{1, 1}, {-1, 1}, {-1, -1}, {1, -1}}};
  for (const Corner& k : corners) {
    // Along the side to the corner's arc, then round it.
    const Vec2 cc{c.x + k.sx * (a - rr), c.y + k.sy * (b - rr)};
    const bool vertical_first = k.sx * k.sy > 0;  // right side up, left side down
    const Vec2 in = vertical_first ? Vec2{cc.x + k.sx * rr, cc.y} : Vec2{cc.x, cc.y + k.sy * rr};
    const Vec2 to = vertical_first ? Vec2{cc.x, cc.y + k.sy * rr} : Vec2{cc.x + k.sx * rr, cc.y};
    if (core::distance(in, at) > 1e-9) out.segs.push_back({in, std::nullopt, 0});
    if (rr > 1e-9) out.segs.push_back({to, cc, 1});
    at = rr > 1e-9 ? to : in;
  }
  if (core::distance(out.start, at) > 1e-9) out.segs.push_back({out.start, std::nullopt, 0});
  return out;
}

// A rounded rectangle about c, half sizes a × b, corner radius rr, run
// counter-clockwise from the middle of its right side at height z, reached
// by a feed move from where the tool is.
bool Translator::ring(Vec2 c, double a, double b, double rr, double z) {
  if (a < 1e-9 && b < 1e-9) return true;
  const canon::Outline path = rounded_rectangle(c, a, b, rr);
  if (!emit_line({path.start.x, path.start.y, z}, false)) return false;
  return std::all_of(path.segs.begin(), path.segs.end(), [&](const canon::OutlineSegment& s) {
    const Vec3 to{s.to.x, s.to.y, z};
    return s.center ? emit_arc(to, *s.center, true, 1) : emit_line(to, false);
  });
}

}  // namespace usina::gcode::romi
