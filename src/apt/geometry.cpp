#include "apt/geometry.hpp"

#include <cmath>

namespace usina::apt {

std::string_view type_name(GeomType t) {
  switch (t) {
  case GeomType::Point: return "POINT";
  case GeomType::Line: return "LINE";
  case GeomType::Circle: return "CIRCLE";
  case GeomType::Plane: return "PLANE";
  case GeomType::Vector: return "VECTOR";
  case GeomType::Pattern: return "PATERN";
  }
  return "?";
}

std::size_t canon_size(GeomType t) {
  switch (t) {
  case GeomType::Point:
  case GeomType::Vector: return 3;
  case GeomType::Line:
  case GeomType::Plane: return 4;
  case GeomType::Circle: return 7;
  case GeomType::Pattern: return 0;
  }
  return 0;
}

std::vector<double> canonical(const Geom& g) {
  if (g.type != GeomType::Pattern) return {g.c.begin(), g.c.begin() + canon_size(g.type)};
  std::vector<double> out;
  out.reserve(g.points.size() * 3);
  for (const core::Vec3& p : g.points) {
    out.push_back(p.x);
    out.push_back(p.y);
    out.push_back(p.z);
  }
  return out;
}

Geom make_point(double x, double y, double z) {
  Geom g{GeomType::Point, {}, {}};
  g.c[0] = x;
  g.c[1] = y;
  g.c[2] = z;
  return g;
}

Geom make_line(double a, double b, double d) {
  const double n = std::hypot(a, b);
  Geom g{GeomType::Line, {}, {}};
  g.c[0] = a / n;
  g.c[1] = b / n;
  g.c[3] = d / n;
  return g;
}

Geom make_circle(double xc, double yc, double zc, double r) {
  Geom g{GeomType::Circle, {}, {}};
  g.c = {xc, yc, zc, 0.0, 0.0, 1.0, r};
  return g;
}

}  // namespace usina::apt
