#include "cam/pocket.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "core/arc.hpp"

namespace usina::cam {
namespace {

// The pocket's region for Clipper: outline counter-clockwise, islands clockwise.
std::vector<Ring> region(const PocketShape& s, double tol) {
  std::vector<Ring> r{to_ring(s.outline, tol, true)};
  for (const Path& island : s.islands)
    r.push_back(to_ring(island, tol, false));
  return r;
}

// Strict crossing of segments ab and cd (touching does not count).
bool crosses(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = core::cross(b - a, c - a);
  const double d2 = core::cross(b - a, d - a);
  const double d3 = core::cross(d - c, a - c);
  const double d4 = core::cross(d - c, b - c);
  return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Whether the tool centre may feed straight from a to b: the segment crosses
// no wall ring and its middle is inside the walls (even-odd over the rings,
// so inside the outline's and outside the islands').
bool inside_walls(Vec2 a, Vec2 b, const std::vector<Ring>& walls) {
  int count = 0;
  const Vec2 mid = (a + b) * 0.5;
  for (const Ring& r : walls) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      if (crosses(a, b, r[i], r[(i + 1) % r.size()])) return false;
    }
    if (inside(r, mid)) ++count;
  }
  return count % 2 == 1;
}

class PocketWriter {
 public:
  PocketWriter(ProgramWriter& w, const std::vector<Ring>& walls) : w_(w), walls_(walls) {}

  // One ring at height z from its point nearest the tool, reached by a feed
  // inside the walls when there is one, else over the top.
  void ring(const Ring& r, double z, bool first) {
    const Vec3 at = w_.position();
    const Path p = ring_to_path(r, {at.x, at.y});
    if (first || !inside_walls({at.x, at.y}, p.start, walls_)) {
      w_.rapid_over(p.start);
      w_.plunge(z);
    } else {
      w_.feed({p.start.x, p.start.y, z});
    }
    w_.path(p, z);
  }

 private:
  ProgramWriter& w_;
  const std::vector<Ring>& walls_;
};

// The outline's extent: its bounding box's width and height.
Vec2 extent(const Path& outline) {
  Vec2 lo = outline.start;
  Vec2 hi = outline.start;
  for (const Vec2& p : linearize(outline, 0.01)) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  return hi - lo;
}

// The rings are at most the outline's half width over the stepover.
bool check_rings(Vec2 size, const PocketOptions& o, core::DiagnosticSink& diags) {
  const double half = std::max(size.x, size.y) / 2.0;
  if (half / o.stepover <= kMaxPasses) return true;
  return fail(diags, core::Code::GenBadValue,
              fmt::format("a stepover of {:g} mm makes more than {} rings in a pocket {:g} mm "
                          "across; give a larger stepover",
                          o.stepover, kMaxPasses, 2 * half));
}

bool check_ranges(const PocketOptions& o, core::DiagnosticSink& diags) {
  bool ok = check_cutting(o.cut, diags);
  ok = check_range("the depth (--depth)", o.depth, kLength, diags) && ok;
  ok = check_range("the step down (--step-down)", o.step_down, kLength, diags) && ok;
  ok = check_range("the stepover (--stepover)", o.stepover, kLength, diags) && ok;
  ok = check_range("the finish allowance (--finish-allowance)", o.finish_allowance, kLengthOrZero,
                   diags) &&
       ok;
  return check_range("the tolerance", o.tolerance, kTolerance, diags) && ok;
}

bool check_closed(const PocketShape& shape, core::DiagnosticSink& diags) {
  if (!shape.outline.closed) {
    return fail(diags, core::Code::GenOpenOutline,
                fmt::format("the pocket's outline (from ({:g}, {:g})) is not closed; a pocket "
                            "needs a closed outline",
                            shape.outline.start.x, shape.outline.start.y));
  }
  for (const Path& island : shape.islands) {
    if (!island.closed) {
      return fail(diags, core::Code::GenOpenOutline,
                  fmt::format("the island from ({:g}, {:g}) is not closed", island.start.x,
                              island.start.y));
    }
  }
  return true;
}

// The moves of one level from above, before any ring is made (the rings
// are made once for every level): at most (half the narrower side − r −
// allowance) / stepover + 3 rings deep (with the core ring and the finishing
// pass), each no more points than the region's contours plus a full round
// corner, at the deepest offset, about the outline and each island.
double estimate_level_moves(const PocketShape& shape, Vec2 size, const PocketOptions& o) {
  const double r = o.cut.tool_diameter / 2.0;
  const double inside = std::min(size.x, size.y) / 2.0;
  const double deep = std::max(0.0, (inside - r - o.finish_allowance) / o.stepover) + 3;
  double points = linearized_points(shape.outline, o.tolerance);
  for (const Path& island : shape.islands)
    points += linearized_points(island, o.tolerance);
  points += static_cast<double>(shape.islands.size() + 1) *
            core::segments_for_tolerance(inside, 2 * std::numbers::pi, o.tolerance);
  return deep * (points + 3);
}

// The moves the rings make: each ring's points and the moves between rings,
// at every level.
double ring_moves(const PocketRings& rings, const PocketOptions& o) {
  double level = 0;
  for (const auto* set : {&rings.roughing, &rings.finish}) {
    for (const Ring& ring : *set)
      level += static_cast<double>(ring.size()) + 3;
  }
  return std::ceil(o.depth / o.step_down) * level + 10;
}

constexpr std::string_view kLessWork =
    "give a larger stepover or step down, or cut the pocket in parts";

bool check_pocket(const PocketShape& shape, const PocketOptions& o, core::DiagnosticSink& diags) {
  if (!check_ranges(o, diags)) return false;
  std::vector<Path> all{shape.outline};
  all.insert(all.end(), shape.islands.begin(), shape.islands.end());
  if (!check_extent(all, diags) || !check_passes(o.depth, o.step_down, diags)) return false;
  const Vec2 size = extent(shape.outline);
  if (!check_rings(size, o, diags)) return false;
  if (o.stepover > o.cut.tool_diameter) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("the stepover {:g} mm is more than the tool diameter {:g} mm, which "
                            "would leave ridges between the rings; give at most {:g}",
                            o.stepover, o.cut.tool_diameter, o.cut.tool_diameter));
  }
  return check_closed(shape, diags) &&
         check_work("one level of the pocket", estimate_level_moves(shape, size, o),
                    o.cut.max_moves, kLessWork, diags);
}

// Material no pass reaches (docs/cam.md, "Material left"): the finishing
// pass runs a tool radius from the walls and clears a tool diameter from
// them; the roughing clears what is within a tool radius of the region
// offset by r + allowance. When the allowance is above the tool radius, the
// region deeper than a tool diameter may be in neither: where the pocket is
// too narrow for a roughing ring (the core of a small pocket, a channel),
// or between the two (an allowance above the diameter). 0.01 mm keeps the
// offsets' chords from counting as material.
bool check_material_left(const PocketShape& shape, const PocketOptions& o,
                         core::DiagnosticSink& diags) {
  const double r = o.cut.tool_diameter / 2.0;
  if (o.finish_allowance <= r) return true;  // then every point is in one or the other
  const std::vector<Ring> reg = region(shape, o.tolerance);
  const std::vector<Ring> deep = offset_rings(reg, -(2 * r + 0.01), o.tolerance);
  const std::vector<Ring> roughed =
      offset_rings(offset_rings(reg, -(r + o.finish_allowance), o.tolerance), r, o.tolerance);
  const std::vector<Ring> left = difference(deep, roughed);
  if (left.empty()) return true;
  Vec2 lo = left.front().front();
  Vec2 hi = lo;
  double area2 = 0;  // holes run the other way: their area counts negative
  for (const Ring& ring : left) {
    area2 += signed_area2(ring);
    for (const Vec2& p : ring)
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)},
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  return fail(
      diags, core::Code::GenMaterialLeft,
      fmt::format("{:.4g} mm² of material, from ({:.3g}, {:.3g}) to ({:.3g}, {:.3g}), "
                  "would be left standing: the finishing pass clears {:g} mm (a tool "
                  "diameter) from the walls, and the finish allowance of {:g} mm keeps "
                  "the roughing rings from reaching it; give a finish allowance of at "
                  "most {:g} mm (the tool radius)",
                  std::fabs(area2) / 2, lo.x, lo.y, hi.x, hi.y, 2 * r, o.finish_allowance, r));
}

}  // namespace

Path rectangle(Vec2 center, double width, double height, double corner_radius) {
  const Vec2 c = center;
  const double r = corner_radius;
  const double x0 = c.x - width / 2;
  const double x1 = c.x + width / 2;
  const double y0 = c.y - height / 2;
  const double y1 = c.y + height / 2;
  Path p{{c.x, y0}, {}, true};
  auto line = [&](Vec2 to) {
    if (!(to == end_point(p))) p.segs.push_back({to, std::nullopt, 0});
  };
  auto corner = [&](Vec2 to, Vec2 about) {
    if (r > 0) p.segs.push_back({to, about, 1});
  };
  line({x1 - r, y0});
  corner({x1, y0 + r}, {x1 - r, y0 + r});
  line({x1, y1 - r});
  corner({x1 - r, y1}, {x1 - r, y1 - r});
  line({x0 + r, y1});
  corner({x0, y1 - r}, {x0 + r, y1 - r});
  line({x0, y0 + r});
  corner({x0 + r, y0}, {x0 + r, y0 + r});
  line({c.x, y0});
  return p;
}

Path circle(Vec2 center, double radius) {
  const Vec2 a{center.x + radius, center.y};
  return {a, {{a, center, 1}}, true};
}

std::optional<PocketShape> pocket_shape(const std::vector<Path>& paths,
                                        core::DiagnosticSink& diags) {
  constexpr double kTol = 0.001;
  std::optional<std::size_t> outer;
  double outer_area = 0.0;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (!paths[i].closed) {
      fail(diags, core::Code::GenOpenOutline,
           fmt::format("the contour from ({:g}, {:g}) to ({:g}, {:g}) is open; a pocket's "
                       "outline and islands must be closed",
                       paths[i].start.x, paths[i].start.y, end_point(paths[i]).x,
                       end_point(paths[i]).y));
      return std::nullopt;
    }
    const double area = std::fabs(signed_area2(linearize(paths[i], kTol)));
    if (!outer || area > outer_area) outer = i, outer_area = area;
  }
  if (!outer) {
    fail(diags, core::Code::GenOpenOutline, "there is no contour to pocket");
    return std::nullopt;
  }
  PocketShape shape{paths[*outer], {}};
  const Ring outline = to_ring(shape.outline, kTol, true);
  for (std::size_t i = 0; i < paths.size(); ++i) {
    if (i == *outer) continue;
    for (const Vec2& p : linearize(paths[i], kTol)) {
      if (!inside(outline, p)) {
        fail(diags, core::Code::GenBadValue,
             fmt::format("the contour from ({:g}, {:g}) is not inside the pocket's outline "
                         "(the largest contour, from ({:g}, {:g})); draw one pocket at a time",
                         paths[i].start.x, paths[i].start.y, shape.outline.start.x,
                         shape.outline.start.y));
        return std::nullopt;
      }
    }
    shape.islands.push_back(paths[i]);
  }
  return shape;
}

PocketRings pocket_rings(const PocketShape& shape, const PocketOptions& o) {
  const double r = o.cut.tool_diameter / 2.0;
  const std::vector<Ring> reg = region(shape, o.tolerance);
  PocketRings out;
  out.finish = offset_rings(reg, -r, o.tolerance);
  if (out.finish.empty()) return out;
  std::vector<std::vector<Ring>> levels;
  double d = r + o.finish_allowance;
  for (auto rings = offset_rings(reg, -d, o.tolerance); !rings.empty();
       rings = offset_rings(reg, -d, o.tolerance)) {
    levels.push_back(std::move(rings));
    d += o.stepover;
  }
  // The material deeper than a tool radius inside the last ring (a stepover
  // above the radius leaves a core uncut): one more ring a radius further in.
  const double last = d - o.stepover;
  if (!levels.empty() && o.stepover > r) {
    auto core_rings = offset_rings(reg, -(last + r), o.tolerance);
    if (!core_rings.empty()) levels.push_back(std::move(core_rings));
  }
  for (std::size_t i = levels.size(); i-- > 0;) {  // innermost first
    out.roughing.insert(out.roughing.end(), levels[i].begin(), levels[i].end());
  }
  return out;
}

bool generate_pocket(const PocketShape& shape, const PocketOptions& o, canon::Sink& sink,
                     core::DiagnosticSink& diags) {
  if (!check_pocket(shape, o, diags)) return false;
  const PocketRings rings = pocket_rings(shape, o);
  if (rings.finish.empty()) {
    return fail(diags, core::Code::GenToolTooBig,
                fmt::format("a tool of diameter {:g} mm does not fit in the pocket; use a "
                            "smaller tool",
                            o.cut.tool_diameter));
  }
  if (!check_material_left(shape, o, diags) ||
      !check_work("the pocket", ring_moves(rings, o), o.cut.max_moves, kLessWork, diags)) {
    return false;
  }
  ProgramWriter w(sink, o.cut);
  w.begin(fmt::format("usina gen pocket: depth {:g} mm, stepover {:g} mm", o.depth, o.stepover));
  w.emit(canon::Pocket{to_outline(shape.outline), o.depth});
  w.set_origin(canon::Origin::Cycle);
  PocketWriter pw(w, rings.finish);
  for (const double z : depth_levels(o.depth, o.step_down)) {
    bool first = true;
    for (const Ring& r : rings.roughing)
      pw.ring(r, z, std::exchange(first, false));
    for (const Ring& r : rings.finish)
      pw.ring(r, z, std::exchange(first, false));
  }
  w.retract();
  w.set_origin(canon::Origin::Program);
  w.end();
  return true;
}

}  // namespace usina::cam
