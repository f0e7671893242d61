// A DXF SPLINE (a NURBS: degree, knots, weighted control points) as points
// within a tolerance of the curve.
#pragma once

#include <string>
#include <vector>

#include "core/vec3.hpp"

namespace usina::cam {

struct WeightedPoint {
  core::Vec2 p;
  double w = 1.0;
};

// Points from the curve's start to its end, both included; empty with
// `error` set when the data do not make a spline (knot count, order, weights).
std::vector<core::Vec2> approximate_spline(int degree, const std::vector<WeightedPoint>& control,
                                           const std::vector<double>& knots, double tolerance,
                                           std::string& error);

}  // namespace usina::cam
