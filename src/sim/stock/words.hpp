// Numbers and letters in the words of `usina simulate`'s options (--stock,
// --tool-shape) and of a tool table's comments.
#pragma once

#include <charconv>
#include <cmath>
#include <optional>
#include <string>
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

// `s` in lower case (ASCII): the words are read in any case.
inline std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

}  // namespace usina::sim::stock
