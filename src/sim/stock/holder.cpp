#include "sim/stock/holder.hpp"

#include <algorithm>
#include <cmath>

namespace usina::sim::stock {
namespace {

// The stretch of the move, for a cell whose column the holder covers over
// `holder` and the tool over `tool`, in which the holder is there and the tool
// is not, on the given side of the tool's passage.
Stretch without_the_tool(const Stretch& holder, const Stretch& tool, HolderStretch side) {
  if (side == HolderStretch::BeforeTheTool) {
    if (tool.empty()) return holder;  // the tool never reaches the column: all of it
    if (holder.first < tool.first) return {holder.first, tool.first};
    return {};
  }
  if (tool.empty()) return {};  // seen whole before the tool
  if (tool.last < holder.last) return {tool.last, holder.last};
  return {};
}

struct Holder {
  double radius = 0.0, face = 0.0, tool_radius = 0.0;
};

// The deepest the holder goes into the cells [i0, i1) x [j0, j1).
double cells_depth(HeightMap& map, const Path& p, const Holder& h, std::size_t i0, std::size_t i1,
                   std::size_t j0, std::size_t j1, HolderStretch side) {
  const double rh2 = h.radius * h.radius, rt2 = h.tool_radius * h.tool_radius;
  double deepest = 0.0;
  for (std::size_t j = j0; j < j1; ++j) {
    const float* row = map.row(j);
    for (std::size_t i = i0; i < i1; ++i) {
      const double qx = map.x(i) - p.ax, qy = map.y(j) - p.ay;
      const double along = qx * p.ux + qy * p.uy;
      const double e = qx * p.uy - qy * p.ux;
      if (distance2(p, along, e) > rh2) continue;
      const Stretch holder = covering(p, along, std::sqrt(rh2 - e * e));
      if (holder.empty()) continue;
      const Stretch tool = e * e <= rt2 ? covering(p, along, std::sqrt(rt2 - e * e)) : Stretch{};
      const Stretch s = without_the_tool(holder, tool, side);
      // Rising, the face is lowest where the stretch begins: at the move's
      // start it is where the move before left it, and was checked there.
      if (s.empty() || (p.rises && s.first <= 0.0)) continue;
      deepest =
          std::max(deepest, static_cast<double>(row[i]) - (p.tip_lowest(s.first, s.last) + h.face));
    }
  }
  return deepest;
}

}  // namespace

double holder_depth(HeightMap& map, const Path& p, const ToolShape& tool, HolderStretch side,
                    double found) {
  const Holder h{tool.holder / 2.0, tool.stickout, tool.radius()};
  // Heights are at most 0 (the top): a face that stays above it meets nothing,
  // which is most moves of most programs, at one comparison.
  if (p.tip_lowest(0.0, p.length) + h.face >= -kHolderContact) return found;
  if (p.rises && p.length == 0.0) return found;  // straight up: lowest where it was
  const double bx = p.ax + p.ux * p.length, by = p.ay + p.uy * p.length;
  std::size_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  map.columns(std::min(p.ax, bx) - h.radius, std::max(p.ax, bx) + h.radius, i0, i1);
  map.rows(std::min(p.ay, by) - h.radius, std::max(p.ay, by) + h.radius, j0, j1);
  const std::size_t T = HeightMap::kTile;
  const double half = 0.5 * std::hypot(map.dx(), map.dy()) * static_cast<double>(T);
  // A tile whose highest cell stands no deeper above the face's lowest over
  // it than the deepest found so far cannot change the answer (a buried
  // holder would otherwise compare every cell under it, every move).
  double deepest = std::max(found, kHolderContact);
  const auto visit = [&](std::size_t ti, std::size_t tj) {
    const double qx = map.x(ti * T) + 0.5 * (static_cast<double>(T) - 1.0) * map.dx() - p.ax;
    const double qy = map.y(tj * T) + 0.5 * (static_cast<double>(T) - 1.0) * map.dy() - p.ay;
    const double along = qx * p.ux + qy * p.uy;
    const double d = std::sqrt(distance2(p, along, qx * p.uy - qy * p.ux)) - half;
    if (d > h.radius) return;
    // The face's lowest while the holder can be over the tile.
    const double reach = h.radius + half;
    const double floor = p.tip_lowest(std::clamp(along - reach, 0.0, p.length),
                                      std::clamp(along + reach, 0.0, p.length)) +
                         h.face;
    if (static_cast<double>(map.tile_max(ti, tj)) <= floor + deepest) return;
    deepest =
        std::max(deepest, cells_depth(map, p, h, std::max(i0, ti * T), std::min(i1, (ti + 1) * T),
                                      std::max(j0, tj * T), std::min(j1, (tj + 1) * T), side));
  };
  if (i1 <= i0 || j1 <= j0) return found;
  // From the end of the move where the face is lowest: the deepest contact
  // found first passes over most of the rest.
  const bool from_end = p.k < 0.0;
  const std::size_t ta = i0 / T, tb = (i1 - 1) / T, sa = j0 / T, sb = (j1 - 1) / T;
  const bool i_down = (p.ux > 0.0) == from_end, j_down = (p.uy > 0.0) == from_end;
  for (std::size_t m = 0; m <= sb - sa; ++m) {
    const std::size_t tj = j_down ? sb - m : sa + m;
    for (std::size_t n = 0; n <= tb - ta; ++n)
      visit(i_down ? tb - n : ta + n, tj);
  }
  return deepest > kHolderContact ? deepest : found;
}

}  // namespace usina::sim::stock
