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
  // Above the end (docs/simulate.md, "Shank, holder, plunge"): each is 0
  // unless the user gave it, and a tool without it is not checked for it.
  double flutes = 0.0;       // mm above the tip the tool cuts; above, the shank rubs
  double holder = 0.0;       // mm, the holder's diameter: a cylinder from the stick-out up
  double stickout = 0.0;     // mm from the tip to the holder's face
  double plunge_ramp = 0.0;  // degrees: a tool not cutting at its centre ramps no steeper

  double radius() const { return diameter / 2.0; }

  // The height of the end above the tip (a ball's radius, a point's cone):
  // flutes and stick-out reach at least this far.
  double end_height() const { return lift(radius()); }

  // Height of the lower surface above the tip at `r` mm from the axis
  // (0 <= r <= radius()); above the cone or the corner the tool is a
  // cylinder, so nothing lower than this is cut at r.
  double lift(double r) const;

  // 1 / tan(angle / 2): the rise of a cone per mm of radius.
  double cone_slope() const;
};

// Bounds every tool keeps (docs/simulate.md): a diameter in [0.001, 1000]
// mm (below a micrometre is a slip, not a tool: the fuzzer's 6.5e-323),
// an angle in [10, 170] degrees.
inline constexpr double kMinToolDiameter = 0.001;
inline constexpr double kMaxToolDiameter = 1000.0;
inline constexpr double kMinToolAngle = 10.0;
inline constexpr double kMaxToolAngle = 170.0;
// Flutes, holder diameter and stick-out: more than 0, at most this (mm).
inline constexpr double kMaxToolLength = 1000.0;
// The steepest ramp of `no-plunge` when none is written (degrees).
inline constexpr double kDefaultPlungeRamp = 5.0;

// Reads a shape's words: "flat", "ball", "bull:R" (corner radius mm),
// "drill" (118°), "drill:A", "vee" or "chamfer" (90°), "vee:A" (included
// angle, degrees). The diameter is not changed. An error says what is wrong.
tl::expected<ToolShape, std::string> parse_shape(std::string_view words, double diameter);

// The shape a tool table's comment names: its first word among "flat",
// "ball", "bull:R", "drill", "vee", "chamfer" (case-insensitive), or flat.
ToolShape shape_from_comment(std::string_view comment, double diameter);

// Checks a shape's numbers (finite, within the bounds above) and that the
// words above the end go together: a holder with its stick-out, flutes at
// least as long as the end, a stick-out at least as long as the flutes, a
// no-plunge tool flat or bull nose (a ball, a drill or a V cuts at its centre).
tl::expected<void, std::string> check_shape(const ToolShape& t);

// The part of check_shape for the words above the end (tool_reach.cpp).
tl::expected<void, std::string> check_reach(const ToolShape& t);

// Reads the words above the end from `text` (words apart by spaces or
// commas): "flutes:L", "holder:D", "stickout:L", "no-plunge", "no-plunge:A"
// (degrees; default 5). `strict` (a --tool-shape value): any other word is
// an error; otherwise (a tool table comment) other words are prose and
// skipped. A known word with a bad value is an error either way. The shape's
// other values are not checked here (check_shape does).
tl::expected<void, std::string> read_reach_words(std::string_view text, bool strict, ToolShape& t);

// A tool table line's tool: the shape its comment names (shape_from_comment)
// and the words above its end anywhere in the comment, checked.
tl::expected<ToolShape, std::string> tool_from_comment(std::string_view comment, double diameter);

std::string shape_name(const ToolShape& t);

// One value of `usina simulate --tool-shape`, "T=SHAPE[/D][,WORD]...", e.g.
// "1=flat/6,flutes:20,holder:32,stickout:30": the tool's number (0..99999)
// and its shape. Without /D the diameter is the one `known` (the tool
// table's tools) gives tool T, and the words above the end not written are
// the table's. An error says what is wrong.
tl::expected<std::pair<int, ToolShape>, std::string> parse_tool_spec(
    std::string_view spec, const std::map<int, ToolShape>& known);

}  // namespace usina::sim::stock
