// POINT and LINE definition forms (research/apt.md §4.2, §4.3).
#include <cmath>
#include <numbers>

#include "apt/forms.hpp"

namespace usina::apt::forms {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

tl::unexpected<GeomError> unknown() {
  return tl::make_unexpected(GeomError{});
}

GeomResult point_at(std::optional<Vec2> p, double z, const std::string& what) {
  if (!p) return tl::make_unexpected(no_solution(what));
  return make_point(p->x, p->y, z);
}

GeomResult point_intof(const std::vector<Arg>& a, double zsurf) {
  if (match(a, {"INTOF", "l", "l"}))
    return point_at(meet(line2(a[1]), line2(a[2])), zsurf,
                    "POINT/INTOF: the two lines are parallel, they do not meet (IBM error 1005)");
  if (match(a, {"INTOF", "pl", "pl", "pl"})) {
    const core::Vec3 n1{a[1].geom.c[0], a[1].geom.c[1], a[1].geom.c[2]};
    const core::Vec3 n2{a[2].geom.c[0], a[2].geom.c[1], a[2].geom.c[2]};
    const core::Vec3 n3{a[3].geom.c[0], a[3].geom.c[1], a[3].geom.c[2]};
    const double det = core::dot(n1, core::cross(n2, n3));
    if (std::fabs(det) < 1e-10)
      return tl::make_unexpected(no_solution("POINT/INTOF: the three planes meet in no one point"));
    const core::Vec3 p =
        (core::cross(n2, n3) * a[1].geom.c[3] + core::cross(n3, n1) * a[2].geom.c[3] +
         core::cross(n1, n2) * a[3].geom.c[3]) /
        det;
    return make_point(p.x, p.y, p.z);
  }
  const bool lc = match(a, {"sel", "INTOF", "l", "c"}) || match(a, {"sel", "INTOF", "c", "l"});
  if (lc) {
    const Arg& l = a[2].geom.type == GeomType::Line ? a[2] : a[3];
    const Arg& c = a[2].geom.type == GeomType::Circle ? a[2] : a[3];
    return point_at(
        choose(a[0].word, meet(line2(l), circle2(c))), zsurf,
        "POINT/" + a[0].word + ",INTOF: the line does not meet the circle (IBM error 1005)");
  }
  if (match(a, {"sel", "INTOF", "c", "c"}))
    return point_at(choose(a[0].word, meet(circle2(a[2]), circle2(a[3]))), zsurf,
                    "POINT/" + a[0].word + ",INTOF: the circles do not meet (IBM error 1005)");
  return unknown();
}

}  // namespace

GeomResult point_form(const std::vector<Arg>& a, double zsurf) {
  if (match(a, {"n", "n"})) return make_point(a[0].num, a[1].num, zsurf);
  if (match(a, {"n", "n", "n"})) return make_point(a[0].num, a[1].num, a[2].num);
  if (match(a, {"pat", "n"})) return pattern_point(a[0], a[1].num);
  if (!a.empty() && (a[0].word == "INTOF" || (a.size() > 1 && a[1].word == "INTOF")))
    return point_intof(a, zsurf);
  if (match(a, {"c", "ATANGL", "n"})) {
    const Circle2 c = circle2(a[0]);
    const double t = a[2].num * kDeg;
    return make_point(c.c.x + c.r * std::cos(t), c.c.y + c.r * std::sin(t), a[0].geom.c[2]);
  }
  if (match(a, {"CENTER", "c"})) return make_point(a[1].geom.c[0], a[1].geom.c[1], a[1].geom.c[2]);
  for (const char* plane : {"XYPLAN", "YZPLAN", "ZXPLAN"}) {
    const bool rt = match(a, {"RTHETA", plane, "n", "n"});
    if (!rt && !match(a, {"THETAR", plane, "n", "n"})) continue;
    const double r = rt ? a[2].num : a[3].num;
    const double t = (rt ? a[3].num : a[2].num) * kDeg;
    const double u = r * std::cos(t);
    const double v = r * std::sin(t);
    if (plane[0] == 'X') return make_point(u, v, zsurf);
    if (plane[0] == 'Y') return make_point(0.0, u, v);
    return make_point(v, 0.0, u);
  }
  return unknown();
}

namespace {

// The line through `p` at `deg` from +X, normal (-sin, cos) as IBM gives it.
Geom line_at_angle(Vec2 p, double deg) {
  const double t = deg * kDeg;
  const double a = -std::sin(t);
  const double b = std::cos(t);
  return make_line(a, b, a * p.x + b * p.y);
}

GeomResult line_two_points(Vec2 p, Vec2 q) {
  const double dx = q.x - p.x;
  const double dy = q.y - p.y;
  if (std::hypot(dx, dy) < 1e-10)
    return tl::make_unexpected(
        no_solution("LINE: the two points coincide (in XY), they define no line"));
  const double len = std::hypot(dx, dy);
  return make_line(dy / len, -dx / len, (dy * p.x - dx * p.y) / len);
}

// The angle of a line's direction in [0, 180) degrees.
double line_angle(const Arg& l) {
  double deg = std::atan2(-l.geom.c[0], l.geom.c[1]) / kDeg;
  while (deg < 0.0)
    deg += 180.0;
  while (deg >= 180.0)
    deg -= 180.0;
  return deg;
}

GeomResult line_by_angle(const std::vector<Arg>& a) {
  const bool slope = a[1].word == "SLOPE";
  double deg = slope ? std::atan(a[2].num) / kDeg : a[2].num;
  if (a.size() == 4 && a[3].kind == Arg::Kind::Geom) {
    deg += line_angle(a[3]);
  } else if (a.size() == 4 && a[3].word == "YAXIS") {
    deg += 90.0;
  }
  return line_at_angle(xy(a[0]), deg);
}

GeomResult line_tangent_from_point(const std::vector<Arg>& a) {
  const Vec2 p = xy(a[0]);
  const Circle2 c = circle2(a[3]);
  const double dist = std::hypot(c.c.x - p.x, c.c.y - p.y);
  if (dist <= c.r + 1e-10)
    return tl::make_unexpected(no_solution("LINE/point," + a[1].word +
                                           ",TANTO,circle: the point is on or inside the circle, "
                                           "no tangent goes through it (IBM error 1005)"));
  const double toward = std::atan2(c.c.y - p.y, c.c.x - p.x);
  const double off = std::asin(c.r / dist);
  const double t = a[1].word == "LEFT" ? toward + off : toward - off;
  // The normal points to the centre, as IBM's canonical form has it.
  double nx = std::sin(t);
  double ny = -std::cos(t);
  if (nx * (c.c.x - p.x) + ny * (c.c.y - p.y) < 0) {
    nx = -nx;
    ny = -ny;
  }
  return make_line(nx, ny, nx * p.x + ny * p.y);
}

GeomResult line_intercept(const std::vector<Arg>& a) {
  const bool slope = a[0].word == "SLOPE";
  const double deg = slope ? std::atan(a[1].num) / kDeg : a[1].num;
  const double b = a.back().num;
  const bool on_x = a.size() == 5 && a[3].word == "XAXIS";
  return line_at_angle(on_x ? Vec2{b, 0.0} : Vec2{0.0, b}, deg);
}

GeomResult line_parallel_at(const std::vector<Arg>& a) {
  const core::Vec3 n{a[1].geom.c[0], a[1].geom.c[1], 0.0};
  const int s = side_sign(a[2].word, n);
  if (s == 0)
    return tl::make_unexpected(no_solution("LINE/PARLEL: the line runs along the axis " +
                                           a[2].word + " names, it has no such side"));
  return make_line(s * n.x, s * n.y, s * a[1].geom.c[3] + a[3].num);
}

}  // namespace

GeomResult line_form(const std::vector<Arg>& a) {
  if (match(a, {"n", "n", "n", "n"}))
    return line_two_points({a[0].num, a[1].num}, {a[2].num, a[3].num});
  if (match(a, {"n", "n", "n", "n", "n", "n"}))
    return line_two_points({a[0].num, a[1].num}, {a[3].num, a[4].num});
  if (match(a, {"p", "p"})) return line_two_points(xy(a[0]), xy(a[1]));
  if (match(a, {"p", "side", "TANTO", "c"})) return line_tangent_from_point(a);
  for (const char* how : {"ATANGL", "SLOPE"}) {
    if (match(a, {"p", how, "n"}) || match(a, {"p", how, "n", "ax"}) ||
        match(a, {"p", how, "n", "l"}))
      return line_by_angle(a);
    if (match(a, {how, "n", "INTERC", "n"}) || match(a, {how, "n", "INTERC", "ax", "n"}))
      return line_intercept(a);
  }
  if (match(a, {"p", "PARLEL", "l"})) {
    const Vec2 p = xy(a[0]);
    return make_line(a[2].geom.c[0], a[2].geom.c[1], a[2].geom.c[0] * p.x + a[2].geom.c[1] * p.y);
  }
  if (match(a, {"p", "PERPTO", "l"})) {
    const Vec2 p = xy(a[0]);
    const double nx = -a[2].geom.c[1];
    const double ny = a[2].geom.c[0];
    return make_line(nx, ny, nx * p.x + ny * p.y);
  }
  if (match(a, {"PARLEL", "l", "sel", "n"})) return line_parallel_at(a);
  if (match(a, {"XAXIS"})) return make_line(0.0, 1.0, 0.0);
  if (match(a, {"YAXIS"})) return make_line(1.0, 0.0, 0.0);
  if (match(a, {"side", "TANTO", "c", "side", "TANTO", "c"}))
    return tl::make_unexpected(not_built("LINE/side,TANTO,circle,side,TANTO,circle"));
  if (match(a, {"INTOF", "pl", "pl"}))
    return tl::make_unexpected(not_built("LINE/INTOF,plane,plane"));
  return unknown();
}

}  // namespace usina::apt::forms
