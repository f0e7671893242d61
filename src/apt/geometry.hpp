// APT geometry in IBM's canonical forms (research/apt.md §4): a point
// (x,y,z), a line (a,b,0,d) with a·x+b·y = d and (a,b) a unit normal (a
// vertical plane), a plane (a,b,c,d), a circle (xc,yc,zc,0,0,1,r) (a
// vertical cylinder), a vector (i,j,k); a pattern (PATERN) is its points.
#pragma once

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <tl/expected.hpp>

#include "core/diagnostic.hpp"
#include "core/vec3.hpp"

namespace usina::apt {

enum class GeomType : unsigned char { Point, Line, Circle, Plane, Vector, Pattern };

std::string_view type_name(GeomType t);  // "POINT", ...
std::size_t canon_size(GeomType t);      // 3, 4, 7, 4, 3; 0 for a pattern (its points)

// A pattern's points, shared: a pattern of 100,000 points passes from its
// symbol to each statement that names it without being copied.
class PointList {
 public:
  PointList() = default;

  explicit PointList(std::vector<core::Vec3> p)
      : p_(std::make_shared<const std::vector<core::Vec3>>(std::move(p))) {}

  const std::vector<core::Vec3>& all() const {
    static const std::vector<core::Vec3> none;
    return p_ ? *p_ : none;
  }

  std::size_t size() const { return all().size(); }

  const core::Vec3& operator[](std::size_t i) const { return all()[i]; }

  const core::Vec3& front() const { return all().front(); }

  auto begin() const { return all().begin(); }

  auto end() const { return all().end(); }

 private:
  std::shared_ptr<const std::vector<core::Vec3>> p_;
};

struct Geom {
  GeomType type = GeomType::Point;
  std::array<double, 7> c{};
  PointList points;  // a pattern's points, in its order
};

// The numbers `--canonical` prints: the canonical form, or a pattern's
// points x1,y1,z1, x2,y2,z2, ...
std::vector<double> canonical(const Geom& g);

// An argument of a statement after the slash, evaluated.
struct Arg {
  enum class Kind : unsigned char { Number, Word, Geom };
  Kind kind = Kind::Number;
  double num = 0.0;
  std::string word;  // a minor word, upper case
  Geom geom;
  std::string name;  // the symbol a geometry argument was named by, if any
  core::SourceLoc loc;
};

// Why a definition failed: E_APT_UNKNOWN_FORM (no form matches, IBM error
// 1000) or E_APT_NO_SOLUTION (the form has no solution, IBM error 1005).
struct GeomError {
  core::Code code = core::Code::AptUnknownForm;
  std::string message;
};

using GeomResult = tl::expected<Geom, GeomError>;

// The definition `major/args` (POINT, LINE, CIRCLE, PLANE, VECTOR, PATERN); `zsurf`
// is the z of points given by two coordinates.
// `pattern_budget`: the points PATERN definitions may still make and read
// (none without it).
GeomResult define(std::string_view major, const std::vector<Arg>& args, double zsurf,
                  std::size_t* pattern_budget = nullptr);

Geom make_point(double x, double y, double z);
Geom make_line(double a, double b, double d);  // normalises (a,b)
Geom make_circle(double xc, double yc, double zc, double r);

}  // namespace usina::apt
