// Spline geometry of LinuxCNC's G5 (cubic), G5.1 (quadratic) and G5.2/G5.3
// (NURBS) moves in the XY plane, and their linearisation to a chordal tolerance.
//
// LinuxCNC itself feeds every one of them as a NURBS (interp_convert.cc,
// convert_spline: G5 is order 4 with four unit-weight points, G5.1 order 3 with
// three), so the Béziers here are the same curves as those NURBS.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <tl/expected.hpp>

#include "core/vec3.hpp"

namespace usina::core {

struct CubicBezier {
  Vec2 p0;  // start
  Vec2 p1;
  Vec2 p2;
  Vec2 p3;  // end
};

struct QuadBezier {
  Vec2 p0;  // start
  Vec2 p1;
  Vec2 p2;  // end
};

// A non-uniform rational B-spline; build it with make_nurbs so the knots are
// LinuxCNC's. `order` = degree + 1 (LinuxCNC's L); points.size() ==
// weights.size() >= order; knots.size() == points.size() + order.
struct Nurbs {
  int order = 0;
  std::vector<Vec2> points;
  std::vector<double> weights;
  std::vector<double> knots;
};

// --- G-code words to curves ------------------------------------------------

// LinuxCNC docs, G5: I J = offset from the start to the first control point,
// P Q = offset from the END point to the second control point.
CubicBezier cubic_from_g5(Vec2 start, Vec2 end, Vec2 ij, Vec2 pq);

// LinuxCNC docs, G5: on a G5 after a G5, omitted I J continue the previous
// curve's end direction, "as if I and J are the negation of the previous P and
// Q" (interp_convert.cc keeps -P, -Q for it). Returns that I J.
Vec2 g5_continuation_ij(const CubicBezier& previous);

// LinuxCNC docs, G5.1: I J = offset from the start to the single control point.
QuadBezier quad_from_g5_1(Vec2 start, Vec2 end, Vec2 ij);

// --- Evaluation -------------------------------------------------------------
// point(c, t) is the curve at parameter t; tangent(c, t) is its derivative
// dC/dt (not normalised; zero where the control points next to an end
// coincide). Béziers run over t in [0, 1], a Nurbs over domain(nurbs).

Vec2 point(const CubicBezier& c, double t);
Vec2 tangent(const CubicBezier& c, double t);
Vec2 point(const QuadBezier& c, double t);
Vec2 tangent(const QuadBezier& c, double t);

// Knots as LinuxCNC makes them (nurbs_additional_functions.cc,
// knot_vector_creator): `order` zeros, then 1, 2, ... one per further point,
// then `order` copies of count - order + 1. Clamped, so the curve starts at the
// first point and ends at the last. Requires count >= order >= 1.
std::vector<double> linuxcnc_knots(int order, std::size_t count);

// The Nurbs of a G5.2 ... G5.3 block; `points` includes the start point (the
// current position, LinuxCNC docs G5.2). Throws std::invalid_argument when
// check_nurbs() would report a problem: check first, this is for valid input.
Nurbs make_nurbs(int order, std::vector<Vec2> points, std::vector<double> weights);

// Parameter range {first, last} over which the curve is defined.
std::pair<double, double> domain(const Nurbs& c);

// u is clamped to domain(c).
Vec2 point(const Nurbs& c, double u);
Vec2 tangent(const Nurbs& c, double u);

// --- Linearisation ----------------------------------------------------------
// Points from the curve's start (excluded) to its end (included, exactly the
// last control point). Every chord is within `tolerance` of the curve and the
// curve within `tolerance` of its chord: each piece is halved until its control
// points lie within `tolerance` of the chord, which bounds the curve (convex
// hull property, positive weights). So the count follows curvature: a straight
// Bézier is one segment. A tolerance below 1e-9 of the control points' extent
// (or not a number) is raised to it, and halving stops at kSplineMaxDepth
// levels, so the output stays finite whatever the input.
inline constexpr int kSplineMaxDepth = 32;
inline constexpr double kSplineRelativeToleranceFloor = 1e-9;

std::vector<Vec2> linearize(const CubicBezier& c, double tolerance);
std::vector<Vec2> linearize(const QuadBezier& c, double tolerance);
std::vector<Vec2> linearize(const Nurbs& c, double tolerance);

// --- Validation for diagnostics ---------------------------------------------
// Each passes when the input is good, otherwise its error is a message that
// says what is wrong, with the numbers, and what to do.
//
// Note for the interpreter: LinuxCNC itself takes L only when it is above 3
// and uses order 3 otherwise (interp_convert.cc, convert_nurbs), so L2 there
// is silently order 3; these helpers check the order actually used.

tl::expected<void, std::string> check_nurbs_order(int order);
tl::expected<void, std::string> check_nurbs_count(int order, std::size_t count);
// `index` is the control point's position in the block (0 = start point).
tl::expected<void, std::string> check_nurbs_weight(double weight, std::size_t index);
// All of the above plus matching sizes; the first problem found.
tl::expected<void, std::string> check_nurbs(int order, const std::vector<Vec2>& points,
                                            const std::vector<double>& weights);

}  // namespace usina::core
