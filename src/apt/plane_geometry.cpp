#include "apt/plane_geometry.hpp"

#include <cmath>

namespace usina::apt {
namespace {

constexpr double kEps = 1e-10;

}  // namespace

std::optional<Vec2> meet(const Line2& a, const Line2& b) {
  const double det = a.n.x * b.n.y - a.n.y * b.n.x;
  if (std::fabs(det) < kEps) return std::nullopt;
  return Vec2{(a.d * b.n.y - b.d * a.n.y) / det, (a.n.x * b.d - b.n.x * a.d) / det};
}

std::vector<Vec2> meet(const Line2& l, const Circle2& c) {
  // The foot of the perpendicular from the centre, then ± along the line.
  const double dist = l.n.x * c.c.x + l.n.y * c.c.y - l.d;
  const Vec2 foot{c.c.x - dist * l.n.x, c.c.y - dist * l.n.y};
  const double h2 = c.r * c.r - dist * dist;
  const double tol = 1e-9 * std::max(1.0, c.r * c.r);
  if (h2 < -tol) return {};
  if (h2 <= tol) return {foot};
  const double h = std::sqrt(h2);
  const Vec2 u{-l.n.y, l.n.x};
  return {Vec2{foot.x + h * u.x, foot.y + h * u.y}, Vec2{foot.x - h * u.x, foot.y - h * u.y}};
}

std::vector<Vec2> meet(const Circle2& a, const Circle2& b) {
  const double dx = b.c.x - a.c.x;
  const double dy = b.c.y - a.c.y;
  const double d = std::hypot(dx, dy);
  if (d < kEps) return {};
  const double along = (d * d + a.r * a.r - b.r * b.r) / (2.0 * d);
  const double h2 = a.r * a.r - along * along;
  const double tol = 1e-9 * std::max(1.0, a.r * a.r);
  if (h2 < -tol) return {};
  const Vec2 base{a.c.x + along * dx / d, a.c.y + along * dy / d};
  if (h2 <= tol) return {base};
  const double h = std::sqrt(h2);
  return {Vec2{base.x - h * dy / d, base.y + h * dx / d},
          Vec2{base.x + h * dy / d, base.y - h * dx / d}};
}

bool is_selector(std::string_view w) {
  return w == "XLARGE" || w == "XSMALL" || w == "YLARGE" || w == "YSMALL" || w == "ZLARGE" ||
         w == "ZSMALL";
}

std::optional<Vec2> choose(std::string_view sel, const std::vector<Vec2>& candidates) {
  if (candidates.empty() || sel.size() < 2) return std::nullopt;
  const bool large = sel.substr(1) == "LARGE";
  const bool by_x = sel[0] == 'X';
  std::optional<Vec2> best;
  for (const Vec2& p : candidates) {
    if (!best) {
      best = p;
      continue;
    }
    const double v = by_x ? p.x : p.y;
    const double b = by_x ? best->x : best->y;
    if (large ? v > b : v < b) best = p;
  }
  return best;
}

int side_sign(std::string_view sel, const core::Vec3& normal) {
  if (sel.size() < 2) return 0;
  const double comp = sel[0] == 'X' ? normal.x : (sel[0] == 'Y' ? normal.y : normal.z);
  if (std::fabs(comp) < 1e-9) return 0;
  const bool large = sel.substr(1) == "LARGE";
  return (comp > 0) == large ? 1 : -1;
}

}  // namespace usina::apt
