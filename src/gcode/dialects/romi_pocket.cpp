// G26, the romi pocket: between the current point and (X, Y), corner radius
// R (default the tool's radius), depth Z below the surface, finishing
// allowances I J K, D rings from the centre outwards at each of L depth
// steps, then the wall at full depth. The pocket's outline is emitted as a
// `pocket` feature before the moves.
#include <cmath>

#include <fmt/format.h>

#include "gcode/dialects/romi_engine.hpp"

namespace usina::gcode::romi {
namespace {

struct PocketWords {
  Vec2 corner;
  double depth = 0.0;
  double radius = 0.0;
  double ax = 0.0, ay = 0.0, az = 0.0;  // allowances I J K
  int rings = 1;                        // D
  int steps = 1;                        // L
};

}  // namespace

bool Engine::h_pocket(int) {
  moved_by_handler_ = true;
  if (comp_.active()) {
    return error(core::Code::CompNotAllowed, 0,
                 "G26 with cutter radius compensation on: G40 first");
  }
  if (!words_.has('X') || !words_.has('Y') || !words_.has('Z')) {
    return error(core::Code::MissingWord, 0,
                 "G26 needs X Y (the opposite corner) and Z (the depth)");
  }
  if (!require_feed("G26")) return false;
  if (tool_diameter_ <= 0.0) {
    return error(core::Code::UnknownToolDiameter, 0,
                 "a pocket needs the tool's diameter: change the tool with T<n> M06 first");
  }
  PocketWords p;
  const Vec3 p0 = pos_;
  p.corner = {incremental('X') ? p0.x + mm(*words_.take('X')) : mm(*words_.take('X')),
              incremental('Y') ? p0.y + mm(*words_.take('Y')) : mm(*words_.take('Y'))};
  const double z = *words_.take('Z');
  p.depth = std::fabs(mm(z));
  const double rt = tool_diameter_ / 2.0;
  p.radius = words_.has('R') ? mm(*words_.take('R')) : rt;
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
  const Vec2 c{(p0.x + p.corner.x) / 2, (p0.y + p.corner.y) / 2};
  const double half_w = std::fabs(p.corner.x - p0.x) / 2;
  const double half_h = std::fabs(p.corner.y - p0.y) / 2;
  if (p.radius < rt - 1e-9) {
    return error(
        core::Code::PocketTooSmall, words_.col('R'),
        fmt::format("pocket corner radius R{} is smaller than the tool's radius {}", p.radius, rt));
  }
  if (p.radius > std::min(half_w, half_h) + 1e-9) {
    return error(core::Code::BadWordValue, words_.col('R'),
                 fmt::format("pocket corner radius R{} is larger than half the pocket's side {}",
                             p.radius, std::min(half_w, half_h)));
  }
  const double hx = half_w - rt;
  const double hy = half_h - rt;
  const double rx = hx - p.ax;
  const double ry = hy - p.ay;
  if (hx < 0 || hy < 0 || rx < 0 || ry < 0 || p.ax < 0 || p.ay < 0 || p.az < 0 || p.az > p.depth) {
    return error(core::Code::PocketTooSmall, 0,
                 fmt::format("a pocket {}×{} mm cannot be cut with a {} mm tool and allowances "
                             "I{} J{} K{}",
                             2 * half_w, 2 * half_h, tool_diameter_, p.ax, p.ay, p.az));
  }
  if (z < 0) {
    note(core::Code::DepthSignIgnored, core::Severity::Note, 0,
         fmt::format("G26 depth Z{}: the pocket is {} mm deep (the sign is ignored)", z, p.depth));
  }
  if (!tf_.uniform()) {
    return error(core::Code::UnequalScaleArc, 0,
                 "a pocket under G72 with unequal factors: its corners would be ellipses");
  }
  // The feature: the pocket's own outline, after the transformation.
  canon::Outline outline = rounded_rectangle(c, half_w, half_h, p.radius);
  auto place = [&](Vec2 q) {
    const Vec3 a = machine_.to_absolute({tf_.apply(q).x, tf_.apply(q).y, 0.0});
    return Vec2{a.x, a.y};
  };
  outline.start = place(outline.start);
  for (canon::OutlineSegment& s : outline.segs) {
    s.to = place(s.to);
    if (s.center) {
      s.center = place(*s.center);
      s.turn = tf_.flips() ? -1 : 1;
    }
  }
  machine_.emit(canon::Pocket{std::move(outline), p.depth});
  CycleOrigin origin(machine_);
  if (!emit_line({c.x, c.y, p0.z}, true)) return false;
  const double rough = p.depth - p.az;
  const double corner = p.radius - rt;
  for (int k = 1; k <= p.steps; ++k) {
    const double zk = -rough * k / p.steps;
    if (!emit_line({c.x, c.y, zk}, false)) return false;
    for (int m = 1; m <= p.rings; ++m) {
      if (!count_jump()) return false;
      const double s = static_cast<double>(m) / p.rings;
      if (!ring(c, rx * s, ry * s, corner, zk)) return false;
    }
    if (!emit_line({c.x, c.y, zk}, false)) return false;
  }
  if ((p.az > 0 && !emit_line({c.x, c.y, -p.depth}, false)) || !ring(c, hx, hy, corner, -p.depth) ||
      !emit_line({c.x, c.y, -p.depth}, false) || !emit_line({c.x, c.y, p0.z}, true) ||
      !emit_line(p0, true)) {
    return false;
  }
  return true;
}

}  // namespace usina::gcode::romi
