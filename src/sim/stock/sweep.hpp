// The exact sweep of a tool along a straight move through the height map:
// each cell under the path gets the lowest point of the tool's lower
// envelope over the move, found in closed form (flat, ball, drill, V) or by
// bisection of a convex function to 1e-9 mm (bull nose), never by stamping
// the tool at sample points (docs/simulate.md, "Sweeping").
#pragma once

#include <cstdint>
#include <limits>

#include "core/vec3.hpp"
#include "sim/stock/height_map.hpp"
#include "sim/stock/tool_shape.hpp"

namespace usina::sim::stock {

struct Cut {
  double removed_mm3 = 0.0;
  double deepest = 0.0;  // mm: the most one cell lost
  // The lowest the tool's lower surface came over a cell of the stock
  // (cut or not), Z mm; +inf when it passed over none.
  double lowest = std::numeric_limits<double>::infinity();

  void add(const Cut& c);
};

// Sweeps `tool` with its tip from `a` to `b` (Z up, the tool vertical):
// lowers the cells under it, marks those it cut with `mark`.
Cut sweep(HeightMap& map, const ToolShape& tool, const core::Vec3& a, const core::Vec3& b,
          std::uint8_t mark);

// The lowest point of the tool's lower surface over (cx, cy) while its tip
// moves from a to b, Z mm; +inf when the tool does not pass over it. What
// sweep() gives each cell (tests check it against brute force).
double envelope(const ToolShape& tool, const core::Vec3& a, const core::Vec3& b, double cx,
                double cy);

}  // namespace usina::sim::stock
