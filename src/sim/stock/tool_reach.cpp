// The tool above its end: how long its flutes are, the holder's diameter and
// the stick-out, and whether it cuts at its centre (docs/simulate.md,
// "Shank, holder, plunge"). Written by the user or absent: a value not given
// is 0 and its check is not made, never a guess.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "sim/stock/tool_shape.hpp"
#include "sim/stock/words.hpp"

namespace usina::sim::stock {
namespace {

bool separator(char c) {
  return c == ',' || std::isspace(static_cast<unsigned char>(c)) != 0;
}

// A length after "flutes:", "holder:", "stickout:": finite, in (0, kMaxToolLength].
tl::expected<double, std::string> length_of(const std::string& key, const std::string& value) {
  const auto v = finite_number(value);
  if (!v) {
    const char* hint = key == "holder" && value.find('x') != std::string::npos
                           ? " (the holder's diameter only: its length is not used)"
                           : "";
    return tl::unexpected(fmt::format("'{}' after '{}:' is not a number{}", value, key, hint));
  }
  if (*v <= 0.0 || *v > kMaxToolLength) {
    return tl::unexpected(fmt::format("'{}:' must be more than 0 and at most {:g} mm, not {:g}",
                                      key, kMaxToolLength, *v));
  }
  return *v;
}

tl::expected<double, std::string> ramp_of(const std::string& value) {
  if (value.empty()) return kDefaultPlungeRamp;
  const auto v = finite_number(value);
  if (!v || *v <= 0.0 || *v >= 90.0) {
    return tl::unexpected(fmt::format(
        "'no-plunge:{}': the steepest ramp must be more than 0 and less than 90 degrees", value));
  }
  return *v;
}

// One word; false when it is none of the words above the end.
tl::expected<bool, std::string> read_word(std::string_view word, ToolShape& t) {
  const std::string w = lower(word);
  const std::size_t colon = w.find(':');
  const std::string key = w.substr(0, colon);
  const std::string value = colon == std::string::npos ? std::string() : w.substr(colon + 1);
  double* length = key == "flutes"     ? &t.flutes
                   : key == "holder"   ? &t.holder
                   : key == "stickout" ? &t.stickout
                                       : nullptr;
  if (length != nullptr && colon != std::string::npos) {
    auto v = length_of(key, value);
    if (!v) return tl::unexpected(v.error());
    *length = *v;
    return true;
  }
  if (key == "no-plunge") {
    auto v = ramp_of(value);
    if (!v) return tl::unexpected(v.error());
    t.plunge_ramp = *v;
    return true;
  }
  return false;
}

}  // namespace

tl::expected<void, std::string> read_reach_words(std::string_view text, bool strict, ToolShape& t) {
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && separator(text[i]))
      ++i;
    std::size_t j = i;
    while (j < text.size() && !separator(text[j]))
      ++j;
    if (j > i) {
      const std::string_view word = text.substr(i, j - i);
      auto known = read_word(word, t);
      if (!known) return tl::unexpected(known.error());
      if (!*known && strict) {
        return tl::unexpected(
            fmt::format("'{}' is not a word after a tool's shape: flutes:L, holder:D, "
                        "stickout:L, no-plunge or no-plunge:A",
                        word));
      }
    }
    i = j;
  }
  return {};
}

tl::expected<void, std::string> check_reach(const ToolShape& t) {
  const double end = t.end_height();
  if (t.holder > 0.0 && t.stickout <= 0.0) {
    return tl::unexpected(std::string(
        "a holder needs its stick-out: stickout:L, mm from the tool's tip to the holder's face"));
  }
  if (t.flutes > 0.0 && t.flutes < end) {
    return tl::unexpected(fmt::format(
        "flutes of {:g} mm are shorter than the tool's end ({:g} mm from the tip)", t.flutes, end));
  }
  if (t.stickout > 0.0 && t.stickout < std::max(t.flutes, end)) {
    return tl::unexpected(fmt::format(
        "a stick-out of {:g} mm is shorter than the {} ({:g} mm): the holder would cover them",
        t.stickout, t.flutes >= end ? "flutes" : "tool's end", std::max(t.flutes, end)));
  }
  if (t.plunge_ramp > 0.0 && t.kind != ToolKind::Flat && t.kind != ToolKind::BullNose) {
    return tl::unexpected(std::string(
        "no-plunge is for a flat or bull nose end mill: a ball, a drill or a V cuts at its "
        "centre"));
  }
  return {};
}

tl::expected<ToolShape, std::string> tool_from_comment(std::string_view comment, double diameter) {
  ToolShape t = shape_from_comment(comment, diameter);
  auto read = read_reach_words(comment, false, t);
  if (read) read = check_shape(t);
  if (!read) return tl::unexpected(read.error());
  return t;
}

}  // namespace usina::sim::stock
