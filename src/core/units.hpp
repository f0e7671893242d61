// Units and angle conversions. Internally usina works in mm, s and radians.
#pragma once

#include <numbers>

namespace usina::core {

inline constexpr double kMmPerInch = 25.4;
inline constexpr double kPi = std::numbers::pi;

enum class LengthUnit { Mm, Inch };

constexpr double mm_per(LengthUnit u) {
  return u == LengthUnit::Inch ? kMmPerInch : 1.0;
}

constexpr double deg_to_rad(double deg) {
  return deg * kPi / 180.0;
}

constexpr double rad_to_deg(double rad) {
  return rad * 180.0 / kPi;
}

}  // namespace usina::core
