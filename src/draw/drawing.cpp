#include "draw/drawing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "draw/layer_style.hpp"

namespace usina::draw {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Segments shorter than this add nothing (a move along Z only).
constexpr double kMinLength = 1e-6;
// A point this close to a line's extension continues it.
constexpr double kCollinear = 1e-6;

// Whether the point `to` goes on from `line` in its direction.
bool continues(const Line& line, Vec2 to) {
  const Vec2 d = line.to - line.from;
  const double len = core::norm(d);
  if (len < kMinLength) return false;
  const Vec2 step = to - line.to;
  return core::dot(d, step) > 0.0 && std::fabs(core::cross(d, to - line.from)) / len <= kCollinear;
}

// Rank of a layer in the writers' order.
std::tuple<int, int, std::string_view> order_key(const Layer& layer) {
  const std::string_view n = layer.name;
  if (n == kContourLayer) return {0, 0, n};
  if (n == kRapidLayer) return {1, 0, n};
  if (n == kHolesLayer) return {2, 0, n};
  if (n == kPocketsLayer) return {3, 0, n};
  if (const auto tool = tool_of_layer(n)) return {4, *tool, n};
  return {5, 0, n};
}

// Whether the arc passes the direction `angle` (radians).
bool arc_passes(const Arc& a, double angle) {
  const double from = a.ccw ? a.start_angle : a.end_angle;
  double d = std::fmod(angle - from, kTwoPi);
  if (d < 0) d += kTwoPi;
  return d <= arc_sweep(a);
}

}  // namespace

Vec2 arc_start(const Arc& a) {
  return a.center + Vec2{std::cos(a.start_angle), std::sin(a.start_angle)} * a.radius;
}

Vec2 arc_end(const Arc& a) {
  return a.center + Vec2{std::cos(a.end_angle), std::sin(a.end_angle)} * a.radius;
}

double arc_sweep(const Arc& a) {
  double s = a.ccw ? a.end_angle - a.start_angle : a.start_angle - a.end_angle;
  while (s <= 0.0)
    s += kTwoPi;
  while (s > kTwoPi)
    s -= kTwoPi;
  return s;
}

void Box::add(Vec2 p) {
  if (empty) {
    min = max = p;
    empty = false;
    return;
  }
  min = {std::min(min.x, p.x), std::min(min.y, p.y)};
  max = {std::max(max.x, p.x), std::max(max.y, p.y)};
}

void Box::add(const Box& b) {
  if (b.empty) return;
  add(b.min);
  add(b.max);
}

namespace {

struct BoundsOf {
  Box operator()(const Line& l) const {
    Box b;
    b.add(l.from);
    b.add(l.to);
    return b;
  }

  Box operator()(const Arc& a) const {
    Box b;
    b.add(arc_start(a));
    b.add(arc_end(a));
    for (int q = 0; q < 4; ++q) {
      const double angle = q * std::numbers::pi / 2.0;
      if (arc_passes(a, angle)) b.add(a.center + Vec2{std::cos(angle), std::sin(angle)} * a.radius);
    }
    return b;
  }

  Box operator()(const Circle& c) const {
    Box b;
    b.add(c.center - Vec2{c.radius, c.radius});
    b.add(c.center + Vec2{c.radius, c.radius});
    return b;
  }

  Box operator()(const Polyline& p) const {
    Box b;
    for (const Vec2& v : p.points)
      b.add(v);
    return b;
  }
};

}  // namespace

Box bounds_of(const Entity& e) {
  return std::visit(BoundsOf{}, e);
}

Box view_box(const Box& bounds) {
  if (bounds.empty) return {{-5.0, -5.0}, {5.0, 5.0}, false};
  const double margin = std::max(1.0, 0.05 * std::max(bounds.width(), bounds.height()));
  return {bounds.min - Vec2{margin, margin}, bounds.max + Vec2{margin, margin}, false};
}

Layer& Drawing::layer(std::string_view name) {
  for (auto& l : layers_)
    if (l->name == name) return *l;
  layers_.push_back(std::make_unique<Layer>(
      Layer{std::string(name), style_of(name), EntityList(hold_bytes_, *spill_), {}, {}}));
  return *layers_.back();
}

std::vector<const Layer*> Drawing::layers() const {
  std::vector<const Layer*> out;
  out.reserve(layers_.size());
  for (const auto& l : layers_)
    out.push_back(l.get());
  std::sort(out.begin(), out.end(),
            [](const Layer* a, const Layer* b) { return order_key(*a) < order_key(*b); });
  return out;
}

void Drawing::add_line(Layer& layer, Vec2 from, Vec2 to) {
  if (core::distance(from, to) < kMinLength) return;
  bounds_.add(from);
  bounds_.add(to);
  if (extend_run(layer, from, to)) return;
  layer.entities.push_back(Line{from, to});
  start_run(layer, from, to);
}

double Drawing::line_tolerance() const {
  double tol = std::max(tolerance_, kCollinear);
  if (picture_width_ > 0 && picture_height_ > 0) {
    const double pixel =
        std::max(bounds_.width() / picture_width_, bounds_.height() / picture_height_);
    tol = std::max(tol, 0.5 * pixel);
  }
  return tol;
}

namespace {

// The half-width of the directions from a line's start that pass within
// `tol` of a point `d` away (a point that close allows any forward one).
double half_angle(double d, double tol) {
  return d <= tol ? std::numbers::pi / 2.0 : std::asin(tol / d);
}

}  // namespace

// The line's start A stays; its end moves to `to` when `to`'s direction
// from A is within every earlier point's band and no nearer to A than
// they came (so each lies beside the line, not past its end). This is the
// cone test of the sleeve simplification: O(1) a move, whatever the run.
bool Drawing::extend_run(Layer& layer, Vec2 from, Vec2 to) {
  LineRun& run = layer.run;
  if (layer.entities.empty() || run.entity != layer.entities.size() - 1) return false;
  // A new tool's run starts with a line of its own (the pictures colour by tool).
  if (!layer.tool_runs.empty() && layer.tool_runs.back().first == layer.entities.size())
    return false;
  auto* last = std::get_if<Line>(&layer.entities.back());
  if (last == nullptr || core::distance(last->to, from) >= kMinLength) return false;
  const Vec2 v = to - last->from;
  const double d = core::norm(v);
  if (d < run.reach) return false;
  const double angle = std::atan2(core::cross(run.dir, v), core::dot(run.dir, v));
  if (angle < run.lo || angle > run.hi) return false;
  const double half = half_angle(d, line_tolerance());
  run.lo = std::max(run.lo, angle - half);
  run.hi = std::min(run.hi, angle + half);
  run.reach = d;
  last->to = to;
  return true;
}

void Drawing::start_run(Layer& layer, Vec2 from, Vec2 to) {
  const Vec2 v = to - from;
  const double d = core::norm(v);
  const double half = half_angle(d, line_tolerance());
  layer.run = {layer.entities.size() - 1, v * (1.0 / d), -half, half, d};
}

void Drawing::add_arc(Layer& layer, const Arc& arc) {
  if (arc.radius < kMinLength) return;
  bounds_.add(bounds_of(arc));
  layer.entities.push_back(arc);
}

void Drawing::add_circle(Layer& layer, const Circle& circle) {
  if (circle.radius < kMinLength) return;
  bounds_.add(bounds_of(circle));
  layer.entities.push_back(circle);
}

void Drawing::add_polyline(Layer& layer, std::vector<Vec2> points, bool closed) {
  std::vector<Vec2> kept;
  kept.reserve(points.size());
  for (const Vec2& p : points) {
    if (!kept.empty() && core::distance(kept.back(), p) < kMinLength) continue;
    if (kept.size() >= 2 && continues(Line{kept[kept.size() - 2], kept.back()}, p)) {
      kept.back() = p;
      continue;
    }
    kept.push_back(p);
  }
  if (kept.size() < 2) return;
  if (kept.size() == 2 && !closed) {
    add_line(layer, kept[0], kept[1]);
    return;
  }
  for (const Vec2& p : kept)
    bounds_.add(p);
  layer.entities.push_back(Polyline{std::move(kept), closed});
}

std::size_t Drawing::entity_count() const {
  std::size_t n = 0;
  for (const auto& l : layers_)
    n += l->entities.size();
  return n;
}

void Drawing::set_hold(std::size_t layer_bytes, std::size_t drawing_bytes, std::string folder) {
  hold_bytes_ = layer_bytes;
  spill_->hold_limit = drawing_bytes;
  spill_->set_folder(std::move(folder));
}

std::optional<std::string> Drawing::read_error() const {
  for (const auto& l : layers_)
    if (!l->entities.read_error().empty()) return l->entities.read_error();
  return std::nullopt;
}

}  // namespace usina::draw
