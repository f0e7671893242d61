// What the job reads off the drawing to choose and drive its tools: the
// holes of a drill layer (its circles, by diameter) and the smallest inside
// corner of a contour (no end mill larger than twice it cuts the corner).
#pragma once

#include <cstddef>
#include <vector>

#include "cam/path.hpp"

namespace usina::cam {
struct PocketShape;  // cam/pocket.hpp
}  // namespace usina::cam

namespace usina::job {

struct HoleGroup {
  double diameter = 0;
  std::vector<cam::Vec2> centers;  // in drawing order
};

// The full circles of `paths`, grouped by diameter (within 0.001 mm),
// smallest first; `others` counts the paths that are not circles.
std::vector<HoleGroup> holes_of(const std::vector<cam::Path>& paths, std::size_t& others);

// The smallest radius of the corners a tool meets going around the closed
// `contour` on the side `tool_inside` (inside the region it bounds, or
// outside it): arcs bending around the tool, and 0 for a sharp corner that
// turns that way. Infinity when there is none (a convex outline cut
// outside).
double smallest_inside_radius(const cam::Path& contour, bool tool_inside);
// The smallest corner a pocket's tool meets: the outline's inside corners,
// and each island's, which the tool goes round from outside (an island's
// re-entrant corners bound the tool; its outer corners do not).
double pocket_corner(const cam::PocketShape& shape);

// The smallest radius of curvature of an ellipse of semi-axes rx, ry: b²/a
// at the ends of its major axis.
double ellipse_smallest_radius(double rx, double ry);

}  // namespace usina::job
