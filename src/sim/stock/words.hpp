// Numbers in the words of `usina simulate`'s options (--stock, --tool-shape).
#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string_view>

namespace usina::sim::stock {

// The whole of `s` as a finite number, or nullopt.
inline std::optional<double> finite_number(std::string_view s) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) {
    return std::nullopt;
  }
  return v;
}

}  // namespace usina::sim::stock
