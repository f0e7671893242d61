#include "sim/stock/target.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace usina::sim::stock {
namespace {

// Where the rings cross the horizontal line at `y`, in X order: the spans
// between the 1st and 2nd, 3rd and 4th... crossings are inside (even-odd).
// An edge counts from its lower end up to, not including, its upper end,
// so a vertex on the line is crossed once and a horizontal edge never.
void crossings(const std::vector<std::vector<Vec2>>& rings, double y, std::vector<double>& xs) {
  xs.clear();
  for (const auto& ring : rings) {
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 a = ring[k];
      const Vec2 b = ring[(k + 1) % n];
      if ((a.y <= y) == (b.y <= y)) continue;
      xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
    }
  }
  std::sort(xs.begin(), xs.end());
}

}  // namespace

// Row by row, the cells whose centres fall between a pair of crossings.
// The cost is the target's cells plus its edges once a row.
TargetResult check_target(const HeightMap& map, const TargetLayer& target, double tolerance) {
  TargetResult r;
  r.layer = target.layer;
  r.title = target.title.empty() ? "layer " + target.layer : target.title;
  r.reachable = target.reachable;
  r.operation = target.operation;
  r.z = target.z;
  std::vector<double> xs;
  std::size_t inside = 0, above = 0;
  double left = 0.0;
  for (std::size_t j = 0; j < map.ny(); ++j) {
    crossings(target.rings, map.y(j), xs);
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      std::size_t i0 = 0, i1 = 0;
      map.columns(xs[k], xs[k + 1], i0, i1);
      for (std::size_t i = i0; i < i1; ++i) {
        ++inside;
        const double over = map.z(i, j) - target.z;
        if (over <= 0.0) continue;
        left += over;
        if (over <= tolerance) continue;
        ++above;
        if (over > r.most_above_mm) {
          r.most_above_mm = over;
          r.most_at = {map.x(i), map.y(j)};
        }
      }
    }
  }
  r.area_mm2 = static_cast<double>(inside) * map.cell_area();
  r.above_mm2 = static_cast<double>(above) * map.cell_area();
  r.left_mm3 = left * map.cell_area();
  return r;
}

std::string material_above_message(const TargetResult& r, double tolerance) {
  return fmt::format(
      "{} (Z{:g}): {:.2f} mm² of its {:.2f} mm² stand more than {:g} mm above the target, "
      "up to {:.3f} mm (the most at X{:.3f} Y{:.3f}); {:.3f} mm³ left there. {}",
      r.title, r.z, r.above_mm2, r.area_mm2, tolerance, r.most_above_mm, r.most_at.x, r.most_at.y,
      r.left_mm3,
      r.reachable ? "The area is what the operation's tool can reach: its corners are left out"
                  : "Corners narrower than the tool count too");
}

}  // namespace usina::sim::stock
