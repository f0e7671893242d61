// G16 polar coordinates, G51 scaling, G51.1 mirror and G68 rotation of the
// fanuc dialect (docs/fanuc.md §7): the front end keeps the programmed XY
// point and gives the interpreter the transformed one.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "gcode/dialects/fanuc_engine.hpp"

namespace usina::gcode::fanuc {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

core::Vec2 rotate(core::Vec2 v, double deg) {
  const double c = std::cos(deg * kRad), s = std::sin(deg * kRad);
  return {v.x * c - v.y * s, v.x * s + v.y * c};
}

int tenths(double v) {
  return static_cast<int>(std::lround(v * 10.0));
}

}  // namespace

core::Vec2 Transform::apply(core::Vec2 p) const {
  if (mirror_x) p.x = 2 * mirror_cx - p.x;
  if (mirror_y) p.y = 2 * mirror_cy - p.y;
  if (scaling) p = {scale_cx + (p.x - scale_cx) * scale_x, scale_cy + (p.y - scale_cy) * scale_y};
  if (rotation) {
    const core::Vec2 r = rotate({p.x - rot_cx, p.y - rot_cy}, rot_deg);
    p = {rot_cx + r.x, rot_cy + r.y};
  }
  return p;
}

core::Vec2 Transform::inverse(core::Vec2 q) const {
  if (rotation) {
    const core::Vec2 r = rotate({q.x - rot_cx, q.y - rot_cy}, -rot_deg);
    q = {rot_cx + r.x, rot_cy + r.y};
  }
  if (scaling) q = {scale_cx + (q.x - scale_cx) / scale_x, scale_cy + (q.y - scale_cy) / scale_y};
  if (mirror_y) q.y = 2 * mirror_cy - q.y;
  if (mirror_x) q.x = 2 * mirror_cx - q.x;
  return q;
}

bool Transform::reverses() const {
  bool r = mirror_x != mirror_y;
  if (scaling && (scale_x < 0) != (scale_y < 0)) r = !r;
  return r;
}

core::Vec2 Engine::actual_xy() const {
  const Axes& p = interp_.state().pos;
  const double per = core::mm_per(interp_.state().units);
  return {p[0] / per, p[1] / per};
}

void Engine::reset_program_point() {
  prog_ = xf_.inverse(actual_xy());
  if (polar_) {
    polar_r_ = std::hypot(prog_.x, prog_.y);
    polar_a_ = std::atan2(prog_.y, prog_.x) / kRad;
  }
}

// The modal codes of the transformations: they take their words.
bool Engine::transform_codes(const TapeBlock& b, Words& w) {
  bool changed = false;
  const core::Vec2 here = actual_xy();
  auto factor = [&](char l) -> std::optional<double> {
    NcWord* f = w.find(l);
    if (f == nullptr) return std::nullopt;
    // Scale factors without a point are in 0.001 units whatever DPI says.
    return f->integer_literal ? f->raw * 0.001 : f->raw;
  };
  if (w.has_g(150) || w.has_g(160)) {
    polar_ = w.has_g(160);
    w.take_g(150);
    w.take_g(160);
    changed = true;
  }
  if (w.has_g(500)) {
    w.take_g(500);
    xf_.scaling = false;
    changed = true;
  }
  if (w.has_g(510)) {
    w.take_g(510);
    const double p = factor('P').value_or(1.0);
    xf_.scale_x = factor('I').value_or(p);
    xf_.scale_y = factor('J').value_or(p);
    if (xf_.scale_x == 0 || xf_.scale_y == 0)
      return error(core::Code::ScaleOutOfRange, b, 0, "G51: a scale factor of 0");
    xf_.scale_cx = w.get('X', here.x);
    xf_.scale_cy = w.get('Y', here.y);
    for (char l : std::string_view("XYZPIJK"))
      w.take(l);
    xf_.scaling = true;
    changed = true;
  }
  if (w.has_g(501)) {
    w.take_g(501);
    const bool any = w.has('X') || w.has('Y');
    if (!any || w.has('X')) xf_.mirror_x = false;
    if (!any || w.has('Y')) xf_.mirror_y = false;
    w.take('X');
    w.take('Y');
    changed = true;
  }
  if (w.has_g(511)) {
    w.take_g(511);
    if (w.has('X')) {
      xf_.mirror_x = true;
      xf_.mirror_cx = w.get('X', 0);
    }
    if (w.has('Y')) {
      xf_.mirror_y = true;
      xf_.mirror_cy = w.get('Y', 0);
    }
    w.take('X');
    w.take('Y');
    changed = true;
  }
  if (w.has_g(690)) {
    w.take_g(690);
    xf_.rotation = false;
    changed = true;
  }
  if (w.has_g(680)) {
    w.take_g(680);
    if (interp_.state().plane != core::Plane::XY)
      return error(core::Code::Unsupported, b, 0, "G68 outside G17 is not implemented yet");
    xf_.rot_cx = w.get('X', here.x);
    xf_.rot_cy = w.get('Y', here.y);
    xf_.rot_deg = w.get('R', 0.0);
    w.take('X');
    w.take('Y');
    w.take('R');
    xf_.rotation = true;
    changed = true;
  }
  if (changed) reset_program_point();
  return true;
}

// The XY words of a move under the transformations.
bool Engine::transform_words(const TapeBlock& b, Words& w) {
  if (!xf_.active() && !polar_) return true;
  for (int g : {40, 100, 280, 290, 300, 520, 530, 920})
    if (w.has_g(g)) return true;
  // Copies: words are appended below, which moves the list.
  auto value = [&](char l) -> std::optional<NcWord> {
    const NcWord* f = w.find(l);
    return f != nullptr ? std::optional<NcWord>(*f) : std::nullopt;
  };
  const auto x = value('X'), y = value('Y'), i = value('I'), j = value('J');
  const int motion = cycle_;
  const bool arc = motion == 20 || motion == 30;
  if (!x && !y && !(arc && (i || j))) return true;
  if (interp_.state().plane != core::Plane::XY)
    return error(core::Code::Unsupported, b, 0,
                 "G16/G51/G51.1/G68 outside the G17 plane is not implemented yet");
  const bool incremental = w.has_g(910) || (interp_.state().incremental && !w.has_g(900));
  const core::Vec2 start_prog = prog_;
  core::Vec2 p = prog_;
  if (polar_) {
    if (arc) return error(core::Code::Unsupported, b, 0, "arcs under G16 are not implemented yet");
    if (incremental && x)
      return error(
          core::Code::Unsupported, b, x->pos,
          "a G16 radius in G91 (polar origin at the current point) is not implemented yet");
    const double radius = x ? x->value : polar_r_;
    const double angle = incremental ? polar_a_ + (y ? y->value : 0.0) : (y ? y->value : polar_a_);
    polar_r_ = radius;
    polar_a_ = angle;
    p = {radius * std::cos(angle * kRad), radius * std::sin(angle * kRad)};
  } else if (incremental) {
    p = {p.x + (x ? x->value : 0.0), p.y + (y ? y->value : 0.0)};
  } else {
    p = {x ? x->value : p.x, y ? y->value : p.y};
  }
  prog_ = p;
  const core::Vec2 actual = actual_xy();
  const core::Vec2 q = xf_.apply(p);
  const core::Vec2 out = incremental ? core::Vec2{q.x - actual.x, q.y - actual.y} : q;
  w.take('X');
  w.take('Y');
  w.list.push_back({'X', out.x, out.x, false, false, false, 0});
  w.list.push_back({'Y', out.y, out.y, false, false, false, 0});
  if (!arc) return true;
  if (xf_.scaling && std::fabs(std::fabs(xf_.scale_x) - std::fabs(xf_.scale_y)) > 1e-12)
    return error(core::Code::UnequalScaleArc, b, 0,
                 "an arc under unequal scale factors would be an ellipse");
  int g = motion;
  if (xf_.reverses()) g = g == 20 ? 30 : 20;
  for (NcWord& word : w.list)
    if (word.letter == 'G' && (tenths(word.value) == 20 || tenths(word.value) == 30))
      word.taken = true;
  w.list.push_back({'G', g / 10.0, g / 10.0, false, false, false, 0});
  if (i || j) {
    const core::Vec2 centre{start_prog.x + (i ? i->value : 0.0),
                            start_prog.y + (j ? j->value : 0.0)};
    const core::Vec2 c = xf_.apply(centre);
    w.take('I');
    w.take('J');
    w.list.push_back({'I', c.x - actual.x, 0, false, false, false, 0});
    w.list.push_back({'J', c.y - actual.y, 0, false, false, false, 0});
  } else if (NcWord* r = w.find('R'); r != nullptr && xf_.scaling) {
    r->value *= std::fabs(xf_.scale_x);
  }
  return true;
}

}  // namespace usina::gcode::fanuc
