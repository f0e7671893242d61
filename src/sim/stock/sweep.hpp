// The exact sweep of a tool along a straight move through the height map:
// each cell under the path gets the lowest point of the tool's lower
// envelope over the move, found in closed form (flat, ball, drill, V) or by
// bisection of a convex function to 1e-9 mm (bull nose), never by stamping
// the tool at sample points (docs/simulate.md, "Sweeping").
#pragma once

#include <array>
#include <cstdint>
#include <limits>

#include "core/vec3.hpp"
#include "sim/stock/height_map.hpp"
#include "sim/stock/tool_shape.hpp"

namespace usina::sim::stock {

// A shank within this of the stock is not taken for rubbing it (mm).
inline constexpr double kShankContact = 0.001;
// Stock this high above the tip under a non-centre-cutting tool's axis is
// not taken for a plunge into it (mm).
inline constexpr double kPlungeStock = 0.01;

// A move's volume is also told by the stretch of the move that cut it, in
// this many equal parts of its length (the removal rate over time).
inline constexpr std::size_t kCutParts = 16;

struct Cut {
  double removed_mm3 = 0.0;
  // removed_mm3 by where along the move the tool's leading edge reached the
  // cell (part k: from k/kCutParts to (k+1)/kCutParts of the XY length; a
  // plunge's all in part 0). Summed part by part by add().
  std::array<double, kCutParts> parts_mm3{};
  double deepest = 0.0;  // mm: the most one cell lost
  // The lowest the tool's lower surface came over a cell of the stock
  // (cut or not), Z mm; +inf when it passed over none.
  double lowest = std::numeric_limits<double>::infinity();
  // Above the end, each 0 when clear (docs/simulate.md, "Shank, holder, plunge"):
  double shank_rub = 0.0;    // mm: stock above the flutes where the tool entered it
  double holder_hit = 0.0;   // mm: the deepest the holder went into stock
  double plunge_into = 0.0;  // mm: stock above the tip under a no-plunge tool's axis

  void add(const Cut& c);
};

// Sweeps `tool` with its tip from `a` to `b` (Z up, the tool vertical):
// lowers the cells under it, marks those it cut with `mark`; checks the
// shank, the holder and a plunge where the tool's words ask for it.
Cut sweep(HeightMap& map, const ToolShape& tool, const core::Vec3& a, const core::Vec3& b,
          std::uint8_t mark);

// The lowest point of the tool's lower surface over (cx, cy) while its tip
// moves from a to b, Z mm; +inf when the tool does not pass over it. What
// sweep() gives each cell (tests check it against brute force).
double envelope(const ToolShape& tool, const core::Vec3& a, const core::Vec3& b, double cx,
                double cy);

}  // namespace usina::sim::stock
