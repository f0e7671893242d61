// Grbl's checks from the position (grbl/machine_check.hpp): gcode.c's arc
// radius rule and probe target, limits.c's soft limits.
#include "gcode/grbl/machine_check.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "core/arc.hpp"

namespace usina::gcode::grbl {

std::optional<core::Diagnostic> MachineCheck::block(const LineMoves& moves,
                                                    const MachineFacts& facts) {
  // Most lines: one straight move that went by unbuilt, where no travel is
  // checked. What the whole visit does for it, without the visit.
  if (moves.built.empty() && moves.passed.size() == 1 &&
      (facts.homing || !facts.travel.soft_limits)) {
    at_ = {moves.passed.front().to, true};
    return std::nullopt;
  }
  const Position start = at_;
  facts_ = &facts;
  failure_.reset();
  // A move that went by unbuilt is a traverse or a feed: checked as one.
  moves.each(
      [&](const canon::Op& o) {
        op(o);
        return !failure_;
      },
      [&](const LineMoves::Passed& p) {
        moved(p.to, p.src);
        return !failure_;
      });
  if (failure_) at_ = start;
  return std::move(failure_);
}

void MachineCheck::op(const canon::Op& op) {
  if (const auto* a = std::get_if<canon::Arc>(&op.kind)) check_arc(*a, op.src);
  if (const auto* p = std::get_if<canon::Probe>(&op.kind)) {
    if (at_.known && core::norm(p->to - at_.pos) < 1e-9) {
      fail(op.src, 33, "the probe target is the current position");
    }
    travel(p->to, op.src);
    at_.known = false;  // the probe stops short of its target: the next start is not `to`
    return;
  }
  if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) moved(t->to, op.src);
  if (const auto* f = std::get_if<canon::Feed>(&op.kind)) moved(f->to, op.src);
  if (const auto* s = std::get_if<canon::Spline>(&op.kind)) {
    for (const core::Vec3& q : s->points)
      travel(q, op.src);
    moved(s->to, op.src);
  }
}

void MachineCheck::moved(const core::Vec3& to, const core::SourceLoc& src) {
  travel(to, src);
  at_ = {to, true};
}

// Grbl's soft limits (mc_line → limits_soft_check; a jog: jog.c) on the
// machine position of a move's end: the op's (work offsets and G92
// applied) plus the G43.1 tool length on Z. A jog beyond is refused
// (error:15); any other move is alarm 2, which stops the machine.
void MachineCheck::travel(const core::Vec3& to, const core::SourceLoc& src) {
  if (failure_ || facts_->homing || !facts_->travel.soft_limits) return;
  const core::Vec3 machine = to + core::Vec3{0, 0, facts_->tool_length_mm};
  const int a = facts_->travel.beyond(machine);
  if (a < 0) return;
  const std::string what = fmt::format(
      "the machine position {}{:.4f} is outside the travel {:.3f} to 0 ($13{}={}, $20=1)", "XYZ"[a],
      machine[a], -facts_->travel.max[a], a, facts_->travel.max[a]);
  if (facts_->jog) return fail(src, 15, "the jog's target: " + what);
  failure_ = core::Diagnostic{
      core::Code::GrblAlarm, core::Severity::Error, src,
      fmt::format("grbl ALARM:2 (Soft limit): {}; Grbl stops and locks out every line until "
                  "a reset and $X or $H, so usina ends the run here",
                  what)};
}

void MachineCheck::check_arc(const canon::Arc& a, const core::SourceLoc& src) {
  if (at_.known) {
    // Grbl's rule (gcode.c): the radius to the end may differ from the
    // radius to the start by 0.005 mm, or by up to 0.5 mm when that is
    // also at most 0.1 % of the radius.
    const core::Vec3 n = a.normal;
    auto in_plane = [&](const core::Vec3& v) { return v - n * core::dot(v, n); };
    const double r = core::norm(in_plane(at_.pos - a.center));
    const double delta = std::fabs(core::norm(in_plane(a.to - a.center)) - r);
    if (delta > 0.005 && (delta > 0.5 || delta > 0.001 * r)) {
      fail(src, 33,
           fmt::format("the arc's end is {:.4f} mm off its circle of radius {:.4f} mm (Grbl "
                       "allows 0.005 mm, or 0.1 % of the radius up to 0.5 mm)",
                       delta, r));
    }
    arc_travel(a, src);
  }
  moved(a.to, src);
}

// Grbl cuts an arc into segments within $12 and checks each end.
void MachineCheck::arc_travel(const canon::Arc& a, const core::SourceLoc& src) {
  if (failure_ || !facts_->travel.soft_limits) return;
  const core::Plane plane = std::fabs(a.normal.z) > 0.5   ? core::Plane::XY
                            : std::fabs(a.normal.y) > 0.5 ? core::Plane::ZX
                                                          : core::Plane::YZ;
  const double sweep =
      core::arc_sweep(core::in_plane(at_.pos, plane), core::in_plane(a.to, plane),
                      core::in_plane(a.center, plane), a.turn > 0, std::abs(a.turn));
  for (const core::Vec3& q :
       core::linearize_arc(at_.pos, a.to, a.center, plane, sweep, facts_->travel.arc_tolerance))
    travel(q, src);
}

void MachineCheck::fail(const core::SourceLoc& src, int number, std::string_view detail) {
  failure_ = core::Diagnostic{core::Code::GrblError, core::Severity::Error, src,
                              error_message(number, detail)};
}

}  // namespace usina::gcode::grbl
