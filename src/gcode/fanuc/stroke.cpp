// G22/G23 stored stroke check 2 of the fanuc dialect (docs/fanuc.md §7):
// `G22 X Y Z I J K` arms a box whose inside (parameter 1300 bit 0 OUT = 0)
// or outside (OUT = 1) the tool may not enter; every later move is checked,
// straight ones exactly (segment against box), arcs by chords within a
// small tolerance, and the first move that enters stops the run with
// Fanuc's overtravel alarm (OT0502 in the + direction, OT0503 in the -).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "gcode/fanuc/engine.hpp"

namespace usina::gcode::fanuc {
namespace {

constexpr double kEps = 1e-9;        // mm: a move along the boundary does not enter
constexpr double kChordMm = 0.001;   // an arc's chords stay this close to it
constexpr int kMaxChords = 100'000;  // a huge arc is checked a little coarser

std::string alarm(int axis, double direction) {
  return fmt::format("{} {}{} overtravel (stored stroke check 2)",
                     direction >= 0 ? "OT0502" : "OT0503", direction >= 0 ? '+' : '-', "XYZ"[axis]);
}

// The points of an arc or helix from `from`, about `c.center`, within
// kChordMm of the curve.
std::vector<core::Vec3> arc_points(core::Vec3 from, const canon::Arc& c) {
  const core::Vec3 n = c.normal;
  auto along = [&](core::Vec3 p) { return p.x * n.x + p.y * n.y + p.z * n.z; };
  const core::Vec3 u = from - c.center;
  const core::Vec3 v = c.to - c.center;
  const core::Vec3 u0 = u - n * along(u);
  const core::Vec3 v0 = v - n * along(v);
  const double r = std::hypot(u0.x, u0.y, u0.z);
  auto cross = [&](core::Vec3 a) {
    return core::Vec3{n.y * a.z - n.z * a.y, n.z * a.x - n.x * a.z, n.x * a.y - n.y * a.x};
  };
  const core::Vec3 nu = cross(u0);
  double sweep =
      std::atan2(nu.x * v0.x + nu.y * v0.y + nu.z * v0.z, u0.x * v0.x + u0.y * v0.y + u0.z * v0.z);
  const double turn = 2 * std::numbers::pi;
  if (c.turn > 0 && sweep <= kEps) sweep += turn;
  if (c.turn < 0 && sweep >= -kEps) sweep -= turn;
  sweep += (c.turn > 0 ? 1 : -1) * turn * (std::abs(c.turn) - 1);
  const double step = r > kChordMm ? 2 * std::acos(1 - kChordMm / r) : turn;
  const int chords =
      std::clamp(static_cast<int>(std::ceil(std::fabs(sweep) / step)), 1, kMaxChords);
  const double a0 = along(u), a1 = along(v);
  std::vector<core::Vec3> points;
  for (int k = 1; k <= chords; ++k) {
    const double t = static_cast<double>(k) / chords;
    const double th = sweep * t;
    points.push_back(c.center + u0 * std::cos(th) + cross(u0) * std::sin(th) +
                     n * (a0 + (a1 - a0) * t));
  }
  points.back() = c.to;
  return points;
}

}  // namespace

tl::expected<void, std::string> StrokeCheck::forbidden(core::Vec3 p) const {
  if (!area_) return {};
  for (int a = 0; a < 3; ++a) {
    const bool below = p[a]<area_->lo[a] - kEps, above = p[a]> area_->hi[a] + kEps;
    if (outside_forbidden && (below || above)) return tl::unexpected(alarm(a, above ? 1 : -1));
  }
  if (outside_forbidden) return {};
  for (int a = 0; a < 3; ++a)
    if (p[a] <= area_->lo[a] + kEps || p[a] >= area_->hi[a] - kEps) return {};
  return tl::unexpected(alarm(0, 1));
}

// The segment a-b against the box: slabs for the inside, the end point for
// the outside (the box is convex: a segment that leaves it ends outside).
tl::expected<void, std::string> StrokeCheck::segment(core::Vec3 a, core::Vec3 b) const {
  if (outside_forbidden) return forbidden(b);
  double enter = 0, leave = 1;
  int axis = 0;
  for (int k = 0; k < 3; ++k) {
    const double lo = area_->lo[k] + kEps, hi = area_->hi[k] - kEps, d = b[k] - a[k];
    if (std::fabs(d) < 1e-15) {
      if (a[k] <= lo || a[k] >= hi) return {};
      continue;
    }
    double t1 = (lo - a[k]) / d, t2 = (hi - a[k]) / d;
    if (t1 > t2) std::swap(t1, t2);
    if (t1 > enter) {
      enter = t1;
      axis = k;
    }
    leave = std::min(leave, t2);
    if (enter >= leave) return {};
  }
  return tl::unexpected(alarm(axis, b[axis] - a[axis]));
}

tl::expected<void, std::string> StrokeCheck::path(const std::vector<core::Vec3>& points) const {
  core::Vec3 from = at_;
  for (const core::Vec3& p : points) {
    if (auto ok = segment(from, p); !ok) return ok;
    from = p;
  }
  return {};
}

namespace {

// Where a move ends: the tool's place after it (none for other ops).
std::optional<core::Vec3> move_end(const canon::Op& op) {
  if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) return t->to;
  if (const auto* f = std::get_if<canon::Feed>(&op.kind)) return f->to;
  if (const auto* p = std::get_if<canon::Probe>(&op.kind)) return p->to;
  if (const auto* a = std::get_if<canon::Arc>(&op.kind)) return a->to;
  const auto* s = std::get_if<canon::Spline>(&op.kind);
  if (s != nullptr && !s->points.empty()) return s->points.back();
  return std::nullopt;
}

}  // namespace

void StrokeCheck::on(const canon::Op& op) {
  if (violation_) return;  // the control stopped at the alarm
  const std::optional<core::Vec3> end = move_end(op);
  // The path, as points, only while an area is armed.
  if (area_ && end) {
    std::vector<core::Vec3> points = {*end};
    if (const auto* s = std::get_if<canon::Spline>(&op.kind)) points = s->points;
    if (const auto* a = std::get_if<canon::Arc>(&op.kind)) points = arc_points(at_, *a);
    if (auto ok = path(points); !ok) {
      violation_ = Violation{op.src, ok.error()};
      return;
    }
  }
  if (end) {
    at_ = *end;
    passed_ = false;
  }
  next_.on(op);
}

// G22 X Y Z I J K arms the area (corners in the coordinates of the trace:
// docs/fanuc.md); G23 disarms it.
bool Engine::stroke_codes(const TapeBlock& b, Words& w) {
  const bool on = w.has_g(220), off = w.has_g(230);
  if (on && off) return error(core::Code::ModalGroupConflict, b, 0, "G22 and G23 in one block");
  if (off) {
    w.take_g(230);
    stroke_.disarm();
    return true;
  }
  if (!on) return true;
  const double per = core::mm_per(interp_.state().units);
  StrokeCheck::Box box;
  static constexpr std::string_view kCorners = "XYZIJK";
  for (std::size_t k = 0; k < kCorners.size(); ++k) {
    const NcWord* word = w.find(kCorners[k]);
    if (word == nullptr) {
      return error(core::Code::MissingWord, b, 0,
                   "G22 needs X Y Z and I J K (two opposite corners of the area)");
    }
    (k < 3 ? box.hi : box.lo)[static_cast<int>(k % 3)] = word->value * per;
  }
  for (int a = 0; a < 3; ++a) {
    if (box.lo[a] > box.hi[a]) std::swap(box.lo[a], box.hi[a]);
  }
  w.take_g(220);
  for (char c : kCorners)
    w.take(c);
  stroke_.arm(box, interp_.last_move_end());
  if (const auto ok = stroke_.forbidden(stroke_.position()); !ok) {
    return error(
        core::Code::ForbiddenArea, b, 0,
        fmt::format("{}: the tool is already in the forbidden area when G22 arms it", ok.error()));
  }
  return true;
}

// Reports a move into the forbidden area once, at its block.
bool Engine::stroke_violation() {
  const auto& v = stroke_.violation();
  if (!v) return false;
  if (!failed_ || !reported_stroke_) {
    reported_stroke_ = true;
    diags_.report({core::Code::ForbiddenArea, core::Severity::Error, v->loc,
                   fmt::format("{}: the move enters the forbidden area of G22", v->message)});
    failed_ = true;
  }
  return true;
}

}  // namespace usina::gcode::fanuc
