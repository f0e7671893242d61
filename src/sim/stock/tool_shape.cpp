#include "sim/stock/tool_shape.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "sim/stock/words.hpp"

namespace usina::sim::stock {
namespace {

// "ball" -> (ball, ""), "bull:1.5" -> (bull, "1.5").
std::pair<std::string, std::string> split_word(std::string_view words) {
  const std::string w = lower(words);
  const std::size_t colon = w.find(':');
  if (colon == std::string::npos) return {w, ""};
  return {w.substr(0, colon), w.substr(colon + 1)};
}

// The end's own numbers: diameter, corner radius, point angle.
tl::expected<void, std::string> check_end(const ToolShape& t) {
  if (!std::isfinite(t.diameter) || t.diameter < kMinToolDiameter ||
      t.diameter > kMaxToolDiameter) {
    return tl::unexpected(
        fmt::format("a tool's diameter must be at least {:g} and at most {:g} mm, "
                    "not {:g}",
                    kMinToolDiameter, kMaxToolDiameter, t.diameter));
  }
  if (t.kind == ToolKind::BullNose && (!std::isfinite(t.corner_radius) || t.corner_radius <= 0.0 ||
                                       t.corner_radius >= t.radius())) {
    return tl::unexpected(fmt::format(
        "a bull nose's corner radius must be more than 0 and less than the tool's radius "
        "({:g} mm), not {:g}",
        t.radius(), t.corner_radius));
  }
  if ((t.kind == ToolKind::Drill || t.kind == ToolKind::Vee) &&
      (!std::isfinite(t.angle) || t.angle < kMinToolAngle || t.angle > kMaxToolAngle)) {
    return tl::unexpected(
        fmt::format("a point's included angle must be {:g} to {:g} degrees, "
                    "not {:g}",
                    kMinToolAngle, kMaxToolAngle, t.angle));
  }
  return {};
}

}  // namespace

double ToolShape::cone_slope() const {
  return 1.0 / std::tan(angle * std::numbers::pi / 360.0);
}

double ToolShape::lift(double r) const {
  switch (kind) {
  case ToolKind::Flat: return 0.0;
  case ToolKind::Ball: {
    const double R = radius();
    return R - std::sqrt(std::max(0.0, R * R - r * r));
  }
  case ToolKind::BullNose: {
    const double flat = radius() - corner_radius;
    if (r <= flat) return 0.0;
    const double d = r - flat;
    return corner_radius - std::sqrt(std::max(0.0, corner_radius * corner_radius - d * d));
  }
  case ToolKind::Drill:
  case ToolKind::Vee: return r * cone_slope();
  }
  return 0.0;
}

tl::expected<void, std::string> check_shape(const ToolShape& t) {
  if (auto ok = check_end(t); !ok) return ok;
  return check_reach(t);
}

tl::expected<ToolShape, std::string> parse_shape(std::string_view words, double diameter) {
  const auto [name, arg] = split_word(words);
  ToolShape t;
  t.diameter = diameter;
  // A plain double and a flag, not an optional: GCC 12 at -O3 warns of a
  // false uninitialised read of an optional<double> here (-Wmaybe-uninitialized).
  const bool given = !arg.empty();
  double value = 0.0;
  if (given) {
    if (auto v = finite_number(arg)) value = *v;
  }
  if (given && !finite_number(arg)) {
    return tl::unexpected(fmt::format("'{}' after '{}:' is not a number", arg, name));
  }
  if (name == "flat" || name == "endmill") {
    t.kind = ToolKind::Flat;
  } else if (name == "ball") {
    t.kind = ToolKind::Ball;
  } else if (name == "bull") {
    t.kind = ToolKind::BullNose;
    if (!given) return tl::unexpected(std::string("a bull nose needs its corner radius: bull:R"));
    t.corner_radius = value;
  } else if (name == "drill") {
    t.kind = ToolKind::Drill;
    t.angle = given ? value : 118.0;
  } else if (name == "vee" || name == "chamfer" || name == "v") {
    t.kind = ToolKind::Vee;
    t.angle = given ? value : 90.0;
  } else {
    return tl::unexpected(fmt::format(
        "'{}' is not a tool shape: flat, ball, bull:R, drill[:A], vee[:A] or chamfer[:A]", name));
  }
  if (!arg.empty() && (t.kind == ToolKind::Flat || t.kind == ToolKind::Ball)) {
    return tl::unexpected(fmt::format("'{}' takes no number", name));
  }
  if (auto ok = check_shape(t); !ok) return tl::unexpected(ok.error());
  return t;
}

ToolShape shape_from_comment(std::string_view comment, double diameter) {
  std::size_t i = 0;
  while (i < comment.size()) {
    while (i < comment.size() && std::isspace(static_cast<unsigned char>(comment[i])) != 0)
      ++i;
    std::size_t j = i;
    while (j < comment.size() && std::isspace(static_cast<unsigned char>(comment[j])) == 0)
      ++j;
    if (j > i) {
      if (auto t = parse_shape(comment.substr(i, j - i), diameter)) return *t;
    }
    i = j;
  }
  ToolShape flat;
  flat.diameter = diameter;
  return flat;
}

std::string shape_name(const ToolShape& t) {
  switch (t.kind) {
  case ToolKind::Flat: return fmt::format("flat {:g} mm", t.diameter);
  case ToolKind::Ball: return fmt::format("ball {:g} mm", t.diameter);
  case ToolKind::BullNose:
    return fmt::format("bull nose {:g} mm, corner {:g} mm", t.diameter, t.corner_radius);
  case ToolKind::Drill: return fmt::format("drill {:g} mm, {:g}°", t.diameter, t.angle);
  case ToolKind::Vee: return fmt::format("V {:g} mm, {:g}°", t.diameter, t.angle);
  }
  return "tool";
}

}  // namespace usina::sim::stock

namespace usina::sim::stock {

tl::expected<std::pair<int, ToolShape>, std::string> parse_tool_spec(
    std::string_view spec, const std::map<int, ToolShape>& known) {
  const std::size_t eq = spec.find('=');
  const auto number = finite_number(spec.substr(0, eq));
  if (eq == std::string_view::npos || !number || *number < 0 || *number > 99999 ||
      *number != static_cast<int>(*number)) {
    return tl::unexpected(
        fmt::format("--tool-shape '{}' is not T=SHAPE[/D][,WORD]... (e.g. 3=ball/6, 4=bull:1/10, "
                    "1=flat/6,flutes:20,holder:32,stickout:30)",
                    spec));
  }
  // The shape and its diameter end at the first comma; the words above the end follow.
  const std::size_t comma = spec.find(',', eq);
  const std::string_view end = spec.substr(
      eq + 1, comma == std::string_view::npos ? std::string_view::npos : comma - eq - 1);
  const std::string_view words =
      comma == std::string_view::npos ? std::string_view{} : spec.substr(comma + 1);
  const std::size_t slash = end.find('/');
  const int n = static_cast<int>(*number);
  const auto listed = known.find(n);
  double diameter = listed != known.end() ? listed->second.diameter : 0.0;
  if (slash != std::string_view::npos) {
    const auto d = finite_number(end.substr(slash + 1));
    if (!d)
      return tl::unexpected(fmt::format("--tool-shape '{}': the diameter is not a number", spec));
    // A diameter written here is checked as written, not taken for a missing one.
    if (*d < kMinToolDiameter || *d > kMaxToolDiameter) {
      return tl::unexpected(
          fmt::format("--tool-shape '{}': the diameter must be at least {:g} and at most {:g} mm, "
                      "not {:g}",
                      spec, kMinToolDiameter, kMaxToolDiameter, *d));
    }
    diameter = *d;
  }
  if (diameter <= 0.0) {
    return tl::unexpected(
        fmt::format("--tool-shape '{}': tool {} has no diameter in the tool table; write it: "
                    "{}=SHAPE/D",
                    spec, n, n));
  }
  auto shape = parse_shape(end.substr(0, slash), diameter);
  if (!shape) return tl::unexpected(fmt::format("--tool-shape '{}': {}", spec, shape.error()));
  if (listed != known.end()) {
    // What the table's comment said above the end stays unless written again.
    shape->flutes = listed->second.flutes;
    shape->holder = listed->second.holder;
    shape->stickout = listed->second.stickout;
    shape->plunge_ramp = listed->second.plunge_ramp;
  }
  auto read = read_reach_words(words, true, *shape);
  if (read) read = check_shape(*shape);
  if (!read) return tl::unexpected(fmt::format("--tool-shape '{}': {}", spec, read.error()));
  return std::pair{n, *shape};
}

}  // namespace usina::sim::stock
