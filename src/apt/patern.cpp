// PATERN definition forms and POINT/pattern,n (docs/apt.md, "Patterns"). Counts are whole numbers;
// increments (INCR) are distances along a vector or angles on a circle between one point and the
// next.
#include "apt/patern.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <utility>

#include "apt/forms.hpp"

namespace usina::apt {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

using Points = std::vector<core::Vec3>;
using PointsResult = tl::expected<Points, GeomError>;

tl::unexpected<GeomError> bad(std::string message) {
  return tl::make_unexpected(GeomError{core::Code::AptBadArgument, std::move(message)});
}

tl::unexpected<GeomError> unknown() {
  return tl::make_unexpected(GeomError{});
}

bool is_word(const Arg& a, std::string_view w) {
  return a.kind == Arg::Kind::Word && a.word == w;
}

bool whole(double n, double least) {
  return n >= least && n <= static_cast<double>(kMaxPatternPoints) && n == std::floor(n);
}

// The points a program's PATERN definitions may still make or read (its
// patterns' bound, kMostProgramPatternPoints): every step takes its share
// before it is done, so the work stays bounded even by definitions that fail.
class Budget {
 public:
  explicit Budget(std::size_t left) : left_(left) {}

  bool take(std::size_t n) {
    if (n > left_) {
      left_ = 0;
      return false;
    }
    left_ -= n;
    return true;
  }

  std::size_t left() const { return left_; }

 private:
  std::size_t left_;
};

tl::unexpected<GeomError> spent() {
  return bad("PATERN: the program's patterns make and read more than " +
             std::to_string(kMostProgramPatternPoints) + " points");
}

GeomResult pattern_of(Points points) {
  if (points.size() > kMaxPatternPoints)
    return bad("PATERN: more than " + std::to_string(kMaxPatternPoints) + " points");
  Geom g;
  g.type = GeomType::Pattern;
  g.points = PointList(std::move(points));
  return g;
}

// INCR,d1,d2,... and INCR,n,AT,d (n steps of d), in groups, from a[i] (INCR)
// to the end.
tl::expected<std::vector<double>, GeomError> increments(const std::vector<Arg>& a, std::size_t i,
                                                        Budget& b) {
  std::vector<double> out;
  while (i < a.size()) {
    if (is_word(a[i], "INCR")) {
      if (++i == a.size() || a[i].kind != Arg::Kind::Number)
        return bad("PATERN: INCR takes increments d1,d2,... or n,AT,d");
      continue;
    }
    if (a[i].kind != Arg::Kind::Number) return unknown();
    if (i + 1 < a.size() && is_word(a[i + 1], "AT")) {
      if (i + 2 == a.size() || a[i + 2].kind != Arg::Kind::Number)
        return bad("PATERN: n,AT,d takes the increment d after AT");
      if (!whole(a[i].num, 1) ||
          out.size() + static_cast<std::size_t>(a[i].num) > kMaxPatternPoints)
        return bad("PATERN: the count before AT is a whole number from 1 to " +
                   std::to_string(kMaxPatternPoints) + " in all");
      if (!b.take(static_cast<std::size_t>(a[i].num))) return spent();
      out.insert(out.end(), static_cast<std::size_t>(a[i].num), a[i + 2].num);
      i += 3;
      continue;
    }
    if (out.size() == kMaxPatternPoints)
      return bad("PATERN: more than " + std::to_string(kMaxPatternPoints) + " increments");
    if (!b.take(1)) return spent();
    out.push_back(a[i++].num);
  }
  return out;
}

// Unit direction of a vector argument, or an error.
tl::expected<core::Vec3, GeomError> unit(const Arg& v) {
  const core::Vec3 d = forms::xyz(v);
  const double n = std::sqrt(core::dot(d, d));
  if (!(n > 1e-12)) return bad("PATERN: the vector has no length, so no direction");
  return d / n;
}

// `WORD,first,vector,INCR,...` (LINEAR from a point, PARLEL of a pattern):
// the points from the first argument (`from_point`) or the origin along the
// vector's direction by each increment in turn, that start first; unknown()
// when the statement is not of that form.
PointsResult stepped(const std::vector<Arg>& a, std::string_view word, std::string_view first,
                     bool from_point, Budget& b) {
  const bool incr = a.size() > 4 && forms::match({a.begin(), a.begin() + 3}, {word, first, "v"}) &&
                    is_word(a[3], "INCR");
  if (!incr) return unknown();
  const auto u = unit(a[2]);
  if (!u) return tl::make_unexpected(u.error());
  const auto steps = increments(a, 3, b);
  if (!steps) return tl::make_unexpected(steps.error());
  Points out{from_point ? forms::xyz(a[1]) : core::Vec3{}};
  for (double d : *steps)
    out.push_back(out.back() + *u * d);
  return out;
}

PointsResult linear(const std::vector<Arg>& a, Budget& b) {
  if (forms::match(a, {"LINEAR", "p", "p", "n"})) {
    if (!whole(a[3].num, 2)) return bad("PATERN/LINEAR,point,point,n: n is whole, 2 or more");
    const auto n = static_cast<std::size_t>(a[3].num);
    if (!b.take(n)) return spent();
    const core::Vec3 p = forms::xyz(a[1]), q = forms::xyz(a[2]);
    Points out;
    for (std::size_t k = 0; k < n; ++k)
      out.push_back(p + (q - p) * (static_cast<double>(k) / static_cast<double>(n - 1)));
    return out;
  }
  if (forms::match(a, {"LINEAR", "p", "v", "n"})) {
    if (!whole(a[3].num, 1)) return bad("PATERN/LINEAR,point,vector,n: n is whole, 1 or more");
    if (!b.take(static_cast<std::size_t>(a[3].num))) return spent();
    Points out;
    for (std::size_t k = 0; k < static_cast<std::size_t>(a[3].num); ++k)
      out.push_back(forms::xyz(a[1]) + forms::xyz(a[2]) * static_cast<double>(k));
    return out;
  }
  return stepped(a, "LINEAR", "p", true, b);
}

// Angles in degrees from +X, counter-clockwise; CLW turns the other way.
PointsResult on_circle(const Arg& c, const std::vector<double>& angles) {
  Points out;
  for (double t : angles)
    out.push_back({c.geom.c[0] + c.geom.c[6] * std::cos(t * kDeg),
                   c.geom.c[1] + c.geom.c[6] * std::sin(t * kDeg), c.geom.c[2]});
  return out;
}

PointsResult arc(const std::vector<Arg>& a, Budget& b) {
  const bool ends = forms::match(a, {"ARC", "c", "n", "n", "CLW", "n"}) ||
                    forms::match(a, {"ARC", "c", "n", "n", "CCLW", "n"});
  if (ends) {
    const double sense = a[4].word == "CLW" ? -1.0 : 1.0;
    double sweep = std::fmod(sense * (a[3].num - a[2].num), 360.0);
    if (sweep <= 1e-9) sweep += 360.0;
    const bool round = sweep > 360.0 - 1e-9;  // the whole circle: the last point is not the first
    if (!whole(a[5].num, round ? 1 : 2))
      return bad(
          "PATERN/ARC,circle,a1,a2,CLW|CCLW,n: n is whole, 2 or more (1 or more around "
          "the whole circle)");
    const auto n = static_cast<std::size_t>(a[5].num);
    if (!b.take(n)) return spent();
    const double step = sweep / static_cast<double>(round ? n : n - 1);
    std::vector<double> angles;
    for (std::size_t k = 0; k < n; ++k)
      angles.push_back(a[2].num + sense * step * static_cast<double>(k));
    return on_circle(a[1], angles);
  }
  const bool incr = a.size() > 5 &&
                    (forms::match({a.begin(), a.begin() + 4}, {"ARC", "c", "n", "CLW"}) ||
                     forms::match({a.begin(), a.begin() + 4}, {"ARC", "c", "n", "CCLW"})) &&
                    is_word(a[4], "INCR");
  if (!incr) return unknown();
  const auto steps = increments(a, 4, b);
  if (!steps) return tl::make_unexpected(steps.error());
  const double sense = a[3].word == "CLW" ? -1.0 : 1.0;
  std::vector<double> angles{a[2].num};
  for (double d : *steps)
    angles.push_back(angles.back() + sense * d);
  return on_circle(a[1], angles);
}

PointsResult random(const std::vector<Arg>& a, Budget& b) {
  if (a.size() < 2) return unknown();
  Points out;
  for (std::size_t i = 1; i < a.size(); ++i) {
    const bool point = a[i].kind == Arg::Kind::Geom && a[i].geom.type == GeomType::Point;
    const bool pattern = a[i].kind == Arg::Kind::Geom && a[i].geom.type == GeomType::Pattern;
    if (!point && !pattern) return unknown();
    if (!b.take(pattern ? a[i].geom.points.size() : 1)) return spent();
    if (point) out.push_back(forms::xyz(a[i]));
    if (pattern) out.insert(out.end(), a[i].geom.points.begin(), a[i].geom.points.end());
    if (out.size() > kMaxPatternPoints)
      return bad("PATERN: more than " + std::to_string(kMaxPatternPoints) + " points");
  }
  return out;
}

// The pattern copied by each offset, copy after copy (the manual's
// columns): the first, third ... in the pattern's order, the second,
// fourth ... in the reverse order (the APT360 manual, §4.5.3: the tool
// goes up one column and down the next).
PointsResult copies(const Arg& pattern, const std::vector<core::Vec3>& offsets, Budget& b) {
  const std::vector<core::Vec3>& column = pattern.geom.points.all();
  const std::size_t n = column.size();
  if (n * offsets.size() > kMaxPatternPoints)
    return bad("PATERN/PARLEL: more than " + std::to_string(kMaxPatternPoints) + " points");
  if (!b.take(n * offsets.size())) return spent();
  Points out;
  for (std::size_t k = 0; k < offsets.size(); ++k)
    for (std::size_t i = 0; i < n; ++i)
      out.push_back(column[k % 2 == 0 ? i : n - 1 - i] + offsets[k]);
  return out;
}

bool same_point(const core::Vec3& p, const core::Vec3& q) {
  return core::distance(p, q) <= 1e-6;
}

// PARLEL,pattern1,pattern2: the two meet at the first or last point of
// each (the manual: "a common point"); the columns stand at pattern2's
// points, from that common point on (pattern2 read backwards when the
// common point is its last), so that the first column is pattern1 itself.
PointsResult parlel_patterns(const Arg& column, const Arg& rows, Budget& b) {
  const std::vector<core::Vec3>& c = column.geom.points.all();
  const std::vector<core::Vec3>& r = rows.geom.points.all();
  if (!b.take(r.size())) return spent();
  const auto meets = [&c](const core::Vec3& p) {
    return same_point(p, c.front()) || same_point(p, c.back());
  };
  const bool from_first = meets(r.front());
  if (!from_first && !meets(r.back()))
    return bad(
        "PATERN/PARLEL,pattern1,pattern2: the patterns have no common point (the first or "
        "last point of each)");
  std::vector<core::Vec3> offsets;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const std::size_t k = from_first ? i : r.size() - 1 - i;
    offsets.push_back(r[k] - (from_first ? r.front() : r.back()));
  }
  return copies(column, offsets, b);
}

PointsResult parlel(const std::vector<Arg>& a, Budget& b) {
  std::vector<core::Vec3> offsets;
  if (forms::match(a, {"PARLEL", "pat", "pat"})) return parlel_patterns(a[1], a[2], b);
  if (forms::match(a, {"PARLEL", "pat", "v", "n"})) {
    if (!whole(a[3].num, 1)) return bad("PATERN/PARLEL,pattern,vector,n: n is whole, 1 or more");
    if (!b.take(static_cast<std::size_t>(a[3].num))) return spent();
    for (std::size_t k = 0; k < static_cast<std::size_t>(a[3].num); ++k)
      offsets.push_back(forms::xyz(a[2]) * static_cast<double>(k));
    return copies(a[1], offsets, b);
  }
  const auto steps = stepped(a, "PARLEL", "pat", false, b);
  if (!steps) return steps;
  return copies(a[1], *steps, b);
}

}  // namespace

namespace forms {

GeomResult pattern_form(const std::vector<Arg>& a, std::size_t& budget) {
  if (a.empty() || a[0].kind != Arg::Kind::Word) return unknown();
  Budget b(budget);
  PointsResult r = unknown();
  if (a[0].word == "LINEAR") r = linear(a, b);
  if (a[0].word == "ARC") r = arc(a, b);
  if (a[0].word == "RANDOM") r = random(a, b);
  if (a[0].word == "PARLEL") r = parlel(a, b);
  budget = b.left();
  if (!r) return tl::make_unexpected(r.error());
  return pattern_of(std::move(*r));
}

GeomResult pattern_point(const Arg& pattern, double n) {
  const std::size_t count = pattern.geom.points.size();
  if (!(n >= 1 && n <= static_cast<double>(count) && n == std::floor(n)))
    return bad("POINT/pattern,n: n is the number of a point of the pattern, 1 to " +
               std::to_string(count));
  const core::Vec3 p = pattern.geom.points[static_cast<std::size_t>(n) - 1];
  return make_point(p.x, p.y, p.z);
}

}  // namespace forms
}  // namespace usina::apt
