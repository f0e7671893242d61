// CIRCLE, PLANE and VECTOR definition forms (research/apt.md §4.4, §4.5).
#include <cmath>

#include "apt/forms.hpp"

namespace usina::apt::forms {
namespace {

tl::unexpected<GeomError> unknown() {
  return tl::make_unexpected(GeomError{});
}

GeomResult circle_at(std::optional<Vec2> c, double z, double r, const std::string& what) {
  if (!c) return tl::make_unexpected(no_solution(what));
  return make_circle(c->x, c->y, z, r);
}

GeomResult circle_three_points(Vec2 a, Vec2 b, Vec2 c, double z) {
  const double d = 2.0 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
  if (std::fabs(d) < 1e-10)
    return tl::make_unexpected(
        no_solution("CIRCLE/point,point,point: the points lie on one line (IBM error 1005)"));
  const double a2 = a.x * a.x + a.y * a.y;
  const double b2 = b.x * b.x + b.y * b.y;
  const double c2 = c.x * c.x + c.y * c.y;
  const double ux = (a2 * (b.y - c.y) + b2 * (c.y - a.y) + c2 * (a.y - b.y)) / d;
  const double uy = (a2 * (c.x - b.x) + b2 * (a.x - c.x) + c2 * (b.x - a.x)) / d;
  return make_circle(ux, uy, z, std::hypot(a.x - ux, a.y - uy));
}

// The line `l` moved by `r` to the side `sel` names; empty when it has none.
std::optional<Line2> offset_to(const Arg& l, std::string_view sel, double r) {
  const Line2 base = line2(l);
  const int s = side_sign(sel, {base.n.x, base.n.y, 0.0});
  if (s == 0) return std::nullopt;
  return Line2{base.n, base.d + s * r};
}

GeomResult circle_fillet(const std::vector<Arg>& a, double zsurf) {
  const double r = a[5].num;
  const auto l1 = offset_to(a[1], a[0].word, r);
  const auto l2 = offset_to(a[3], a[2].word, r);
  if (!l1 || !l2)
    return tl::make_unexpected(
        no_solution("CIRCLE: a line runs along the axis its selector names"));
  return circle_at(meet(*l1, *l2), zsurf, r,
                   "CIRCLE tangent to two lines: the lines are parallel (IBM error 1005)");
}

GeomResult circle_line_point(const std::vector<Arg>& a, double zsurf) {
  const double r = a[5].num;
  const Line2 l = line2(a[1]);
  std::vector<Vec2> found;
  for (int s : {1, -1}) {
    const auto pts = meet(Line2{l.n, l.d + s * r}, Circle2{xy(a[3]), r});
    found.insert(found.end(), pts.begin(), pts.end());
  }
  return circle_at(choose(a[2].word, found), zsurf, r,
                   "CIRCLE/TANTO,line,...,point,RADIUS: the point is farther than twice the "
                   "radius from the line (IBM error 1005)");
}

GeomResult circle_line_circle(const std::vector<Arg>& a, double zsurf) {
  const double r = a[6].num;
  const auto l = offset_to(a[1], a[0].word, r);
  const Circle2 c = circle2(a[4]);
  const double rr = a[3].word == "IN" ? c.r - r : c.r + r;
  if (!l || rr <= 0.0)
    return tl::make_unexpected(
        no_solution("CIRCLE tangent to a line and a circle: no such circle"));
  return circle_at(choose(a[2].word, meet(*l, Circle2{c.c, rr})), zsurf, r,
                   "CIRCLE tangent to a line and a circle: they are too far apart for radius " +
                       std::to_string(r) + " (IBM error 1005)");
}

GeomResult circle_two_circles(const std::vector<Arg>& a, double zsurf) {
  const double r = a[6].num;
  const Circle2 c1 = circle2(a[2]);
  const Circle2 c2 = circle2(a[4]);
  const double r1 = a[1].word == "IN" ? c1.r - r : c1.r + r;
  const double r2 = a[3].word == "IN" ? c2.r - r : c2.r + r;
  if (r1 <= 0.0 || r2 <= 0.0)
    return tl::make_unexpected(no_solution(
        "CIRCLE tangent IN a circle: the radius is larger than that circle's (IBM error 1005)"));
  return circle_at(choose(a[0].word, meet(Circle2{c1.c, r1}, Circle2{c2.c, r2})), zsurf, r,
                   "CIRCLE tangent to two circles: no such circle (IBM error 1005)");
}

GeomResult circle_center_forms(const std::vector<Arg>& a) {
  const Vec2 c = xy(a[1]);
  const double z = a[1].geom.c[2];
  if (match(a, {"CENTER", "p", "RADIUS", "n"})) return make_circle(c.x, c.y, z, a[3].num);
  if (match(a, {"CENTER", "p", "TANTO", "l"})) {
    const Line2 l = line2(a[3]);
    return make_circle(c.x, c.y, z, std::fabs(l.n.x * c.x + l.n.y * c.y - l.d));
  }
  if (match(a, {"CENTER", "p", "p"}))
    return make_circle(c.x, c.y, z, std::hypot(a[2].geom.c[0] - c.x, a[2].geom.c[1] - c.y));
  if (match(a, {"CENTER", "p", "ls", "TANTO", "c"})) {
    const Circle2 o = circle2(a[4]);
    const double dist = std::hypot(o.c.x - c.x, o.c.y - c.y);
    const double r = a[2].word == "LARGE" ? dist + o.r : std::fabs(dist - o.r);
    return make_circle(c.x, c.y, z, r);
  }
  return unknown();
}

}  // namespace

GeomResult circle_form(const std::vector<Arg>& a, double zsurf) {
  GeomResult r = unknown();
  if (match(a, {"n", "n", "n"})) r = make_circle(a[0].num, a[1].num, zsurf, a[2].num);
  if (match(a, {"n", "n", "n", "n"})) r = make_circle(a[0].num, a[1].num, a[2].num, a[3].num);
  if (!a.empty() && a[0].word == "CENTER" && a.size() > 1) r = circle_center_forms(a);
  if (match(a, {"p", "p", "p"})) r = circle_three_points(xy(a[0]), xy(a[1]), xy(a[2]), zsurf);
  if (match(a, {"sel", "l", "sel", "l", "RADIUS", "n"})) r = circle_fillet(a, zsurf);
  if (match(a, {"TANTO", "l", "sel", "p", "RADIUS", "n"})) r = circle_line_point(a, zsurf);
  if (match(a, {"sel", "l", "sel", "io", "c", "RADIUS", "n"})) r = circle_line_circle(a, zsurf);
  if (match(a, {"sel", "io", "c", "io", "c", "RADIUS", "n"})) r = circle_two_circles(a, zsurf);
  if (r && !(r->c[6] > 0.0))
    return tl::make_unexpected(no_solution("CIRCLE: the radius is " + std::to_string(r->c[6]) +
                                           "; a circle needs a radius above 0"));
  return r;
}

namespace {

GeomResult make_plane(core::Vec3 n, double d) {
  const double len = std::sqrt(core::dot(n, n));
  if (len < 1e-12)
    return tl::make_unexpected(no_solution("PLANE: the normal is zero, no plane (IBM error 1005)"));
  Geom g{GeomType::Plane, {}, {}};
  g.c[0] = n.x / len;
  g.c[1] = n.y / len;
  g.c[2] = n.z / len;
  g.c[3] = d / len;
  return g;
}

core::Vec3 normal_of(const Arg& a) {
  return {a.geom.c[0], a.geom.c[1], a.geom.c[2]};
}

}  // namespace

GeomResult plane_form(const std::vector<Arg>& a) {
  if (match(a, {"n", "n", "n", "n"})) return make_plane({a[0].num, a[1].num, a[2].num}, a[3].num);
  if (match(a, {"p", "p", "p"})) {
    const core::Vec3 n = core::cross(xyz(a[1]) - xyz(a[0]), xyz(a[2]) - xyz(a[0]));
    return make_plane(n, core::dot(n, xyz(a[0])));
  }
  if (match(a, {"p", "PARLEL", "pl"}))
    return make_plane(normal_of(a[2]), core::dot(normal_of(a[2]), xyz(a[0])));
  if (match(a, {"p", "PERPTO", "v"}))
    return make_plane(normal_of(a[2]), core::dot(normal_of(a[2]), xyz(a[0])));
  if (match(a, {"PARLEL", "pl", "sel", "n"})) {
    const int s = side_sign(a[2].word, normal_of(a[1]));
    if (s == 0)
      return tl::make_unexpected(no_solution("PLANE/PARLEL: the plane has no " + a[2].word +
                                             " side (its normal is across that axis)"));
    return make_plane(normal_of(a[1]) * s, s * a[1].geom.c[3] + a[3].num);
  }
  return unknown();
}

GeomResult vector_form(const std::vector<Arg>& a) {
  Geom g{GeomType::Vector, {}, {}};
  if (match(a, {"n", "n", "n"})) {
    g.c[0] = a[0].num;
    g.c[1] = a[1].num;
    g.c[2] = a[2].num;
    return g;
  }
  if (match(a, {"p", "p"})) {
    const core::Vec3 v = xyz(a[1]) - xyz(a[0]);
    g.c[0] = v.x;
    g.c[1] = v.y;
    g.c[2] = v.z;
    return g;
  }
  return unknown();
}

}  // namespace usina::apt::forms
