// PATERN definition forms and GOTO/pattern's modifiers (docs/apt.md,
// "Patterns"). Counts are whole numbers; increments (INCR) are distances
// along a vector or angles on a circle between one point and the next.
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
tl::expected<std::vector<double>, GeomError> increments(const std::vector<Arg>& a, std::size_t i) {
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
      out.insert(out.end(), static_cast<std::size_t>(a[i].num), a[i + 2].num);
      i += 3;
      continue;
    }
    if (out.size() == kMaxPatternPoints)
      return bad("PATERN: more than " + std::to_string(kMaxPatternPoints) + " increments");
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

PointsResult linear(const std::vector<Arg>& a) {
  if (forms::match(a, {"LINEAR", "p", "p", "n"})) {
    if (!whole(a[3].num, 2)) return bad("PATERN/LINEAR,point,point,n: n is whole, 2 or more");
    const auto n = static_cast<std::size_t>(a[3].num);
    const core::Vec3 p = forms::xyz(a[1]), q = forms::xyz(a[2]);
    Points out;
    for (std::size_t k = 0; k < n; ++k)
      out.push_back(p + (q - p) * (static_cast<double>(k) / static_cast<double>(n - 1)));
    return out;
  }
  if (forms::match(a, {"LINEAR", "p", "v", "n"})) {
    if (!whole(a[3].num, 1)) return bad("PATERN/LINEAR,point,vector,n: n is whole, 1 or more");
    Points out;
    for (std::size_t k = 0; k < static_cast<std::size_t>(a[3].num); ++k)
      out.push_back(forms::xyz(a[1]) + forms::xyz(a[2]) * static_cast<double>(k));
    return out;
  }
  const bool incr = a.size() > 4 &&
                    forms::match({a.begin(), a.begin() + 3}, {"LINEAR", "p", "v"}) &&
                    is_word(a[3], "INCR");
  if (!incr) return unknown();
  const auto u = unit(a[2]);
  if (!u) return tl::make_unexpected(u.error());
  const auto steps = increments(a, 3);
  if (!steps) return tl::make_unexpected(steps.error());
  Points out{forms::xyz(a[1])};
  for (double d : *steps)
    out.push_back(out.back() + *u * d);
  return out;
}

// Angles in degrees from +X, counter-clockwise; CLW turns the other way.
PointsResult on_circle(const Arg& c, const std::vector<double>& angles) {
  Points out;
  for (double t : angles)
    out.push_back({c.geom.c[0] + c.geom.c[6] * std::cos(t * kDeg),
                   c.geom.c[1] + c.geom.c[6] * std::sin(t * kDeg), c.geom.c[2]});
  return out;
}

PointsResult arc(const std::vector<Arg>& a) {
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
  const auto steps = increments(a, 4);
  if (!steps) return tl::make_unexpected(steps.error());
  const double sense = a[3].word == "CLW" ? -1.0 : 1.0;
  std::vector<double> angles{a[2].num};
  for (double d : *steps)
    angles.push_back(angles.back() + sense * d);
  return on_circle(a[1], angles);
}

PointsResult random(const std::vector<Arg>& a) {
  if (a.size() < 2) return unknown();
  Points out;
  for (std::size_t i = 1; i < a.size(); ++i) {
    const bool point = a[i].kind == Arg::Kind::Geom && a[i].geom.type == GeomType::Point;
    const bool pattern = a[i].kind == Arg::Kind::Geom && a[i].geom.type == GeomType::Pattern;
    if (!point && !pattern) return unknown();
    if (point) out.push_back(forms::xyz(a[i]));
    if (pattern) out.insert(out.end(), a[i].geom.points.begin(), a[i].geom.points.end());
    if (out.size() > kMaxPatternPoints)
      return bad("PATERN: more than " + std::to_string(kMaxPatternPoints) + " points");
  }
  return out;
}

// The pattern copied by each offset, copy after copy.
PointsResult copies(const Arg& pattern, const std::vector<core::Vec3>& offsets) {
  const std::size_t n = pattern.geom.points.size();
  if (n * offsets.size() > kMaxPatternPoints)
    return bad("PATERN/PARLEL: more than " + std::to_string(kMaxPatternPoints) + " points");
  Points out;
  for (const core::Vec3& d : offsets)
    for (const core::Vec3& p : pattern.geom.points)
      out.push_back(p + d);
  return out;
}

PointsResult parlel(const std::vector<Arg>& a) {
  std::vector<core::Vec3> offsets;
  if (forms::match(a, {"PARLEL", "pat", "pat"})) {
    for (const core::Vec3& q : a[2].geom.points)
      offsets.push_back(q - a[2].geom.points.front());
    return copies(a[1], offsets);
  }
  if (forms::match(a, {"PARLEL", "pat", "v", "n"})) {
    if (!whole(a[3].num, 1)) return bad("PATERN/PARLEL,pattern,vector,n: n is whole, 1 or more");
    for (std::size_t k = 0; k < static_cast<std::size_t>(a[3].num); ++k)
      offsets.push_back(forms::xyz(a[2]) * static_cast<double>(k));
    return copies(a[1], offsets);
  }
  const bool incr = a.size() > 4 &&
                    forms::match({a.begin(), a.begin() + 3}, {"PARLEL", "pat", "v"}) &&
                    is_word(a[3], "INCR");
  if (!incr) return unknown();
  const auto u = unit(a[2]);
  if (!u) return tl::make_unexpected(u.error());
  const auto steps = increments(a, 3);
  if (!steps) return tl::make_unexpected(steps.error());
  offsets.push_back({});
  for (double d : *steps)
    offsets.push_back(offsets.back() + *u * d);
  return copies(a[1], offsets);
}

using Range = std::pair<std::size_t, std::size_t>;  // first, last (from 0)

// i[,THRU,j],... from a[k] on, while numbers come: the ranges of the points
// named (numbered from 1 in `n`); k ends past them.
tl::expected<std::vector<Range>, GeomError> point_list(const std::vector<Arg>& a, std::size_t& k,
                                                       std::size_t n, const std::string& what) {
  const auto number = [&](const Arg& x) -> tl::expected<std::size_t, GeomError> {
    if (x.kind != Arg::Kind::Number || !(x.num >= 1) || x.num > static_cast<double>(n) ||
        x.num != std::floor(x.num))
      return bad("GOTO/pattern," + what + ": a point's number is whole, 1 to " + std::to_string(n));
    return static_cast<std::size_t>(x.num) - 1;
  };
  std::vector<Range> out;
  while (k < a.size() && a[k].kind == Arg::Kind::Number) {
    const auto from = number(a[k++]);
    if (!from) return tl::make_unexpected(from.error());
    std::size_t to = *from;
    if (k < a.size() && is_word(a[k], "THRU")) {
      if (++k == a.size()) return bad("GOTO/pattern," + what + ": THRU takes a point's number");
      const auto last = number(a[k++]);
      if (!last) return tl::make_unexpected(last.error());
      to = *last;
    }
    out.push_back({std::min(*from, to), std::max(*from, to)});
  }
  if (out.empty()) return bad("GOTO/pattern," + what + " takes the numbers of points");
  return out;
}

// Adds 1 to `hits` over the union of `ranges` (through a difference array:
// the work is the pattern's size plus the ranges', never their product).
void count_once(std::vector<Range> ranges, std::vector<int>& delta) {
  std::sort(ranges.begin(), ranges.end());
  std::size_t i = 0;
  while (i < ranges.size()) {
    Range r = ranges[i++];
    while (i < ranges.size() && ranges[i].first <= r.second + 1)
      r.second = std::max(r.second, ranges[i++].second);
    ++delta[r.first];
    --delta[r.second + 1];
  }
}

struct Modifiers {
  bool invers = false;
  std::vector<int> omit, retain;  // difference arrays of the points named
  int retains = 0;                // RETAIN groups
  std::vector<std::pair<Range, double>> avoid;
};

tl::expected<Modifiers, GeomError> read_modifiers(const std::vector<Arg>& mods, std::size_t n) {
  Modifiers m;
  m.omit.assign(n + 1, 0);
  m.retain.assign(n + 1, 0);
  for (std::size_t k = 0; k < mods.size();) {
    const std::string w = mods[k].kind == Arg::Kind::Word ? mods[k].word : std::string();
    ++k;
    if (w == "INVERS") {
      m.invers = true;
      continue;
    }
    double rise = 0.0;
    if (w == "AVOID") {
      if (k == mods.size() || mods[k].kind != Arg::Kind::Number || !(mods[k].num > 0))
        return bad("GOTO/pattern,AVOID takes the rise (more than 0), then the points' numbers");
      rise = mods[k++].num;
    }
    if (w != "OMIT" && w != "RETAIN" && w != "AVOID")
      return bad("GOTO/pattern takes INVERS, OMIT, RETAIN and AVOID after the pattern" +
                 std::string(w.empty() ? "" : ", not " + w));
    auto ranges = point_list(mods, k, n, w);
    if (!ranges) return tl::make_unexpected(ranges.error());
    if (w == "OMIT") count_once(std::move(*ranges), m.omit);
    if (w == "RETAIN") {
      count_once(std::move(*ranges), m.retain);
      ++m.retains;
    }
    for (const Range& r : w == "AVOID" ? *ranges : std::vector<Range>{})
      m.avoid.push_back({r, rise});
  }
  return m;
}

// The rise of each point: the largest AVOID naming it (a sweep over the
// ranges' ends).
std::vector<double> rises(std::vector<std::pair<Range, double>> avoid, std::size_t n) {
  std::vector<double> out(n, 0.0);
  std::sort(avoid.begin(), avoid.end());
  std::multiset<std::pair<std::size_t, double>> open;  // (last, rise)
  std::multiset<double> heights;
  std::size_t next = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (next < avoid.size() && avoid[next].first.first == i) {
      open.insert({avoid[next].first.second, avoid[next].second});
      heights.insert(avoid[next].second);
      ++next;
    }
    while (!open.empty() && open.begin()->first < i) {
      heights.erase(heights.find(open.begin()->second));
      open.erase(open.begin());
    }
    if (!heights.empty()) out[i] = *heights.rbegin();
  }
  return out;
}

}  // namespace

tl::expected<std::vector<PatternVisit>, GeomError> pattern_visits(const Geom& pattern,
                                                                  const std::vector<Arg>& mods) {
  const std::size_t n = pattern.points.size();
  auto m = read_modifiers(mods, n);
  if (!m) return tl::make_unexpected(m.error());
  const std::vector<double> rise = rises(std::move(m->avoid), n);
  std::vector<bool> keep(n);
  int omitted = 0, retained = 0;
  for (std::size_t i = 0; i < n; ++i) {
    omitted += m->omit[i];
    retained += m->retain[i];
    keep[i] = omitted == 0 && retained == m->retains;  // each OMIT and RETAIN narrows
  }
  std::vector<PatternVisit> out;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = m->invers ? n - 1 - k : k;
    if (keep[i]) out.push_back({pattern.points[i], rise[i]});
  }
  if (out.empty()) return bad("GOTO/pattern: OMIT and RETAIN leave no point to go to");
  return out;
}

namespace forms {

GeomResult pattern_form(const std::vector<Arg>& a) {
  if (a.empty() || a[0].kind != Arg::Kind::Word) return unknown();
  PointsResult r = unknown();
  if (a[0].word == "LINEAR") r = linear(a);
  if (a[0].word == "ARC") r = arc(a);
  if (a[0].word == "RANDOM") r = random(a);
  if (a[0].word == "PARLEL") r = parlel(a);
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
