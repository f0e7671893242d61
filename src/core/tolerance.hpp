// Tolerances for comparing positions (DESIGN.md, "Numbers").
#pragma once

#include <algorithm>
#include <cmath>

namespace usina::core {

// Geometry checks (is this point on that circle?) in mm.
inline constexpr double kGeometryTolerance = 1e-6;
// Relative tolerance for comparing computed values.
inline constexpr double kRelativeTolerance = 1e-9;

inline bool nearly_equal(double a, double b, double abs_tol = kGeometryTolerance) {
  return std::fabs(a - b) <=
         std::max(abs_tol, kRelativeTolerance * std::max(std::fabs(a), std::fabs(b)));
}

}  // namespace usina::core
