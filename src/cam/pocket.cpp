#include "cam/pocket.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

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

// The rings are at most the outline's half width over the stepover.
bool check_rings(const Path& outline, const PocketOptions& o, core::DiagnosticSink& diags) {
  Vec2 lo = outline.start;
  Vec2 hi = outline.start;
  for (const Vec2& p : linearize(outline, 0.01)) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double half = std::max(hi.x - lo.x, hi.y - lo.y) / 2.0;
  if (half / o.stepover <= kMaxPasses) return true;
  return fail(diags, core::Code::GenBadValue,
              fmt::format("a stepover of {:g} mm makes more than {} rings in a pocket {:g} mm "
                          "across",
                          o.stepover, kMaxPasses, 2 * half));
}

bool check_pocket(const PocketShape& shape, const PocketOptions& o, core::DiagnosticSink& diags) {
  bool ok = check_cutting(o.cut, diags);
  ok = check_positive("the depth", o.depth, "mm", diags) && ok;
  ok = check_positive("the step down", o.step_down, "mm", diags) && ok;
  ok = check_positive("the stepover", o.stepover, "mm", diags) && ok;
  ok = check_positive("the finish allowance", o.finish_allowance, "mm", diags, true) && ok;
  ok = check_positive("the tolerance", o.tolerance, "mm", diags) && ok;
  if (!ok) return false;
  std::vector<Path> all{shape.outline};
  all.insert(all.end(), shape.islands.begin(), shape.islands.end());
  if (!check_extent(all, diags) || !check_passes(o.depth, o.step_down, diags)) return false;
  if (!check_rings(shape.outline, o, diags)) return false;
  if (o.stepover > o.cut.tool_diameter) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("the stepover {:g} mm is more than the tool diameter {:g} mm, which "
                            "would leave ridges between the rings; give at most {:g}",
                            o.stepover, o.cut.tool_diameter, o.cut.tool_diameter));
  }
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
