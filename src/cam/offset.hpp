// Offsets of contours by a distance (a tool radius), through Clipper 1.
//
// Clipper works on integer coordinates: usina scales millimetres by 1e4, a
// step of 0.1 µm, ten times finer than the 1 µm a control resolves, while
// ±107 m stays inside Clipper's fast 64-bit range (±2^30 units), so no part
// a machine holds needs its slower 128-bit arithmetic.
//
// Offset contours are polylines: arcs are cut into chords within the
// tolerance first, and the round corners Clipper adds are chords too.
#pragma once

#include <optional>
#include <vector>

#include "cam/path.hpp"

namespace usina::cam {

inline constexpr double kClipperScale = 1e4;  // Clipper units per mm (see above)

// A closed polygon, its last point joined to its first (not repeated).
// Outer boundaries run counter-clockwise, holes clockwise.
using Ring = std::vector<Vec2>;

// The rings offset by `delta` mm: outward from outer boundaries (and into
// holes) for delta > 0, inward for delta < 0, round corners within
// `tolerance`. What vanishes is left out; a ring may split in several.
std::vector<Ring> offset_rings(const std::vector<Ring>& rings, double delta, double tolerance);

// The area of `subject` outside `clip` (both sets of rings, even-odd:
// outer boundaries and holes in either orientation).
std::vector<Ring> difference(const std::vector<Ring>& subject, const std::vector<Ring>& clip);

// A closed path's points as a ring with the given orientation.
Ring to_ring(const Path& p, double tolerance, bool ccw);

// A ring as a closed path of straight segments, walked from its point
// nearest `near`.
Path ring_to_path(const Ring& ring, Vec2 near);

// The tool-centre path of a closed contour with the tool on its `left` (or
// right) side, `radius` away, walked in the contour's own direction from
// near its start. Several paths when the offset splits the contour; none
// when the contour is too small for the tool on that side.
std::vector<Path> offset_closed(const Path& p, double radius, bool left, double tolerance);

// The same for an open contour: the side `radius` away, from near its start
// to near its end. Nullopt when nothing of that side is left.
std::optional<Path> offset_open(const Path& p, double radius, bool left, double tolerance);

// True when `p` is inside the ring (even-odd rule).
bool inside(const Ring& ring, Vec2 p);

}  // namespace usina::cam
