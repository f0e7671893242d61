#include "gcode/interp/canon_machine.hpp"

#include <cmath>

#include <fmt/format.h>

#include "canon/limits.hpp"
#include "core/units.hpp"

namespace usina::gcode {

Vec3 CanonMachine::to_absolute(const Vec3& p) const {
  const ModalState& s = *state_;
  Vec3 q = p + xyz(s.g92);
  if (s.rotation_deg != 0.0) {
    const Vec2 r = core::rotate({q.x, q.y}, core::deg_to_rad(s.rotation_deg));
    q.x = r.x;
    q.y = r.y;
  }
  return q + xyz(s.g5x);
}

Vec3 CanonMachine::to_program(const Vec3& abs) const {
  const ModalState& s = *state_;
  Vec3 q = abs - xyz(s.g5x);
  if (s.rotation_deg != 0.0) {
    const Vec2 r = core::rotate({q.x, q.y}, -core::deg_to_rad(s.rotation_deg));
    q.x = r.x;
    q.y = r.y;
  }
  return q - xyz(s.g92);
}

std::optional<double> CanonMachine::feed_rate() const {
  if (feed_mode_ != FeedMode::UnitsPerMinute) return std::nullopt;
  return feed_;
}

canon::ProgrammedFeed CanonMachine::programmed_feed() const {
  using Mode = canon::ProgrammedFeed::Mode;
  switch (feed_mode_) {
  case FeedMode::InverseTime: return {Mode::InverseTime, feed_};
  case FeedMode::UnitsPerRev: return {Mode::PerRevolution, feed_};
  case FeedMode::UnitsPerMinute: break;
  }
  return {Mode::PerMinute, feed_};
}

void CanonMachine::refuse(const std::string& why) {
  faulted_ = true;
  core::SourceLoc loc = src_;
  loc.length = 0;
  diags_->report({core::Code::ValueOutOfRange, core::Severity::Error, loc,
                  fmt::format("{} (usina's ranges: docs/rs274ngc.md, Numbers); check the values, "
                              "increments, offsets and scale factors that lead here",
                              why)});
}

void CanonMachine::emit(canon::OpKind kind) {
  if (faulted_) return;
  if (auto in_range = canon::check_range(kind); !in_range) return refuse(in_range.error());
  sink_->on(canon::Op{std::move(kind), src_, origin_});
}

template <class Move>
void CanonMachine::send(Move&& move) {
  if (sink_->reads_ops()) return emit(std::forward<Move>(move));
  if (faulted_) return;
  if (auto in_range = canon::check_range(move); !in_range) return refuse(in_range.error());
  sink_->pass(src_);
}

void CanonMachine::traverse_axes(const Axes& to) {
  state_->pos = to;
  last_ = to_absolute(xyz(to));
  moved_ = true;
  send(canon::Traverse{last_, abc_of(to)});
}

void CanonMachine::feed_axes(const Axes& to) {
  state_->pos = to;
  last_ = to_absolute(xyz(to));
  moved_ = true;
  send(canon::Feed{last_, feed_rate(), abc_of(to), programmed_feed()});
}

void CanonMachine::probe_axes(const Axes& to, const Vec3& stop) {
  state_->pos = to;
  last_ = to_absolute(stop);  // what the canon reports after the probe (a tool change reads it)
  moved_ = true;
  emit(canon::Probe{to_absolute(xyz(to)), abc_of(to)});
}

void CanonMachine::arc_axes(const Axes& to, const Vec3& center, int turn) {
  const core::PlaneAxes ax = core::axes_of(state_->plane);
  // An arc whose end is apart from its start but which turns less than a
  // back end can tell from nothing (core::arc_sweep closes it into a full
  // circle): a radius a billion times its chord.
  const Vec2 start = core::in_plane(xyz(state_->pos), state_->plane);
  const Vec2 centre = core::in_plane(center, state_->plane);
  const double chord = core::distance(start, core::in_plane(xyz(to), state_->plane));
  const double radius = core::distance(start, centre);
  if (chord > 1e-6 && chord < 1e-9 * radius) {
    return refuse(
        fmt::format("the arc's radius {:g} mm is too large for its chord {:g} mm: it "
                    "could not be told from a full circle; program a straight move",
                    radius, chord));
  }
  Vec3 c = center;
  c[ax.axial] = state_->pos[static_cast<std::size_t>(ax.axial)];  // the start's axial coordinate
  Vec3 normal = core::normal_of(state_->plane);
  if (state_->rotation_deg != 0.0) {
    const Vec2 r = core::rotate({normal.x, normal.y}, core::deg_to_rad(state_->rotation_deg));
    normal.x = r.x;
    normal.y = r.y;
  }
  state_->pos = to;
  last_ = to_absolute(xyz(to));
  moved_ = true;
  emit(canon::Arc{to_absolute(xyz(to)), to_absolute(c), normal, turn, feed_rate(), abc_of(to),
                  programmed_feed()});
}

void CanonMachine::spline(const std::vector<Vec3>& points) {
  if (points.empty()) return;
  canon::Spline op;
  op.points.reserve(points.size());
  for (const Vec3& p : points)
    op.points.push_back(to_absolute(p));
  op.to = op.points.back();
  op.f = feed_rate();
  op.programmed = programmed_feed();
  set_xyz(state_->pos, points.back());
  last_ = op.to;
  moved_ = true;
  emit(std::move(op));
}

void CanonMachine::traverse(const Vec3& to) {
  Axes a = state_->pos;
  set_xyz(a, to);
  traverse_axes(a);
}

void CanonMachine::feed(const Vec3& to) {
  Axes a = state_->pos;
  set_xyz(a, to);
  feed_axes(a);
}

void CanonMachine::arc(const Vec3& to, const Vec3& center, int turn) {
  Axes a = state_->pos;
  set_xyz(a, to);
  arc_axes(a, center, turn);
}

void CanonMachine::dwell(double seconds) {
  emit(canon::Dwell{seconds});
}

void CanonMachine::spindle(canon::SpindleDir dir) {
  state_->spindle = dir;
  emit(canon::Spindle{state_->speed, dir});
}

void CanonMachine::hole(const Vec3& top, double depth) {
  emit(canon::Hole{to_absolute(top), hole_diameter_, depth});
}

}  // namespace usina::gcode
