#include "draw/builder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <type_traits>
#include <vector>

#include <fmt/format.h>

#include "core/arc.hpp"
#include "draw/layer_style.hpp"

namespace usina::draw {
namespace {

using core::Vec3;

Vec2 xy(const Vec3& v) {
  return {v.x, v.y};
}

// The plane an arc turns in, from its normal (the axis it is closest to).
core::Plane plane_of(const Vec3& normal) {
  const double ax = std::fabs(normal.x);
  const double ay = std::fabs(normal.y);
  const double az = std::fabs(normal.z);
  if (az >= ax && az >= ay) return core::Plane::XY;
  return ax >= ay ? core::Plane::YZ : core::Plane::ZX;
}

// A hole whose tool diameter is unknown: a cross of this half-size (mm).
constexpr double kHoleMarker = 1.0;
// Points closer than this are one point (a full circle's start and end).
constexpr double kSamePoint = 1e-6;

// What a segment, an arc or a circle is, at the SVG's resolution: its
// layer, its kind and its numbers in units of 0.0001 mm (a line's ends in
// order, an arc turned counter-clockwise).
struct DrawnKey {
  const Layer* layer = nullptr;
  int kind = 0;
  std::array<std::int64_t, 6> v{};

  bool operator==(const DrawnKey&) const = default;
};

struct DrawnKeyHash {
  std::size_t operator()(const DrawnKey& k) const {
    std::size_t h = std::hash<const Layer*>{}(k.layer) ^ static_cast<std::size_t>(k.kind);
    for (const std::int64_t x : k.v)
      h = (h ^ static_cast<std::size_t>(x)) * 0x100000001b3ULL;
    return h;
  }
};

constexpr double kResolution = 1e-4;  // mm: svg_writer's four decimals

// The grid point of `v`; none for a number too large to draw anyway.
bool quantize(double v, std::int64_t& out) {
  if (!std::isfinite(v) || std::fabs(v) > 1e12) return false;
  out = std::llround(v / kResolution);
  return true;
}

bool quantize(Vec2 p, std::int64_t& x, std::int64_t& y) {
  return quantize(p.x, x) && quantize(p.y, y);
}

std::optional<DrawnKey> line_key(const Layer& layer, Vec2 a, Vec2 b) {
  DrawnKey k{&layer, 0, {}};
  if (!quantize(a, k.v[0], k.v[1]) || !quantize(b, k.v[2], k.v[3])) return std::nullopt;
  if (std::pair(k.v[2], k.v[3]) < std::pair(k.v[0], k.v[1])) {
    std::swap(k.v[0], k.v[2]);
    std::swap(k.v[1], k.v[3]);
  }
  return k;
}

std::optional<DrawnKey> circle_key(const Layer& layer, const Circle& c) {
  DrawnKey k{&layer, 1, {}};
  if (!quantize(c.center, k.v[0], k.v[1]) || !quantize(c.radius, k.v[2])) return std::nullopt;
  return k;
}

std::optional<DrawnKey> arc_key(const Layer& layer, const Arc& a) {
  DrawnKey k{&layer, 2, {}};
  // A clockwise arc from S to E is the counter-clockwise one from E to S.
  const Vec2 from = a.ccw ? arc_start(a) : arc_end(a);
  const Vec2 to = a.ccw ? arc_end(a) : arc_start(a);
  if (!quantize(a.center, k.v[0], k.v[1]) || !quantize(from, k.v[2], k.v[3]) ||
      !quantize(to, k.v[4], k.v[5]))
    return std::nullopt;
  return k;
}

}  // namespace

// The things drawn lately, in constant memory and with no allocation after
// the start: two open-addressed tables (generations) of half the window
// each. A key is looked up in both and enters the newer; when the newer is
// full it becomes the older and the older is emptied. So the last window/2
// to window keys are remembered. The probes read only the keys' hashes (a
// table small enough for the cache); a key itself is read when its hash
// matches. (A node-based set with a ring of keys spent a quarter of `usina
// draw`'s time in its allocations and cache misses.)
class RetraceWindow {
 public:
  explicit RetraceWindow(std::size_t size) : half_(std::max<std::size_t>(size / 2, 1)) {
    std::size_t slots = 4;
    while (slots < 2 * half_)  // at most half full: short probes
      slots <<= 1;
    mask_ = slots - 1;
    for (Generation& g : generations_) {
      g.hashes.assign(slots, 0);
      g.keys.assign(slots, DrawnKey{});
    }
  }

  // True when `key` is in the window; else it enters it.
  bool seen(const std::optional<DrawnKey>& key) {
    if (!key) return false;
    const std::uint64_t hash = DrawnKeyHash{}(*key) | 1;  // 0 marks an empty slot
    if (find(generations_[0], hash, *key) || find(generations_[1], hash, *key)) return true;
    if (count_ == half_) {
      std::swap(generations_[0], generations_[1]);
      std::fill(generations_[0].hashes.begin(), generations_[0].hashes.end(), 0);
      count_ = 0;
    }
    Generation& newer = generations_[0];
    std::size_t i = slot_of(hash);
    while (newer.hashes[i] != 0)
      i = (i + 1) & mask_;
    newer.hashes[i] = hash;
    newer.keys[i] = *key;
    ++count_;
    return false;
  }

 private:
  struct Generation {
    std::vector<std::uint64_t> hashes;
    std::vector<DrawnKey> keys;
  };

  std::size_t slot_of(std::uint64_t hash) const {
    // Fibonacci hashing spreads the hash's bits over the table.
    return static_cast<std::size_t>((hash * 0x9E3779B97F4A7C15ULL) >> 20) & mask_;
  }

  bool find(const Generation& g, std::uint64_t hash, const DrawnKey& key) const {
    for (std::size_t i = slot_of(hash); g.hashes[i] != 0; i = (i + 1) & mask_)
      if (g.hashes[i] == hash && g.keys[i] == key) return true;
    return false;
  }

  std::size_t half_;
  std::size_t mask_ = 0;
  std::size_t count_ = 0;
  std::array<Generation, 2> generations_;
};

DrawingBuilder::~DrawingBuilder() = default;

DrawingBuilder::DrawingBuilder(Drawing& drawing, View view, core::Vec3 start, DrawLimits limits)
    : drawing_(drawing),
      view_(view),
      pos_(start),
      limits_(limits),
      drawn_(std::make_unique<RetraceWindow>(std::max<std::size_t>(limits.retrace_window, 1))) {
  // The standard layers exist even when empty, so that every drawing of a
  // view has the same layer table.
  if (view_ == View::Part) {
    contour_ = &drawing_.layer(kContourLayer);
    holes_ = &drawing_.layer(kHolesLayer);
    pockets_ = &drawing_.layer(kPocketsLayer);
  }
  rapid_ = &drawing_.layer(kRapidLayer);
}

void DrawingBuilder::on(const canon::Op& op) {
  const bool draws = canon::is_motion(op.kind) || std::holds_alternative<canon::Hole>(op.kind) ||
                     std::holds_alternative<canon::Pocket>(op.kind);
  if (draws && !room(op)) {
    std::visit(
        [&](const auto& k) {
          if constexpr (requires { k.to; }) pos_ = k.to;
        },
        op.kind);
    return;
  }
  std::visit(
      [&](const auto& k) {
        using T = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<T, canon::Traverse>) {
          traverse(k.to, op.origin);
        } else if constexpr (std::is_same_v<T, canon::Feed> || std::is_same_v<T, canon::Probe>) {
          feed(k.to, op.origin);
        } else if constexpr (std::is_same_v<T, canon::Arc>) {
          arc(k, op.origin);
        } else if constexpr (std::is_same_v<T, canon::Spline>) {
          spline(k, op.origin);
        } else if constexpr (std::is_same_v<T, canon::ToolChange>) {
          if (k.tool != tool_) tool_layer_ = nullptr;
          tool_ = k.tool;
        } else if constexpr (std::is_same_v<T, canon::Hole>) {
          hole(k);
        } else if constexpr (std::is_same_v<T, canon::Pocket>) {
          pocket(k);
        }
      },
      op.kind);
}

bool DrawingBuilder::room(const canon::Op& op) {
  if (drawing_.entity_count() < limits_.max_entities &&
      polyline_points_ < limits_.max_polyline_points)
    return true;
  if (not_drawn_++ == 0) first_not_drawn_line_ = op.src.line;
  return false;
}

std::optional<std::string> DrawingBuilder::limit_note(std::string_view where_listed) const {
  if (not_drawn_ == 0) return std::nullopt;
  return fmt::format(
      "the drawing holds {} entities, more than a picture shows: the {} moves from line {} on "
      "are not drawn ({})",
      drawing_.entity_count(), not_drawn_, first_not_drawn_line_, where_listed);
}

void DrawingBuilder::line(Layer& layer, Vec2 from, Vec2 to) {
  if (drawn_->seen(line_key(layer, from, to))) return;
  drawing_.add_line(layer, from, to);
}

void DrawingBuilder::circle(Layer& layer, const Circle& c) {
  if (drawn_->seen(circle_key(layer, c))) return;
  drawing_.add_circle(layer, c);
}

void DrawingBuilder::polyline(Layer& layer, std::vector<Vec2> points) {
  polyline_points_ += points.size();
  drawing_.add_polyline(layer, std::move(points));
}

Layer* DrawingBuilder::feed_layer(canon::Origin origin) {
  if (view_ == View::Part) {
    if (origin != canon::Origin::Program) return nullptr;
    auto& runs = contour_->tool_runs;
    if (runs.empty() || runs.back().tool != tool_)
      runs.push_back({contour_->entities.size(), tool_});
    return contour_;
  }
  if (tool_layer_ == nullptr) tool_layer_ = &drawing_.layer(toolpath_layer(tool_));
  return tool_layer_;
}

void DrawingBuilder::traverse(const Vec3& to, canon::Origin origin) {
  // A cycle's rapids in the plane are its moves from hole to hole (its own
  // are along the drill's axis, which the plan view does not show): the part
  // view keeps them, as the seed's drawing does; a tool-change excursion not.
  if (view_ == View::Toolpath || origin != canon::Origin::ToolChange)
    line(*rapid_, xy(pos_), xy(to));
  pos_ = to;
}

void DrawingBuilder::feed(const Vec3& to, canon::Origin origin) {
  if (Layer* layer = feed_layer(origin)) line(*layer, xy(pos_), xy(to));
  pos_ = to;
}

void DrawingBuilder::arc(const canon::Arc& a, canon::Origin origin) {
  Layer* layer = feed_layer(origin);
  const Vec3 from = pos_;
  pos_ = a.to;
  if (layer == nullptr) return;
  const core::Plane plane = plane_of(a.normal);
  const double axial = a.normal[core::axes_of(plane).axial];
  const bool ccw = (a.turn > 0) == (axial > 0);
  if (plane != core::Plane::XY) {
    // An arc in a vertical plane projects to a path along a line (with a
    // helix's drift): drawn as its linearisation.
    const double sweep = core::arc_sweep(core::in_plane(from, plane), core::in_plane(a.to, plane),
                                         core::in_plane(a.center, plane), ccw, std::abs(a.turn));
    std::vector<Vec2> points{xy(from)};
    for (const Vec3& p : core::linearize_arc(from, a.to, a.center, plane, sweep, kArcTolerance))
      points.push_back(xy(p));
    polyline(*layer, std::move(points));
    return;
  }
  // A helix projects to its arc; one that turns more than once, or closes
  // on itself, to the full circle.
  const Vec2 c = xy(a.center);
  const Vec2 s = xy(from) - c;
  const Vec2 e = xy(a.to) - c;
  const double radius = core::norm(s);
  if (std::abs(a.turn) > 1 || core::distance(xy(from), xy(a.to)) < kSamePoint) {
    circle(*layer, {c, radius});
    return;
  }
  const Arc drawn{c, radius, std::atan2(s.y, s.x), std::atan2(e.y, e.x), ccw};
  if (drawn_->seen(arc_key(*layer, drawn))) return;
  drawing_.add_arc(*layer, drawn);
}

void DrawingBuilder::spline(const canon::Spline& s, canon::Origin origin) {
  Layer* layer = feed_layer(origin);
  const Vec3 from = pos_;
  pos_ = s.to;
  if (layer == nullptr) return;
  std::vector<Vec2> points{xy(from)};
  points.reserve(s.points.size() + 1);
  for (const Vec3& p : s.points)
    points.push_back(xy(p));
  polyline(*layer, std::move(points));
}

void DrawingBuilder::hole(const canon::Hole& h) {
  if (view_ != View::Part) return;
  Layer& layer = *holes_;
  const Vec2 c = xy(h.at);
  if (h.diameter > 0.0) {
    circle(layer, {c, h.diameter / 2.0});
    return;
  }
  // No tool diameter known (no tool table, no D): a cross marks the centre.
  line(layer, c - Vec2{kHoleMarker, 0.0}, c + Vec2{kHoleMarker, 0.0});
  line(layer, c - Vec2{0.0, kHoleMarker}, c + Vec2{0.0, kHoleMarker});
}

void DrawingBuilder::pocket(const canon::Pocket& p) {
  if (view_ != View::Part) return;
  Layer& layer = *pockets_;
  Vec2 at = p.outline.start;
  for (const canon::OutlineSegment& seg : p.outline.segs) {
    if (!seg.center || seg.turn == 0) {
      drawing_.add_line(layer, at, seg.to);
    } else {
      const Vec2 c = *seg.center;
      const Vec2 s = at - c;
      const Vec2 e = seg.to - c;
      if (core::distance(at, seg.to) < kSamePoint) {
        drawing_.add_circle(layer, {c, core::norm(s)});
      } else {
        drawing_.add_arc(
            layer, {c, core::norm(s), std::atan2(s.y, s.x), std::atan2(e.y, e.x), seg.turn > 0});
      }
    }
    at = seg.to;
  }
}

}  // namespace usina::draw
