// A 2-D path in the XY plane: a start point and straight segments or circular
// arcs, as a drawing has them (DXF entities, chained contours, offsets). Arcs
// stay arcs until something (an offset by Clipper) needs a polyline.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "canon/op.hpp"
#include "core/vec3.hpp"

namespace usina::cam {

using core::Vec2;

// A straight segment (no centre) or an arc about `center`; turn +1 is
// counter-clockwise seen from +Z, −1 clockwise. An arc that ends where it
// starts is a full circle.
struct PathSegment {
  Vec2 to;
  std::optional<Vec2> center;
  int turn = 0;
};

struct Path {
  Vec2 start;
  std::vector<PathSegment> segs;
  bool closed = false;
};

// Where the path ends (its start when it has no segments).
Vec2 end_point(const Path& p);

// The same path walked the other way (arcs change their turn).
Path reversed(const Path& p);

// Start point of segment i (the previous segment's end).
Vec2 segment_start(const Path& p, std::size_t i);

// Signed sweep of an arc segment from `from` (radians, positive CCW).
double segment_sweep(Vec2 from, const PathSegment& s);

// Length of one segment starting at `from`, and of the whole path.
double segment_length(Vec2 from, const PathSegment& s);
double path_length(const Path& p);

// Points of the path from its start (included) to its end (included), arcs
// split into chords within `tolerance` of the arc.
std::vector<Vec2> linearize(const Path& p, double tolerance);

// How many points linearize() would make, without making them.
double linearized_points(const Path& p, double tolerance);

// The arc of a DXF polyline vertex's bulge (tan of a quarter of the included
// angle, positive counter-clockwise; DXF reference, LWPOLYLINE group 42) from
// `from` to `to`. A zero bulge is a straight segment.
PathSegment bulge_segment(Vec2 from, Vec2 to, double bulge);

// Twice the signed area of a closed polygon (positive counter-clockwise).
double signed_area2(const std::vector<Vec2>& ring);

// The path as a canon outline (for a Pocket feature).
canon::Outline to_outline(const Path& p);

}  // namespace usina::cam
