// The plane computations the definition forms share: intersections of
// lines and circles in XY, choices by XLARGE/YSMALL selectors.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "core/vec3.hpp"

namespace usina::apt {

using core::Vec2;

struct Line2 {
  Vec2 n;  // unit normal
  double d = 0.0;
};

struct Circle2 {
  Vec2 c;
  double r = 0.0;
};

// The meeting point of two lines; empty when they are parallel.
std::optional<Vec2> meet(const Line2& a, const Line2& b);

// The points of a line on a circle (0, 1 or 2).
std::vector<Vec2> meet(const Line2& l, const Circle2& c);

// The points two circles share (0, 1 or 2; none for concentric circles).
std::vector<Vec2> meet(const Circle2& a, const Circle2& b);

// Whether `w` is XLARGE, XSMALL, YLARGE, YSMALL, ZLARGE or ZSMALL.
bool is_selector(std::string_view w);

// The candidate with the largest or smallest x or y as `sel` says.
std::optional<Vec2> choose(std::string_view sel, const std::vector<Vec2>& candidates);

// +1 or -1: the sign that makes `normal` point to the side `sel` names
// (XLARGE: +x); 0 when the normal has no component along that axis.
int side_sign(std::string_view sel, const core::Vec3& normal);

}  // namespace usina::apt
