// Test helper: the distance from a point to an ellipse centred at the origin.
#pragma once

#include <cmath>
#include <numbers>

#include "core/vec3.hpp"

namespace usina::test {

// Unsigned distance from q to the ellipse x²/rx² + y²/ry² = 1: the best of a
// dense sample of the parameter refined by golden-section search.
inline double ellipse_distance(core::Vec2 q, double rx, double ry) {
  auto d2 = [&](double t) {
    const double dx = rx * std::cos(t) - q.x;
    const double dy = ry * std::sin(t) - q.y;
    return dx * dx + dy * dy;
  };
  constexpr int kSamples = 2048;
  const double step = 2 * std::numbers::pi / kSamples;
  double best = 0;
  for (int i = 1; i < kSamples; ++i)
    if (d2(i * step) < d2(best)) best = i * step;
  double lo = best - step;
  double hi = best + step;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 100; ++i) {
    const double a = hi - g * (hi - lo);
    const double b = lo + g * (hi - lo);
    if (d2(a) < d2(b)) {
      hi = b;
    } else {
      lo = a;
    }
  }
  return std::sqrt(d2((lo + hi) / 2));
}

inline bool inside_ellipse(core::Vec2 q, double rx, double ry) {
  return (q.x * q.x) / (rx * rx) + (q.y * q.y) / (ry * ry) < 1.0;
}

}  // namespace usina::test
