// What the definition forms share: matching the arguments against a form's
// pattern and reading them (internal to the apt module).
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "apt/geometry.hpp"
#include "apt/plane_geometry.hpp"

namespace usina::apt::forms {

// Pattern items: "n" a number, "p" point, "l" line, "c" circle, "pl" plane,
// "v" vector, "pat" pattern, "sel" XLARGE..ZSMALL, "side" LEFT|RIGHT, "io" IN|OUT, "ls"
// LARGE|SMALL, "ax" XAXIS|YAXIS; an upper-case item is that minor word.
bool match(const std::vector<Arg>& args, std::initializer_list<std::string_view> pattern);

inline Vec2 xy(const Arg& a) {
  return {a.geom.c[0], a.geom.c[1]};
}

inline core::Vec3 xyz(const Arg& a) {
  return {a.geom.c[0], a.geom.c[1], a.geom.c[2]};
}

inline Line2 line2(const Arg& a) {
  return {{a.geom.c[0], a.geom.c[1]}, a.geom.c[3]};
}

inline Circle2 circle2(const Arg& a) {
  return {{a.geom.c[0], a.geom.c[1]}, a.geom.c[6]};
}

GeomError no_solution(std::string message);
GeomError not_built(std::string_view form);

GeomResult point_form(const std::vector<Arg>& a, double zsurf);
GeomResult line_form(const std::vector<Arg>& a);
GeomResult circle_form(const std::vector<Arg>& a, double zsurf);
GeomResult plane_form(const std::vector<Arg>& a);
GeomResult vector_form(const std::vector<Arg>& a);
// patern.cpp; `budget`: the points the program's patterns may still make
// and read (each definition takes its share, failing or not).
GeomResult pattern_form(const std::vector<Arg>& a, std::size_t& budget);
GeomResult pattern_point(const Arg& pattern, double n);  // POINT/pattern,n

// "POINT, LEFT, 3": the kinds of the arguments, for a message.
std::string describe(const std::vector<Arg>& args);

}  // namespace usina::apt::forms
