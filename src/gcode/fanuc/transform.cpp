// G16 polar coordinates, G51 scaling, G51.1 mirror and G68 rotation of the
// fanuc dialect (docs/fanuc.md §7): the front end keeps the programmed point
// and gives the interpreter the transformed one, in any of the planes
// G17 (X Y), G18 (Z X) and G19 (Y Z).
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "gcode/fanuc/engine.hpp"

namespace usina::gcode::fanuc {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;
constexpr std::string_view kAxes = "XYZ";
constexpr std::string_view kCentres = "IJK";

core::Vec2 rotate(core::Vec2 v, double deg) {
  const double c = std::cos(deg * kRad), s = std::sin(deg * kRad);
  return {v.x * c - v.y * s, v.x * s + v.y * c};
}

int tenths(double v) {
  return static_cast<int>(std::lround(v * 10.0));
}

bool is_cycle(int g) {
  return g == 730 || g == 740 || g == 760 || (g >= 810 && g <= 890);
}

bool in_plane(int axis, core::Plane plane) {
  const core::PlaneAxes a = core::axes_of(plane);
  return axis == a.first || axis == a.second;
}

// Rotates p about c in the plane by deg (counter-clockwise seen from the
// tip of the plane's normal, from the first axis towards the second).
core::Vec3 rotate_in(core::Vec3 p, core::Vec3 c, core::Plane plane, double deg) {
  const core::PlaneAxes a = core::axes_of(plane);
  const core::Vec2 r = rotate({p[a.first] - c[a.first], p[a.second] - c[a.second]}, deg);
  p[a.first] = c[a.first] + r.x;
  p[a.second] = c[a.second] + r.y;
  return p;
}

}  // namespace

// The plane a block works in: its own G17/G18/G19 comes first.
core::Plane Engine::block_plane(const Words& w) const {
  if (w.has_g(170)) return core::Plane::XY;
  if (w.has_g(180)) return core::Plane::ZX;
  if (w.has_g(190)) return core::Plane::YZ;
  return interp_.state().plane;
}

bool Transform::affects(int axis) const {
  const auto i = static_cast<std::size_t>(axis);
  return mirror[i] || (scaling && scale[axis] != 1.0) || (rotation && in_plane(axis, rot_plane));
}

core::Vec3 Transform::mirror_scale(core::Vec3 p) const {
  for (int i = 0; i < 3; ++i) {
    if (mirror[static_cast<std::size_t>(i)]) p[i] = 2 * mirror_c[i] - p[i];
    if (scaling) p[i] = scale_c[i] + (p[i] - scale_c[i]) * scale[i];
  }
  return p;
}

core::Vec3 Transform::apply(core::Vec3 p) const {
  p = mirror_scale(p);
  if (rotation) {
    const double deg = reverses(rot_plane) ? -rot_deg : rot_deg;
    p = rotate_in(p, mirror_scale(rot_c), rot_plane, deg);
  }
  return p;
}

core::Vec3 Transform::inverse(core::Vec3 q) const {
  if (rotation) {
    const double deg = reverses(rot_plane) ? -rot_deg : rot_deg;
    q = rotate_in(q, mirror_scale(rot_c), rot_plane, -deg);
  }
  for (int i = 0; i < 3; ++i) {
    if (scaling) q[i] = scale_c[i] + (q[i] - scale_c[i]) / scale[i];
    if (mirror[static_cast<std::size_t>(i)]) q[i] = 2 * mirror_c[i] - q[i];
  }
  return q;
}

bool Transform::reverses(core::Plane plane) const {
  const core::PlaneAxes a = core::axes_of(plane);
  bool r = mirror[static_cast<std::size_t>(a.first)] != mirror[static_cast<std::size_t>(a.second)];
  if (scaling && (scale[a.first] < 0) != (scale[a.second] < 0)) r = !r;
  return r;
}

core::Vec3 Engine::actual_xyz() const {
  const Axes& p = interp_.state().pos;
  const double per = core::mm_per(interp_.state().units);
  return {p[0] / per, p[1] / per, p[2] / per};
}

void Engine::reset_program_point(core::Plane plane) {
  prog_ = xf_.inverse(actual_xyz());
  polar_plane_ = plane;
  if (polar_) {
    const core::Vec2 v = core::in_plane(prog_, polar_plane_);
    polar_r_ = std::hypot(v.x, v.y);
    polar_a_ = std::atan2(v.y, v.x) / kRad;
  }
}

// The modal codes of the transformations: they take their words.
bool Engine::transform_codes(const TapeBlock& b, Words& w) {
  bool changed = false;
  const core::Vec3 here = actual_xyz();
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
    for (int i = 0; i < 3; ++i) {
      const double by_p = i < 2 || scale_z_by_p_ ? p : 1.0;
      xf_.scale[i] = factor(kCentres[static_cast<std::size_t>(i)]).value_or(by_p);
      if (xf_.scale[i] == 0)
        return error(core::Code::ScaleOutOfRange, b, 0, "G51: a scale factor of 0");
      xf_.scale_c[i] = w.get(kAxes[static_cast<std::size_t>(i)], here[i]);
    }
    for (char l : std::string_view("XYZPIJK"))
      w.take(l);
    xf_.scaling = true;
    changed = true;
  }
  const bool any_axis = w.has('X') || w.has('Y') || w.has('Z');
  if (w.has_g(501)) {
    w.take_g(501);
    for (std::size_t i = 0; i < 3; ++i)
      if (!any_axis || w.has(kAxes[i])) xf_.mirror[i] = false;
    for (char l : kAxes)
      w.take(l);
    changed = true;
  }
  if (w.has_g(511)) {
    w.take_g(511);
    for (std::size_t i = 0; i < 3; ++i) {
      if (!w.has(kAxes[i])) continue;
      xf_.mirror[i] = true;
      xf_.mirror_c[static_cast<int>(i)] = w.get(kAxes[i], 0);
    }
    for (char l : kAxes)
      w.take(l);
    changed = true;
  }
  if (w.has_g(690)) {
    w.take_g(690);
    if (xf_.rotation) after_g69_ = xf_.rot_plane;
    xf_.rotation = false;
    xf_.rot_deg = 0;
    changed = true;
  }
  if (w.has_g(680)) {
    if (!rotation_start(w, here)) return false;
    changed = true;
  }
  if (changed) reset_program_point(block_plane(w));
  return true;
}

// G68 in the selected plane: the plane's two axis words are the centre
// (absolute; omitted, the point where G68 is commanded), R the angle. With
// parameter 5400 RIN = 1 an R in G91 adds to the angle in force.
bool Engine::rotation_start(Words& w, core::Vec3 here) {
  w.take_g(680);
  const core::Plane plane = block_plane(w);
  const core::PlaneAxes a = core::axes_of(plane);
  Transform unrotated = xf_;
  unrotated.rotation = false;
  core::Vec3 c = unrotated.inverse(here);
  for (int axis : {a.first, a.second})
    c[axis] = w.get(kAxes[static_cast<std::size_t>(axis)], c[axis]);
  const bool incremental = w.has_g(910) || (interp_.state().incremental && !w.has_g(900));
  const double r = w.get('R', 0.0);  // omitted: parameter 5410, 0
  xf_.rot_deg = rotation_incremental_ && incremental ? (xf_.rotation ? xf_.rot_deg : 0.0) + r : r;
  xf_.rot_c = c;
  xf_.rot_plane = plane;
  xf_.rotation = true;
  for (char l : kAxes)
    if (in_plane(static_cast<int>(kAxes.find(l)), plane)) w.take(l);
  w.take('R');
  return true;
}

// The end point of a move under G16, in the selected plane: the first axis
// word is the radius, the second the angle. A radius in G91 measures from
// the current point; otherwise from the work zero. An angle in G91 adds to
// the angle of the current point.
void Engine::polar_point(const std::array<std::optional<NcWord>, 3>& axis, bool incremental,
                         core::Plane plane, core::Vec3& p) {
  const core::PlaneAxes a = core::axes_of(plane);
  const auto& radius = axis[static_cast<std::size_t>(a.first)];
  const auto& angle_word = axis[static_cast<std::size_t>(a.second)];
  const double angle = !angle_word   ? polar_a_
                       : incremental ? polar_a_ + angle_word->value
                                     : angle_word->value;
  const core::Vec2 dir{std::cos(angle * kRad), std::sin(angle * kRad)};
  if (radius && incremental) {
    p[a.first] += radius->value * dir.x;
    p[a.second] += radius->value * dir.y;
    const core::Vec2 v = core::in_plane(p, plane);
    polar_r_ = std::hypot(v.x, v.y);
    polar_a_ = polar_r_ > 1e-12 ? std::atan2(v.y, v.x) / kRad : angle;
  } else {
    polar_r_ = radius ? radius->value : polar_r_;
    polar_a_ = angle;
    p[a.first] = polar_r_ * dir.x;
    p[a.second] = polar_r_ * dir.y;
  }
}

// [16MC] p. 354: "the first move command after G69 must be an absolute
// command". The first move that names an axis of the cancelled rotation's
// plane decides; G28/G30 (to the reference position) and G53 (machine
// coordinates) end the watch too. Blocks that set values rather than move
// (G04 X, G10, G22, G52, G92) are not moves.
void Engine::check_after_rotation(const TapeBlock& b, const Words& w) {
  if (!after_g69_) return;
  for (int g : {40, 100, 220, 520, 920})
    if (w.has_g(g)) return;
  const core::PlaneAxes a = core::axes_of(*after_g69_);
  const NcWord* word = nullptr;
  for (const NcWord& n : w.list) {
    const auto axis = kAxes.find(n.letter);
    if (!n.taken && !n.vacant && axis != std::string_view::npos &&
        (static_cast<int>(axis) == a.first || static_cast<int>(axis) == a.second)) {
      word = &n;
      break;
    }
  }
  if (word == nullptr) return;
  after_g69_.reset();
  for (int g : {280, 300, 530})
    if (w.has_g(g)) return;
  if (w.has_g(910) || (interp_.state().incremental && !w.has_g(900))) {
    warn(core::Code::IncrementalAfterG69, b, word->pos,
         "the first move after G69 (rotation cancel) is incremental: Fanuc wants it absolute "
         "(G90), an incremental one may end at a wrong position on the control");
  }
}

// The axis words of a move under the transformations.
bool Engine::transform_words(const TapeBlock& b, Words& w) {
  check_after_rotation(b, w);
  if (!xf_.active() && !polar_) return true;
  for (int g : {40, 100, 280, 290, 300, 520, 530, 920})
    if (w.has_g(g)) return true;
  const core::Plane plane = block_plane(w);
  const core::PlaneAxes pa = core::axes_of(plane);
  // Copies: words are appended below, which moves the list.
  std::array<std::optional<NcWord>, 3> axis, centre;
  std::array<bool, 3> affected{};
  bool any = false;
  const bool arc = cycle_ == 20 || cycle_ == 30;
  for (std::size_t i = 0; i < 3; ++i) {
    const int n = static_cast<int>(i);
    if (const NcWord* f = w.find(kAxes[i])) axis[i] = *f;
    if (const NcWord* f = w.find(kCentres[i])) centre[i] = *f;
    affected[i] = xf_.affects(n) || (polar_ && in_plane(n, plane));
    any = any || (affected[i] && axis[i]) || (arc && in_plane(n, plane) && centre[i]);
  }
  if (!any) return true;
  if (is_cycle(cycle_) && affected[static_cast<std::size_t>(pa.axial)]) {
    return error(core::Code::Unsupported, b, 0,
                 "a canned cycle whose drilling axis is scaled, mirrored, rotated or polar is not "
                 "implemented");
  }
  if (arc && xf_.rotation && xf_.rot_plane != plane) {
    return error(core::Code::NotAllowedInMode, b, 0,
                 "an arc outside the plane of the G68 rotation (Fanuc alarm 144)");
  }
  if (polar_ && plane != polar_plane_) reset_program_point(plane);
  const bool incremental = w.has_g(910) || (interp_.state().incremental && !w.has_g(900));
  const core::Vec3 actual = actual_xyz();
  for (std::size_t i = 0; i < 3; ++i)  // untransformed axes follow the interpreter
    if (!affected[i]) prog_[static_cast<int>(i)] = actual[static_cast<int>(i)];
  const core::Vec3 start_prog = prog_;
  core::Vec3 p = prog_;
  for (std::size_t i = 0; i < 3; ++i) {
    const int n = static_cast<int>(i);
    if (axis[i] && !(polar_ && in_plane(n, plane)))
      p[n] = incremental ? p[n] + axis[i]->value : axis[i]->value;
  }
  if (polar_) polar_point(axis, incremental, plane, p);
  prog_ = p;
  if (const NcWord* l = w.find('L'); l != nullptr && incremental && is_cycle(cycle_))
    prog_ = start_prog + (p - start_prog) * static_cast<double>(std::lround(l->value));
  const core::Vec3 q = xf_.apply(p);
  for (std::size_t i = 0; i < 3; ++i) {
    if (!affected[i]) continue;
    const int n = static_cast<int>(i);
    const double out = incremental ? q[n] - actual[n] : q[n];
    w.take(kAxes[i]);
    // At the word it came from, for the diagnostics of its value.
    w.add({kAxes[i], out, out, false, false, false, axis[i] ? axis[i]->pos : 0});
  }
  return !arc || transformed_arc(b, w, plane, centre, start_prog);
}

// The direction, centre and radius of an arc under the transformations.
// Under G16 an arc takes its radius as R.
bool Engine::transformed_arc(const TapeBlock& b, Words& w, core::Plane plane,
                             const std::array<std::optional<NcWord>, 3>& centre,
                             core::Vec3 start_prog) {
  const core::PlaneAxes pa = core::axes_of(plane);
  const auto first = static_cast<std::size_t>(pa.first),
             second = static_cast<std::size_t>(pa.second);
  if (polar_ && (centre[first] || centre[second])) {
    const NcWord& c = centre[first] ? *centre[first] : *centre[second];
    return error(core::Code::NotAllowedInMode, b, c.pos,
                 "under G16 an arc takes its radius as R, not I J K");
  }
  if (xf_.scaling &&
      std::fabs(std::fabs(xf_.scale[pa.first]) - std::fabs(xf_.scale[pa.second])) > 1e-12)
    return error(core::Code::UnequalScaleArc, b, 0,
                 "an arc under unequal scale factors would be an ellipse");
  int g = cycle_;
  if (xf_.reverses(plane)) g = g == 20 ? 30 : 20;
  for (NcWord& word : w.list)
    if (word.letter == 'G' && (tenths(word.value) == 20 || tenths(word.value) == 30))
      word.taken = true;
  w.add({'G', g / 10.0, g / 10.0, false, false, false, 0});
  if (centre[first] || centre[second]) {
    core::Vec3 c = start_prog;
    for (std::size_t i : {first, second})
      if (centre[i]) c[static_cast<int>(i)] += centre[i]->value;
    const core::Vec3 cq = xf_.apply(c);
    const core::Vec3 actual = actual_xyz();
    for (std::size_t i : {first, second}) {
      const double v = cq[static_cast<int>(i)] - actual[static_cast<int>(i)];
      w.take(kCentres[i]);
      w.add({kCentres[i], v, v, false, false, false, 0});
    }
  } else if (NcWord* r = w.find('R'); r != nullptr && xf_.scaling) {
    r->value *= std::fabs(xf_.scale[pa.first]);
  }
  return true;
}

}  // namespace usina::gcode::fanuc
