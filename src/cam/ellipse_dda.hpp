// The ellipse by a DDA circular interpolator (seed 002, section 3.1): the
// first quadrant of the circle of radius Ry by the integrators' accumulators
// qx, px, qy, py, X scaled by Rx/Ry (equation 1), then mirrored into the
// fourth (equation 2) and the third and second quadrants (equation 3).
// No sine or cosine: each point is one step of the interpolator.
#pragma once

#include <vector>

#include "core/vec3.hpp"

namespace usina::cam {

using core::Vec2;

// The circle increment for radii rx, ry and a resolution: the resolution,
// shrunk so that it divides ry (the quadrant ends exactly on the X axis)
// and, when rx > ry, by ry/rx (equation 1 would stretch the X steps beyond it).
double dda_increment(double rx, double ry, double resolution);

// The first quadrant, relative to the centre, as the interpolator steps it:
// from (0, ry) clockwise to (rx, 0), both included; one point for each
// clock in which X, Y or both stepped. Needs rx, ry, resolution > 0.
std::vector<Vec2> dda_quadrant(double rx, double ry, double resolution);

// The whole ellipse, relative to the centre, counter-clockwise from (0, ry)
// through (−rx, 0), (0, −ry), (rx, 0) and back to (0, ry) (closed: the first
// point is repeated at the end), as the seed orders its point list.
std::vector<Vec2> dda_ellipse(double rx, double ry, double resolution);

}  // namespace usina::cam
