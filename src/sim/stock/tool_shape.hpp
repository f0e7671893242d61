// The cutters `usina simulate` sweeps through the stock, by the shape of
// their lower end: flat end mill, ball nose, bull nose (corner radius),
// drill point (118°) and chamfer/V (an included angle). Each is a convex
// solid of revolution about Z; `lift(r)` is the height of its lower surface
// above the tip at r mm from the axis (docs/simulate.md).
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <utility>

#include <tl/expected.hpp>

namespace usina::sim::stock {

enum class ToolKind : unsigned char { Flat, Ball, BullNose, Drill, Vee };

struct ToolShape {
  ToolKind kind = ToolKind::Flat;
  double diameter = 6.0;       // mm
  double corner_radius = 0.0;  // mm, bull nose only (0 < r < diameter/2)
  double angle = 118.0;        // degrees included, drill and V only

  double radius() const { return diameter / 2.0; }

  // Height of the lower surface above the tip at `r` mm from the axis
  // (0 <= r <= radius()); above the cone or the corner the tool is a
  // cylinder, so nothing lower than this is cut at r.
  double lift(double r) const;

  // 1 / tan(angle / 2): the rise of a cone per mm of radius.
  double cone_slope() const;
};

// Bounds every tool keeps (docs/simulate.md): a diameter in (0, 1000] mm,
// an angle in [10, 170] degrees.
inline constexpr double kMaxToolDiameter = 1000.0;
inline constexpr double kMinToolAngle = 10.0;
inline constexpr double kMaxToolAngle = 170.0;

// Reads a shape's words: "flat", "ball", "bull:R" (corner radius mm),
// "drill" (118°), "drill:A", "vee" or "chamfer" (90°), "vee:A" (included
// angle, degrees). The diameter is not changed. An error says what is wrong.
tl::expected<ToolShape, std::string> parse_shape(std::string_view words, double diameter);

// The shape a tool table's comment names: its first word among "flat",
// "ball", "bull:R", "drill", "vee", "chamfer" (case-insensitive), or flat.
ToolShape shape_from_comment(std::string_view comment, double diameter);

// Checks a shape's numbers (finite, within the bounds above).
tl::expected<void, std::string> check_shape(const ToolShape& t);

std::string shape_name(const ToolShape& t);

// One value of `usina simulate --tool-shape`, "T=SHAPE" or "T=SHAPE/D": the
// tool's number (0..99999) and its shape. Without /D the diameter is the
// one `known` (the tool table's tools) gives tool T. An error says what is wrong.
tl::expected<std::pair<int, ToolShape>, std::string> parse_tool_spec(
    std::string_view spec, const std::map<int, ToolShape>& known);

}  // namespace usina::sim::stock
