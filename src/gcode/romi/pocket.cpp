// G26, the romi pocket: between the current point and (X, Y), corner radius
// R (default the tool's radius), depth Z below the surface, finishing
// allowances I J K, D rings from the centre outwards at each of L depth
// steps, then the wall at full depth. The pocket's outline is emitted as a
// `pocket` feature before the moves.
#include <cmath>

#include <fmt/format.h>

#include "gcode/romi/translate.hpp"

namespace usina::gcode::romi {

// The pocket's words, and the sizes the checks and the cut share (each
// measured from the pocket's centre, in mm).
struct Translator::Pocket {
  Vec3 start;      // the current point: one corner, and where the tool returns
  Vec2 corner;     // X Y, the opposite corner
  double z = 0.0;  // Z as written: only its size counts
  double depth = 0.0;
  double radius = 0.0;                  // R, the corner radius
  double ax = 0.0, ay = 0.0, az = 0.0;  // allowances I J K
  int rings = 1;                        // D
  int steps = 1;                        // L
  double tool_radius = 0.0;

  Vec2 centre() const { return {(start.x + corner.x) / 2, (start.y + corner.y) / 2}; }

  double half_w() const { return std::fabs(corner.x - start.x) / 2; }

  double half_h() const { return std::fabs(corner.y - start.y) / 2; }

  // Where the tool's centre runs when it cuts the wall at full size.
  double wall_x() const { return half_w() - tool_radius; }

  double wall_y() const { return half_h() - tool_radius; }

  // The outermost roughing ring: the wall less the finishing allowance.
  double rough_x() const { return wall_x() - ax; }

  double rough_y() const { return wall_y() - ay; }
};

bool Translator::h_pocket(int) {
  moved_by_handler_ = true;
  if (!pocket_allowed()) return false;
  Pocket p;
  if (!read_pocket(p) || !check_pocket(p)) return false;
  return emit_pocket_outline(p) && cut_pocket(p);
}

bool Translator::pocket_allowed() {
  if (work_.comp_on) {
    return error(core::Code::CompNotAllowed, 0,
                 "G26 with cutter radius compensation on: G40 first");
  }
  if (!words_.has('X') || !words_.has('Y') || !words_.has('Z')) {
    return error(core::Code::MissingWord, 0,
                 "G26 needs X Y (the opposite corner) and Z (the depth)");
  }
  if (!require_feed("G26")) return false;
  if (work_.tool_diameter <= 0.0) {
    return error(core::Code::UnknownToolDiameter, 0,
                 "a pocket needs the tool's diameter: change the tool with T<n> M06 first");
  }
  return true;
}

bool Translator::read_pocket(Pocket& p) {
  p.start = work_.pos;
  p.corner = {incremental('X') ? p.start.x + mm(*words_.take('X')) : mm(*words_.take('X')),
              incremental('Y') ? p.start.y + mm(*words_.take('Y')) : mm(*words_.take('Y'))};
  p.z = *words_.take('Z');
  p.depth = std::fabs(mm(p.z));
  p.tool_radius = work_.tool_diameter / 2.0;
  p.radius = words_.has('R') ? mm(*words_.take('R')) : p.tool_radius;
  p.ax = words_.has('I') ? mm(*words_.take('I')) : 0.0;
  p.ay = words_.has('J') ? mm(*words_.take('J')) : 0.0;
  p.az = words_.has('K') ? mm(*words_.take('K')) : 0.0;
  if (words_.has('D')) {
    auto d = take_whole('D', 1, 1000);
    if (!d) return false;
    p.rings = static_cast<int>(*d);
  }
  if (words_.has('L')) {
    auto l = take_whole('L', 1, 1000);
    if (!l) return false;
    p.steps = static_cast<int>(*l);
  }
  return true;
}

bool Translator::check_pocket(const Pocket& p) {
  const double rt = p.tool_radius;
  const double half_side = std::min(p.half_w(), p.half_h());
  if (p.radius < rt - 1e-9) {
    return error(
        core::Code::PocketTooSmall, words_.col('R'),
        fmt::format("pocket corner radius R{} is smaller than the tool's radius {}", p.radius, rt));
  }
  if (p.radius > half_side + 1e-9) {
    return error(core::Code::BadWordValue, words_.col('R'),
                 fmt::format("pocket corner radius R{} is larger than half the pocket's side {}",
                             p.radius, half_side));
  }
  if (p.wall_x() < 0 || p.wall_y() < 0 || p.rough_x() < 0 || p.rough_y() < 0 || p.ax < 0 ||
      p.ay < 0 || p.az < 0 || p.az > p.depth) {
    return error(
        core::Code::PocketTooSmall, 0,
        fmt::format("a pocket {}×{} mm cannot be cut with a {} mm tool and allowances "
                    "I{} J{} K{}",
                    2 * p.half_w(), 2 * p.half_h(), work_.tool_diameter, p.ax, p.ay, p.az));
  }
  if (p.z < 0) {
    note(
        core::Code::DepthSignIgnored, core::Severity::Note, 0,
        fmt::format("G26 depth Z{}: the pocket is {} mm deep (the sign is ignored)", p.z, p.depth));
  }
  if (!work_.tf.uniform()) {
    return error(core::Code::UnequalScaleArc, 0,
                 "a pocket under G72 with unequal factors: its corners would be ellipses");
  }
  return true;
}

// The feature: the pocket's own outline, after the transformation, before
// its moves (and after the block's words that come before them).
bool Translator::emit_pocket_outline(const Pocket& p) {
  if (!hand()) return false;
  canon::Outline outline = rounded_rectangle(p.centre(), p.half_w(), p.half_h(), p.radius);
  outline.start = work_.tf.apply(outline.start);
  for (canon::OutlineSegment& s : outline.segs) {
    s.to = work_.tf.apply(s.to);
    if (s.center) {
      s.center = work_.tf.apply(*s.center);
      s.turn = work_.tf.flips() ? -1 : 1;
    }
  }
  interp_.pocket(run_.loc(), std::move(outline), p.depth);
  return true;
}

// Plunges at the centre to each depth step and roughs in rings outwards,
// leaving the allowances; then the floor and the wall at full depth, and
// back to the start.
bool Translator::cut_pocket(const Pocket& p) {
  const OpOrigin origin(interp_, canon::Origin::Cycle);
  const Vec2 c = p.centre();
  const Vec3 p0 = p.start;
  if (!emit_line({c.x, c.y, p0.z}, true)) return false;
  const double rough = p.depth - p.az;
  const double corner = p.radius - p.tool_radius;
  for (int k = 1; k <= p.steps; ++k) {
    const double zk = -rough * k / p.steps;
    if (!emit_line({c.x, c.y, zk}, false)) return false;
    for (int m = 1; m <= p.rings; ++m) {
      if (!run_.count_jump(kJumps)) return false;
      const double s = static_cast<double>(m) / p.rings;
      if (!ring(c, p.rough_x() * s, p.rough_y() * s, corner, zk)) return false;
    }
    if (!emit_line({c.x, c.y, zk}, false)) return false;
  }
  return (p.az <= 0 || emit_line({c.x, c.y, -p.depth}, false)) &&
         ring(c, p.wall_x(), p.wall_y(), corner, -p.depth) &&
         emit_line({c.x, c.y, -p.depth}, false) && emit_line({c.x, c.y, p0.z}, true) &&
         emit_line(p0, true);
}

}  // namespace usina::gcode::romi
