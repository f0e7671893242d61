#include "cam/profile.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "cam/from_dxf.hpp"
#include "cam/offset.hpp"
#include "core/arc.hpp"

namespace usina::cam {
namespace {

inline constexpr Range kTabCount{0.0, kMaxPasses, true, ""};
constexpr std::string_view kLessWork = "give a larger step down, or fewer tabs or contours";

Vec2 unit(Vec2 v) {
  const double n = core::norm(v);
  return n > 0.0 ? v / n : Vec2{1.0, 0.0};
}

// Direction of travel where a segment starts (at `from`) or ends.
Vec2 start_tangent(Vec2 from, const PathSegment& s) {
  if (!s.center) return unit(s.to - from);
  return unit(core::perp(from - *s.center) * s.turn);
}

Vec2 end_tangent(Vec2 from, const PathSegment& s) {
  if (!s.center) return unit(s.to - from);
  return unit(core::perp(s.to - *s.center) * s.turn);
}

// The point `length` along a segment from `from`.
Vec2 point_along(Vec2 from, const PathSegment& s, double length) {
  const double total = segment_length(from, s);
  const double f = total > 0.0 ? length / total : 0.0;
  if (!s.center) return from + (s.to - from) * f;
  return *s.center + core::rotate(from - *s.center, segment_sweep(from, s) * f);
}

// A piece of a path between two distances along it, and whether a tab lifts it.
struct Piece {
  Path path;
  bool tab = false;
};

// The path cut at the tab ends: pieces alternate between cut and tab.
std::vector<Piece> split_for_tabs(const Path& p, const Tabs& tabs, double tool_diameter) {
  const double total = path_length(p);
  std::vector<double> cuts;
  const double half = (tabs.width + tool_diameter) / 2.0;
  for (int i = 0; i < tabs.count; ++i) {
    const double c = total * (i + 0.5) / tabs.count;
    cuts.push_back(c - half);
    cuts.push_back(c + half);
  }
  std::vector<Piece> pieces{{{p.start, {}, false}, false}};
  std::size_t next = 0;
  double s0 = 0.0;
  for (std::size_t i = 0; i < p.segs.size(); ++i) {
    const Vec2 from = segment_start(p, i);
    const PathSegment& seg = p.segs[i];
    const double len = segment_length(from, seg);
    for (; next < cuts.size() && cuts[next] < s0 + len; ++next) {
      if (cuts[next] - s0 <= 1e-9) {  // at the segment's start: no zero-length piece
        pieces.push_back({{from, {}, false}, next % 2 == 0});
        continue;
      }
      const Vec2 q = point_along(from, seg, cuts[next] - s0);
      pieces.back().path.segs.push_back({q, seg.center, seg.turn});
      pieces.push_back({{q, {}, false}, next % 2 == 0});
    }
    pieces.back().path.segs.push_back(seg);
    s0 += len;
  }
  return pieces;
}

struct Lead {
  Vec2 from;  // where the arc starts
  Vec2 to;    // where it ends
  Vec2 center;
  int turn = 1;
};

// A quarter circle tangent to the path at its start (lead-in) or end
// (lead-out), on the `side` away from the part.
Lead lead_in(const Path& p, double radius, int side) {
  const Vec2 t = start_tangent(p.start, p.segs.front());
  const Vec2 c = p.start + core::perp(t) * (radius * side);
  const Vec2 a = c + core::rotate(p.start - c, -side * std::numbers::pi / 2);
  return {a, p.start, c, side};
}

Lead lead_out(const Path& p, double radius, int side) {
  const Vec2 e = end_point(p);
  const Vec2 t = end_tangent(segment_start(p, p.segs.size() - 1), p.segs.back());
  const Vec2 c = e + core::perp(t) * (radius * side);
  return {e, c + core::rotate(e - c, side * std::numbers::pi / 2), c, side};
}

// A tool-centre path and the side of its contour it was offset to.
struct Cut {
  Path path;
  ProfileSide side;
};

void one_pass(ProgramWriter& w, const Cut& cut, double z, const ProfileOptions& o) {
  const Path& p = cut.path;
  const int side = lead_side(cut.side);
  const double tab_z = -o.depth + o.tabs.height;
  const bool leads = o.lead_radius > 0.0;
  if (leads) {
    const Lead in = lead_in(p, o.lead_radius, side);
    w.rapid_over(in.from);
    w.plunge(z);
    w.arc(in.to, in.center, in.turn, z);
  } else {
    w.rapid_over(p.start);
    w.plunge(z);
  }
  if (o.tabs.count > 0 && z < tab_z) {
    for (const Piece& piece : split_for_tabs(p, o.tabs, o.cut.tool_diameter)) {
      const double piece_z = piece.tab ? tab_z : z;
      const Vec3 at = w.position();
      if (piece_z > at.z) w.feed({at.x, at.y, piece_z});
      if (piece_z < at.z) w.plunge(piece_z);
      w.path(piece.path, piece_z);
    }
  } else {
    w.path(p, z);
  }
  if (leads) {
    const Lead out = lead_out(p, o.lead_radius, side);
    w.arc(out.to, out.center, out.turn, z);
  }
  w.retract();
}

bool check_ranges(const ProfileOptions& o, core::DiagnosticSink& diags) {
  bool ok = check_cutting(o.cut, diags);
  ok = check_range("the depth (--depth)", o.depth, kLength, diags) && ok;
  ok = check_range("the step down (--step-down)", o.step_down, kLength, diags) && ok;
  ok = check_range("the lead radius (--lead-radius)", o.lead_radius, kLengthOrZero, diags) && ok;
  ok = check_range("the tolerance", o.tolerance, kTolerance, diags) && ok;
  ok = check_range("the tab count (--tabs)", o.tabs.count, kTabCount, diags) && ok;
  if (o.tabs.count > 0) {
    ok = check_range("the tab width (--tab-width)", o.tabs.width, kLength, diags) && ok;
    ok = check_range("the tab height (--tab-height)", o.tabs.height, kLength, diags) && ok;
    if (ok && o.tabs.height >= o.depth) {
      ok = fail(diags, core::Code::GenBadValue,
                fmt::format("the tab height {:g} mm is not below the depth {:g} mm; tabs are "
                            "the material left at the bottom of the cut",
                            o.tabs.height, o.depth));
    }
  }
  return ok;
}

// The moves of one contour's passes, from above, before it is offset: its
// points (arcs in chords), a full round corner, the leads and the tabs'
// rises and falls, at every level.
double estimate_moves(const std::vector<Path>& contours, const ProfileOptions& o) {
  const double corner =
      core::segments_for_tolerance(o.cut.tool_diameter / 2.0, 2 * std::numbers::pi, o.tolerance);
  double pass = 0;
  for (const Path& c : contours)
    pass += linearized_points(c, o.tolerance) + corner + 4.0 * o.tabs.count + 8;
  return std::ceil(o.depth / o.step_down) * pass + 10;
}

bool check_profile(const std::vector<Path>& contours, const ProfileOptions& o,
                   core::DiagnosticSink& diags) {
  if (!check_ranges(o, diags) || !check_extent(contours, diags) ||
      !check_passes(o.depth, o.step_down, diags)) {
    return false;
  }
  const bool needs_closed = o.side == ProfileSide::Outside || o.side == ProfileSide::Inside ||
                            o.side == ProfileSide::Auto;
  for (const Path& c : contours) {
    if (needs_closed && !c.closed) {
      return fail(diags, core::Code::GenOpenOutline,
                  fmt::format("the contour from ({:g}, {:g}) is open, so it has no inside or "
                              "outside; use --side left or right",
                              c.start.x, c.start.y));
    }
  }
  return check_work("the profile", estimate_moves(contours, o), o.cut.max_moves, kLessWork, diags);
}

// The lead arcs of a cut inside a closed contour stay inside its tool path
// (where the tool centre may be): a lead radius bigger than the room would
// swing the tool through the far wall.
bool check_leads_fit(const Cut& cut, const ProfileOptions& o, core::DiagnosticSink& diags) {
  if (o.lead_radius <= 0.0 || cut.side != ProfileSide::Inside || !cut.path.closed) return true;
  // 0.01 mm of slack: near where they touch, the lead arc and the path's
  // chords cross within the tolerance.
  const std::vector<Ring> room =
      offset_rings({to_ring(cut.path, o.tolerance, true)}, 0.01, o.tolerance);
  if (room.empty()) return true;
  const int side = lead_side(cut.side);
  const Lead in = lead_in(cut.path, o.lead_radius, side);
  const Lead out = lead_out(cut.path, o.lead_radius, side);
  std::vector<Vec2> pts = linearize({in.from, {{in.to, in.center, in.turn}}, false}, o.tolerance);
  pts.pop_back();  // on the path
  const std::vector<Vec2> out_pts =
      linearize({out.from, {{out.to, out.center, out.turn}}, false}, o.tolerance);
  pts.insert(pts.end(), out_pts.begin() + 1, out_pts.end());
  for (const Vec2& q : pts) {
    if (inside(room.front(), q)) continue;
    return fail(diags, core::Code::GenBadValue,
                fmt::format("the lead arc of radius {:g} mm at ({:.4g}, {:.4g}) does not fit "
                            "inside the contour: the tool would cut its far wall; give a "
                            "smaller --lead-radius",
                            o.lead_radius, cut.path.start.x, cut.path.start.y));
  }
  return true;
}

bool check_tabs_fit(const Path& p, const ProfileOptions& o, core::DiagnosticSink& diags) {
  if (o.tabs.count == 0) return true;
  const double need = o.tabs.count * (o.tabs.width + o.cut.tool_diameter);
  const double have = path_length(p);
  if (need < have) return true;
  return fail(diags, core::Code::GenBadValue,
              fmt::format("{} tabs {:g} mm wide with a {:g} mm tool need more than {:.3f} mm of "
                          "tool path, and the path from ({:g}, {:g}) is {:.3f} mm long; use fewer "
                          "or narrower tabs",
                          o.tabs.count, o.tabs.width, o.cut.tool_diameter, need, p.start.x,
                          p.start.y, have));
}

}  // namespace

int lead_side(ProfileSide side) {
  return side == ProfileSide::Right ? -1 : 1;
}

std::vector<Path> profile_paths(const Path& contour, const ProfileOptions& o) {
  const double r = o.offset.value_or(o.cut.tool_diameter / 2.0);
  const bool sided = o.side == ProfileSide::Left || o.side == ProfileSide::Right;
  if (o.side == ProfileSide::On || (r <= 0.0 && (sided || !contour.closed))) return {contour};
  if (sided) {
    std::vector<Path> out;
    core::DiagnosticList ignored;  // an empty result says the tool does not fit
    tool_paths({contour}, o.side == ProfileSide::Left ? Side::Left : Side::Right, r, o.tolerance,
               out, ignored);
    return out;
  }
  const bool ccw = signed_area2(linearize(contour, o.tolerance)) > 0.0;
  const bool outside = o.side != ProfileSide::Inside;  // Auto: one contour is an outline
  // The outside of a counter-clockwise contour is on its right.
  std::vector<Path> out =
      r > 0.0 ? offset_closed(contour, r, outside != ccw, o.tolerance) : std::vector<Path>{contour};
  for (Path& p : out) {
    const bool p_ccw = signed_area2(linearize(p, o.tolerance)) > 0.0;
    if (p_ccw == outside) p = reversed(p);  // outside clockwise, inside counter-clockwise
  }
  return out;
}

std::vector<int> nesting_depths(const std::vector<Path>& contours, double tolerance) {
  std::vector<Ring> rings;
  for (const Path& c : contours)
    rings.push_back(linearize(c, tolerance));
  std::vector<int> depth(contours.size(), 0);
  for (std::size_t i = 0; i < contours.size(); ++i) {
    for (std::size_t j = 0; j < contours.size(); ++j) {
      if (i != j && contours[j].closed && inside(rings[j], contours[i].start)) ++depth[i];
    }
  }
  return depth;
}

namespace {

// Each contour's side: the option's, or under Auto the one its nesting gives.
// Under Auto the holes come first (deepest first), so the part is still held
// by its outline while they are cut.
std::vector<std::pair<const Path*, ProfileSide>> sides_of(const std::vector<Path>& contours,
                                                          const ProfileOptions& o) {
  std::vector<std::pair<const Path*, ProfileSide>> out;
  if (o.side != ProfileSide::Auto) {
    for (const Path& c : contours)
      out.emplace_back(&c, o.side);
    return out;
  }
  const std::vector<int> depth = nesting_depths(contours, o.tolerance);
  std::vector<std::size_t> order(contours.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return depth[a] > depth[b]; });
  for (const std::size_t i : order) {
    out.emplace_back(&contours[i], depth[i] % 2 == 0 ? ProfileSide::Outside : ProfileSide::Inside);
  }
  return out;
}

}  // namespace

bool generate_profile(const std::vector<Path>& contours, const ProfileOptions& o, canon::Sink& sink,
                      core::DiagnosticSink& diags) {
  if (!check_profile(contours, o, diags)) return false;
  std::vector<Cut> cuts;
  for (const auto& [c, side] : sides_of(contours, o)) {
    ProfileOptions one = o;
    one.side = side;
    std::vector<Path> ps = profile_paths(*c, one);
    if (ps.empty()) {
      return fail(diags, core::Code::GenToolTooBig,
                  fmt::format("the contour from ({:g}, {:g}) leaves no room for a tool of "
                              "diameter {:g} mm on that side; use a smaller tool",
                              c->start.x, c->start.y, o.cut.tool_diameter));
    }
    for (Path& p : ps) {
      if (!check_tabs_fit(p, o, diags)) return false;
      cuts.push_back({std::move(p), side});
      if (!check_leads_fit(cuts.back(), o, diags)) return false;
    }
  }
  std::vector<Path> paths;
  for (const Cut& cut : cuts)
    paths.push_back(cut.path);
  const std::vector<double> levels = depth_levels(o.depth, o.step_down);
  const double moves =
      static_cast<double>(levels.size()) *
          (path_moves(paths) + static_cast<double>(cuts.size()) * (4.0 * o.tabs.count + 4)) +
      10;
  if (!check_work("the profile", moves, o.cut.max_moves, kLessWork, diags)) return false;
  ProgramWriter w(sink, o.cut);
  w.begin(fmt::format("usina gen profile: {} contours, depth {:g} mm", cuts.size(), o.depth));
  for (const Cut& cut : cuts) {
    for (const double z : levels)
      one_pass(w, cut, z, o);
  }
  w.end();
  return true;
}

std::optional<ProfileSide> profile_side(std::string_view name) {
  constexpr std::pair<std::string_view, ProfileSide> kNames[] = {
      {"outside", ProfileSide::Outside}, {"inside", ProfileSide::Inside},
      {"left", ProfileSide::Left},       {"right", ProfileSide::Right},
      {"on", ProfileSide::On},           {"auto", ProfileSide::Auto}};
  for (const auto& [n, side] : kNames) {
    if (n == name) return side;
  }
  return std::nullopt;
}

}  // namespace usina::cam
