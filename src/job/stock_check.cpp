#include "job/stock_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>

#include <fmt/format.h>

namespace usina::job {
namespace {

using cam::Vec2;

// core's tolerance for geometry: a line on the stock's edge is on the stock.
constexpr double kOnEdge = 1e-6;
// Arcs become chords this close to them (their points are on the arc).
constexpr double kChord = 0.001;

// A figure for a message: to the micrometre, without a trailing zero or -0.
std::string mm(double v) {
  return fmt::format("{:g}", std::round(v * 1000) / 1000 + 0.0);
}

std::string describe(const StockTop& top) {
  if (top.round) {
    return fmt::format("a circle D{} about X{} Y{}", mm(2 * top.radius), mm(top.centre.x),
                       mm(top.centre.y));
  }
  return fmt::format("X{}..{} Y{}..{}", mm(top.lo.x), mm(top.hi.x), mm(top.lo.y), mm(top.hi.y));
}

// The key the diagnostic points at, or the operation's header without one.
core::SourceLoc at_key(const core::SourceLoc& key, const Operation& op) {
  return key.line > 0 ? key : op.loc;
}

void report(core::DiagnosticSink& diags, core::Code code, core::Severity severity,
            core::SourceLoc loc, std::string message) {
  diags.report({code, severity, loc, std::move(message)});
}

// The point of `points` farthest off the top face, and how far.
struct Farthest {
  double by = -std::numeric_limits<double>::infinity();
  Vec2 at;
};

Farthest farthest_outside(const StockTop& top, const std::vector<Vec2>& points) {
  Farthest f;
  for (const Vec2& p : points) {
    const double by = outside_by(top, p);
    if (by > f.by) f = {by, p};
  }
  return f;
}

// "reaches X.. Y.., N mm outside the stock's top (...)".
std::string reaches(const StockTop& top, const Farthest& f) {
  return fmt::format("reaches X{} Y{}, {} mm outside the stock's top ({})", mm(f.at.x), mm(f.at.y),
                     mm(f.by), describe(top));
}

bool meets(const StockTop& top, const std::vector<Vec2>& line) {
  if (line.size() == 1) return outside_by(top, line[0]) <= kOnEdge;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (segment_meets(top, line[i - 1], line[i])) return true;
  }
  return false;
}

// Whether `p` is inside the closed polygon `ring` (even-odd rule).
bool encloses(const std::vector<Vec2>& ring, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Vec2 a = ring[i];
    const Vec2 b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

bool segment_meets_box(Vec2 a, Vec2 b, Vec2 lo, Vec2 hi) {
  // The segment a + t (b - a), t in [0, 1], clipped by each slab in turn.
  double t0 = 0;
  double t1 = 1;
  const std::array<double, 2> from{a.x, a.y};
  const std::array<double, 2> d{b.x - a.x, b.y - a.y};
  const std::array<double, 2> low{lo.x - kOnEdge, lo.y - kOnEdge};
  const std::array<double, 2> high{hi.x + kOnEdge, hi.y + kOnEdge};
  for (std::size_t i = 0; i < 2; ++i) {
    if (d[i] == 0) {
      if (from[i] < low[i] || from[i] > high[i]) return false;
      continue;
    }
    const double ta = (low[i] - from[i]) / d[i];
    const double tb = (high[i] - from[i]) / d[i];
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
    if (t0 > t1) return false;
  }
  return true;
}

bool segment_meets_circle(Vec2 a, Vec2 b, Vec2 c, double r) {
  const Vec2 d{b.x - a.x, b.y - a.y};
  const double len2 = d.x * d.x + d.y * d.y;
  const double t =
      len2 > 0 ? std::clamp(((c.x - a.x) * d.x + (c.y - a.y) * d.y) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(a.x + t * d.x - c.x, a.y + t * d.y - c.y) <= r + kOnEdge;
}

// A pocket's warning: at or below the stock's bottom it is a cut-out.
void check_through(const StockTop& top, const Operation& op, std::string_view what,
                   core::DiagnosticSink& diags) {
  if (op.depth < top.height - kOnEdge) return;
  const double below = op.depth - top.height;
  report(diags, core::Code::JobCutsThroughStock, core::Severity::Warning, at_key(op.depth_loc, op),
         fmt::format("depth {} mm in a stock {} mm high: the {} cuts through the stock (a "
                     "cut-out: what it surrounds comes loose){}",
                     mm(op.depth), mm(top.height), what,
                     below > kBreakthrough
                         ? fmt::format(", and {} mm into what is under it", mm(below))
                         : ""));
}

// The outline as points: arcs as chords, whose ends are on the arc.
std::vector<Vec2> points_of(const cam::Path& p) {
  return cam::linearize(p, kChord);
}

bool check_contour(const StockTop& top, const Operation& op, const cam::Path& contour,
                   std::size_t index, core::DiagnosticSink& diags) {
  const std::vector<Vec2> line = points_of(contour);
  const Farthest f = farthest_outside(top, line);
  if (f.by <= kOnEdge) return true;
  const std::string which = fmt::format("contour {} of layer \"{}\" (from X{} Y{})", index + 1,
                                        op.layer, mm(contour.start.x), mm(contour.start.y));
  if (meets(top, line)) {
    report(diags, core::Code::JobPartlyOutsideStock, core::Severity::Warning,
           at_key(op.layer_loc, op),
           fmt::format("{} {}: the tool cuts air there (usual when an oversize blank is "
                       "trimmed to its outline; else check the stock's size and origin)",
                       which, reaches(top, f)));
    return true;
  }
  const bool around = contour.closed && encloses(line, top.centre);
  report(diags, core::Code::JobOutsideStock, core::Severity::Error, at_key(op.layer_loc, op),
         fmt::format("{} lies wholly {} the stock's top ({}): {}the {} would cut air{}", which,
                     around ? "around" : "outside", describe(top),
                     around ? "the part is larger than the blank, " : "", op_type_name(op.type),
                     around ? "" : "; check the stock's size and origin, or the layer"));
  return false;
}

std::vector<Vec2> ellipse_points(const Operation& op) {
  // A point every 0.1°: the farthest point off a round stock is found to a
  // few micrometres; off a box, the ends of the axes are among them.
  constexpr int kSteps = 3600;
  std::vector<Vec2> points;
  points.reserve(kSteps);
  for (int i = 0; i < kSteps; ++i) {
    const double a = 2 * std::numbers::pi * i / kSteps;
    points.push_back({op.center[0] + op.rx * std::cos(a), op.center[1] + op.ry * std::sin(a)});
  }
  return points;
}

}  // namespace

StockTop stock_top(const Stock& s) {
  StockTop top;
  top.round = s.shape == "cylinder";
  if (top.round) {
    top.centre = {s.origin[0], s.origin[1]};
    top.radius = s.size[0] / 2;
    top.height = s.size[1];
    top.lo = {top.centre.x - top.radius, top.centre.y - top.radius};
    top.hi = {top.centre.x + top.radius, top.centre.y + top.radius};
  } else {
    top.lo = {s.origin[0], s.origin[1]};
    top.hi = {s.origin[0] + s.size[0], s.origin[1] + s.size[1]};
    top.centre = {(top.lo.x + top.hi.x) / 2, (top.lo.y + top.hi.y) / 2};
    top.height = s.size[2];
  }
  return top;
}

double outside_by(const StockTop& top, Vec2 p) {
  if (top.round) return std::hypot(p.x - top.centre.x, p.y - top.centre.y) - top.radius;
  const double dx = std::max({top.lo.x - p.x, 0.0, p.x - top.hi.x});
  const double dy = std::max({top.lo.y - p.y, 0.0, p.y - top.hi.y});
  if (dx > 0 || dy > 0) return std::hypot(dx, dy);
  return -std::min({p.x - top.lo.x, top.hi.x - p.x, p.y - top.lo.y, top.hi.y - p.y});
}

bool segment_meets(const StockTop& top, Vec2 a, Vec2 b) {
  return top.round ? segment_meets_circle(a, b, top.centre, top.radius)
                   : segment_meets_box(a, b, top.lo, top.hi);
}

double point_length(double diameter, double point_angle_deg) {
  return diameter / 2 / std::tan(point_angle_deg / 2 * std::numbers::pi / 180);
}

bool check_hole_centres(const Stock& s, const Operation& op, const std::vector<Vec2>& centres,
                        core::DiagnosticSink& diags) {
  const StockTop top = stock_top(s);
  const Farthest f = farthest_outside(top, centres);
  if (f.by <= kOnEdge) return true;
  const auto off = std::count_if(centres.begin(), centres.end(),
                                 [&](Vec2 c) { return outside_by(top, c) > kOnEdge; });
  report(diags, core::Code::JobOutsideStock, core::Severity::Error, at_key(op.layer_loc, op),
         fmt::format("{} of the {} hole centres of layer \"{}\" are off the stock; the farthest "
                     "{}: check the stock's size and origin, or the layer",
                     off, centres.size(), op.layer, reaches(top, f)));
  return false;
}

void check_hole_edges(const Stock& s, const Operation& op, const std::vector<HoleGroup>& groups,
                      core::DiagnosticSink& diags) {
  const StockTop top = stock_top(s);
  std::size_t broken = 0;
  Farthest first;
  double diameter = 0;
  for (const HoleGroup& g : groups) {
    for (const Vec2& c : g.centers) {
      const double by = outside_by(top, c) + g.diameter / 2;
      if (by <= kOnEdge) continue;
      if (broken++ == 0) std::tie(first, diameter) = std::pair{Farthest{by, c}, g.diameter};
    }
  }
  if (broken == 0) return;
  report(diags, core::Code::JobPartlyOutsideStock, core::Severity::Warning,
         at_key(op.layer_loc, op),
         fmt::format("{} of the holes of layer \"{}\" break out of the stock's side, the first "
                     "D{} at X{} Y{} by {} mm ({}): the drill cuts partly in air there and is "
                     "pushed off its line",
                     broken, op.layer, mm(diameter), mm(first.at.x), mm(first.at.y), mm(first.by),
                     describe(top)));
}

namespace {

// A drill's tip past the bottom: its full diameter through, but not much more.
void check_drill_depth(const StockTop& top, const Operation& op, const Tool& tool,
                       core::DiagnosticSink& diags) {
  const double below = op.depth - top.height;
  if (below <= kOnEdge) return;  // a blind hole
  const double point = point_length(tool.diameter, kDrillPointAngle);
  const double at_bottom = tool.diameter * std::min(below / point, 1.0);
  const core::SourceLoc loc = at_key(op.depth_loc, op);
  if (at_bottom < tool.diameter - kThroughLip) {
    report(diags, core::Code::JobHoleNotThrough, core::Severity::Warning, loc,
           fmt::format("T{}'s tip goes {} mm below the stock's bottom but its {} mm point does "
                       "not: the hole is D{} at the bottom, not D{}; a through hole needs depth "
                       "{} at least (the height and the point), a blind one {} at most",
                       tool.number, mm(below), mm(point), mm(at_bottom), mm(tool.diameter),
                       mm(top.height + point), mm(top.height)));
  } else if (below > point + kBreakthrough + kOnEdge) {
    report(diags, core::Code::JobCutsBelowStock, core::Severity::Warning, loc,
           fmt::format("T{}'s tip goes {} mm below the stock's bottom: its full diameter is "
                       "through at depth {} (the height and its {} mm point), and {} is the "
                       "deepest before it drills what the stock stands on",
                       tool.number, mm(below), mm(top.height + point), mm(point),
                       mm(top.height + point + kBreakthrough)));
  }
}

void check_spot_depth(const StockTop& top, const Operation& op, const Tool& tool,
                      core::DiagnosticSink& diags) {
  const double point = point_length(tool.diameter, kSpotPointAngle);
  const double below = op.depth - top.height;
  if (below <= point + kBreakthrough + kOnEdge) return;
  report(diags, core::Code::JobCutsBelowStock, core::Severity::Warning, at_key(op.depth_loc, op),
         fmt::format("T{}'s tip goes {} mm below the stock's bottom, past its {} mm point and "
                     "{} mm more: it drills what the stock stands on",
                     tool.number, mm(below), mm(point), mm(kBreakthrough)));
}

bool check_tap_depth(const StockTop& top, const Operation& op, const Tool& tool,
                     core::DiagnosticSink& diags) {
  const double lead = kTapLeadPitches * tool.pitch;
  const double below = op.depth - top.height;
  if (below <= lead + kOnEdge) return true;
  report(diags, core::Code::JobDeeperThanStock, core::Severity::Error, at_key(op.depth_loc, op),
         fmt::format("T{} would go {} mm below the stock's bottom: a through thread is full "
                     "once the tap's lead ({} pitches, {} mm) has passed the bottom; deeper it "
                     "cuts no thread and meets what the stock stands on. Give depth {} at most",
                     tool.number, mm(below), mm(kTapLeadPitches), mm(lead), mm(top.height + lead)));
  return false;
}

// A boring bar's end is square: it is through once at the bottom, and
// below it, past what a breakthrough needs, it cuts what the stock stands on.
void check_bore_depth(const StockTop& top, const Operation& op, const Tool& tool,
                      core::DiagnosticSink& diags) {
  const double below = op.depth - top.height;
  if (below <= kBreakthrough + kOnEdge) return;
  report(diags, core::Code::JobCutsBelowStock, core::Severity::Warning, at_key(op.depth_loc, op),
         fmt::format("T{} bores {} mm below the stock's bottom, more than the {} mm a "
                     "through bore needs: it cuts what the stock stands on; give depth {} at "
                     "most",
                     tool.number, mm(below), mm(kBreakthrough), mm(top.height + kBreakthrough)));
}

}  // namespace

bool check_hole_depth(const Stock& s, const Operation& op, const Tool& tool,
                      core::DiagnosticSink& diags) {
  const StockTop top = stock_top(s);
  switch (op.type) {
  case OpType::Tap: return check_tap_depth(top, op, tool, diags);
  case OpType::Spot: check_spot_depth(top, op, tool, diags); return true;
  case OpType::Bore: check_bore_depth(top, op, tool, diags); return true;
  default: check_drill_depth(top, op, tool, diags); return true;
  }
}

bool check_pocket(const Stock& s, const Operation& op, const cam::Path& outline,
                  core::DiagnosticSink& diags) {
  const StockTop top = stock_top(s);
  const Farthest f = farthest_outside(top, points_of(outline));
  if (f.by > kOnEdge) {
    report(diags, core::Code::JobOutsideStock, core::Severity::Error, at_key(op.layer_loc, op),
           fmt::format("the pocket's outline on layer \"{}\" {}: a pocket is cut inside the "
                       "stock; check the stock's size and origin, or the layer",
                       op.layer, reaches(top, f)));
    return false;
  }
  check_through(top, op, "pocket", diags);
  return true;
}

bool check_ellipse_pocket(const Stock& s, const Operation& op, core::DiagnosticSink& diags) {
  const StockTop top = stock_top(s);
  const Farthest f = farthest_outside(top, ellipse_points(op));
  if (f.by > kOnEdge) {
    report(diags, core::Code::JobOutsideStock, core::Severity::Error, at_key(op.place_loc, op),
           fmt::format("the ellipse about X{} Y{} (rx {}, ry {}) {}: a pocket is cut inside the "
                       "stock",
                       mm(op.center[0]), mm(op.center[1]), mm(op.rx), mm(op.ry), reaches(top, f)));
    return false;
  }
  check_through(top, op, "ellipse pocket", diags);
  return true;
}

bool check_profile(const Stock& s, const Operation& op, const std::vector<cam::Path>& contours,
                   core::DiagnosticSink& diags) {
  const StockTop top = stock_top(s);
  for (std::size_t i = 0; i < contours.size(); ++i) {
    if (!check_contour(top, op, contours[i], i, diags)) return false;
  }
  const double below = op.depth - top.height;
  if (below > kBreakthrough + kOnEdge) {
    report(diags, core::Code::JobCutsBelowStock, core::Severity::Warning, at_key(op.depth_loc, op),
           fmt::format("depth {} mm in a stock {} mm high: the {} goes {} mm below its "
                       "bottom, more than the {} mm a cut-out needs, into what the stock "
                       "stands on",
                       mm(op.depth), mm(top.height), op_type_name(op.type), mm(below),
                       mm(kBreakthrough)));
  }
  return true;
}

bool check_engraving(const Stock& s, const Operation& op,
                     const std::vector<std::vector<Vec2>>& strokes, core::DiagnosticSink& diags) {
  const StockTop top = stock_top(s);
  std::vector<Vec2> points;
  for (const auto& stroke : strokes)
    points.insert(points.end(), stroke.begin(), stroke.end());
  const Farthest f = farthest_outside(top, points);
  if (f.by > kOnEdge) {
    report(diags, core::Code::JobOutsideStock, core::Severity::Error, at_key(op.place_loc, op),
           fmt::format("the text \"{}\" at X{} Y{}, {} mm high, {}: move it or make it smaller",
                       op.text, mm(op.at[0]), mm(op.at[1]), mm(op.height), reaches(top, f)));
    return false;
  }
  check_through(top, op, "engraving", diags);
  return true;
}

bool check_face(const Stock& s, const Operation& op, core::DiagnosticSink& diags) {
  const StockTop top = stock_top(s);
  if (op.depth < top.height - kOnEdge) return true;
  report(diags, core::Code::JobDeeperThanStock, core::Severity::Error, at_key(op.depth_loc, op),
         fmt::format("face depth {} mm in a stock {} mm high: the facing would take the whole "
                     "stock away; a facing takes off the top (a few tenths to a few mm)",
                     mm(op.depth), mm(top.height)));
  return false;
}

}  // namespace usina::job
