#include "apt/contour.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace usina::apt {
namespace {

using core::cross;
using core::dot;
using core::norm;

// Below this a choice of direction is ambiguous (the sine or cosine of
// the angle between the drive surface and the direction of motion).
constexpr double kAmbiguous = 1e-6;
// A stop point closer than this to the start (in length or, on a circle,
// in radians) is where the tool already is, not a stop ahead of it.
constexpr double kAhead = 1e-9;
// IBM's processor adds a revolution with its constant pi, 3.14159 (the
// block data of its arithmetic element), not the double's: the points of
// an arc that wraps through ±180° differ by up to 1e-5 with the true one.
constexpr double kIbmPi = 3.14159;

double signed_distance(const Curve& s, Vec2 p) {
  if (s.circle) return norm(p - s.round.c) - s.round.r;
  return dot(s.line.n, p) - s.line.d;
}

// The position of `p` along `path`: a length on a line, the angle swept
// from the start in the sense of travel ([0, 2π)) on a circle.
double along(const Path& path, Vec2 p) {
  if (!path.circle) return dot(p - path.start, path.t);
  const double a0 = std::atan2(path.start.y - path.c.y, path.start.x - path.c.x);
  const double a1 = std::atan2(p.y - path.c.y, p.x - path.c.x);
  double a = path.sense * (a1 - a0);
  while (a < 0.0)
    a += 2.0 * M_PI;
  while (a >= 2.0 * M_PI)
    a -= 2.0 * M_PI;
  return a;
}

// Where `path` meets a line or a circle.
std::vector<Vec2> meet_path(const Path& path, const Curve& c) {
  if (!path.circle) {
    const Line2 pl{{-path.t.y, path.t.x}, -path.t.y * path.start.x + path.t.x * path.start.y};
    if (c.circle) return meet(pl, c.round);
    const auto p = meet(pl, c.line);
    return p ? std::vector<Vec2>{*p} : std::vector<Vec2>{};
  }
  const Circle2 pc{path.c, path.rho};
  return c.circle ? meet(pc, c.round) : meet(c.line, pc);
}

// The check surface offset by `r` to either side (TO and PAST places).
std::vector<Curve> offsets(const Curve& cs, double r) {
  Curve a = cs;
  Curve b = cs;
  if (cs.circle) {
    a.round.r = cs.round.r + r;
    b.round.r = std::fabs(cs.round.r - r);
    return b.round.r > 0.0 ? std::vector<Curve>{a, b} : std::vector<Curve>{a};
  }
  a.line.d += r;
  b.line.d -= r;
  return {a, b};
}

// The candidates ahead of the start, ordered along the path.
std::vector<Vec2> ahead(const Path& path, const std::vector<Curve>& curves) {
  std::vector<std::pair<double, Vec2>> found;
  for (const Curve& c : curves)
    for (Vec2 p : meet_path(path, c)) {
      const double s = along(path, p);
      if (s > kAhead) found.emplace_back(s, p);
    }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Vec2> out;
  for (const auto& f : found)
    out.push_back(f.second);
  return out;
}

bool near(double a, double b) {
  return std::fabs(a - b) <= 1e-6 * std::max({1.0, std::fabs(a), std::fabs(b)});
}

// TANTO: the place on the path across from where drive and check touch.
std::optional<Vec2> tangent_stop(const Path& path, const Curve& ds, const Curve& cs,
                                 std::string& why) {
  if (!ds.circle && cs.circle) {
    if (!near(std::fabs(signed_distance(ds, cs.round.c)), cs.round.r)) {
      why = "the drive line is not tangent to the check circle";
      return std::nullopt;
    }
    const Vec2 p = path.start + path.t * dot(cs.round.c - path.start, path.t);
    if (along(path, p) <= kAhead) {
      why = "the point where the drive line touches the check circle is behind the tool";
      return std::nullopt;
    }
    return p;
  }
  if (ds.circle && !cs.circle) {
    const double sd = signed_distance(cs, ds.round.c);
    if (!near(std::fabs(sd), ds.round.r)) {
      why = "the check line is not tangent to the drive circle";
      return std::nullopt;
    }
    return path.c + (sd > 0.0 ? -cs.line.n : cs.line.n) * path.rho;
  }
  if (ds.circle && cs.circle) {
    const Vec2 d = cs.round.c - ds.round.c;
    const double dist = norm(d);
    const bool outer = near(dist, ds.round.r + cs.round.r);
    const bool inner = dist > 0.0 && near(dist, std::fabs(ds.round.r - cs.round.r));
    if (!outer && !inner) {
      why = "the drive and check circles are not tangent";
      return std::nullopt;
    }
    const bool toward = outer || ds.round.r > cs.round.r;
    return path.c + d * ((toward ? 1.0 : -1.0) * path.rho / dist);
  }
  why = "two lines are never tangent (TANTO needs a circle)";
  return std::nullopt;
}

}  // namespace

std::optional<double> horizontal_z(const Geom& g) {
  if (g.type != GeomType::Plane) return std::nullopt;
  const auto& c = g.c;
  if (std::fabs(c[2]) < 1e-9 || std::hypot(c[0], c[1]) > 1e-9 * std::fabs(c[2]))
    return std::nullopt;
  return c[3] / c[2];
}

double distance_to(const Curve& c, Vec2 p) {
  if (c.circle) return std::fabs(std::hypot(p.x - c.round.c.x, p.y - c.round.c.y) - c.round.r);
  return std::fabs(c.line.n.x * p.x + c.line.n.y * p.y - c.line.d);
}

std::optional<Curve> curve_of(const Geom& g) {
  Curve out;
  if (g.type == GeomType::Line) {
    out.line = {{g.c[0], g.c[1]}, g.c[3]};
    return out;
  }
  if (g.type == GeomType::Circle) {
    out.circle = true;
    out.round = {{g.c[0], g.c[1]}, g.c[6]};
    return out;
  }
  if (g.type == GeomType::Plane) {
    const double len = std::hypot(g.c[0], g.c[1]);
    if (len < 1e-9 || std::fabs(g.c[2]) > 1e-9 * len) return std::nullopt;  // not vertical
    out.line = {{g.c[0] / len, g.c[1] / len}, g.c[3] / len};
    return out;
  }
  return std::nullopt;
}

Vec2 tangent_at(const Path& path, Vec2 p) {
  if (!path.circle) return path.t;
  const Vec2 v = p - path.c;
  return Vec2{-v.y, v.x} * (path.sense / norm(v));
}

std::optional<Path> drive_path(const Curve& ds, Vec2 te, Vec2 fwd, Turn turn, int side, double r,
                               double tol, std::string& why) {
  Vec2 u{-ds.line.n.y, ds.line.n.x};
  if (ds.circle) {
    const Vec2 v = te - ds.round.c;
    if (norm(v) < 1e-9) {
      why = "the tool is at the centre of the drive circle";
      return std::nullopt;
    }
    u = Vec2{-v.y, v.x} / norm(v);  // counter-clockwise
  }
  double how = dot(fwd, u);
  if (turn == Turn::Back) how = -how;
  if (turn == Turn::Left) how = cross(fwd, u);
  if (turn == Turn::Right) how = -cross(fwd, u);
  if (std::fabs(how) < kAmbiguous) {
    why = turn == Turn::Left || turn == Turn::Right
              ? "the drive surface runs along the direction of motion: neither way turns (use "
                "GOFWD or GOBACK)"
              : "the drive surface crosses the direction of motion at a right angle: neither "
                "way is forward (use GOLFT or GORGT)";
    return std::nullopt;
  }
  const int k = how > 0.0 ? 1 : -1;
  Path p;
  p.start = te;
  if (!ds.circle) {
    p.t = u * k;
    const Vec2 left{-p.t.y, p.t.x};
    const double off = signed_distance(ds, te) * dot(ds.line.n, left);
    if (std::fabs(off - side * r) > tol) {
      why = "the tool is " + fmt::format("{:g}", off) + " to the left of the drive line, not " +
            fmt::format("{:g}", side * r) + " (the cutter's side and radius): position it first";
      return std::nullopt;
    }
    return p;
  }
  p.circle = true;
  p.c = ds.round.c;
  p.sense = k;
  p.rho = norm(te - p.c);
  const double want = ds.round.r - side * r * k;
  if (want <= 0.0 || std::fabs(p.rho - want) > tol) {
    why = "the tool is " + fmt::format("{:g}", p.rho) + " from the drive circle's centre, not " +
          fmt::format("{:g}", want) +
          " (the circle's radius and the cutter's side): position it first";
    return std::nullopt;
  }
  return p;
}

std::optional<Vec2> stop_point(const Path& path, const Curve& ds, const Curve& cs, Stop stop,
                               int nth, double r, std::string& why) {
  if (stop == Stop::Tanto) return tangent_stop(path, ds, cs, why);
  std::size_t index = static_cast<std::size_t>(nth - 1);
  std::vector<Vec2> found;
  if (stop == Stop::On) {
    found = ahead(path, {cs});
  } else {
    found = ahead(path, offsets(cs, r));
    // From a start where the cutter already overlaps the check surface the
    // first place met is where it leaves it: a PAST place (§5.1).
    const bool inside = std::fabs(signed_distance(cs, path.start)) < r - 1e-9;
    const bool first_is_to = !inside;
    index = 2 * index + ((stop == Stop::To) == first_is_to ? 0 : 1);
  }
  if (index >= found.size()) {
    why = found.empty() ? "the path never meets the check surface"
                        : "the path meets the check surface fewer times than asked";
    return std::nullopt;
  }
  return found[index];
}

std::optional<Vec2> startup_one(const Curve& s, Vec2 te, Stop stop, double r, std::string& why) {
  if (stop == Stop::Tanto) {
    why = "GO/ takes TO, ON or PAST";
    return std::nullopt;
  }
  if (!s.circle) {
    const double sd = signed_distance(s, te);
    const double sgn = sd >= 0.0 ? 1.0 : -1.0;
    const double target = stop == Stop::On ? 0.0 : (stop == Stop::To ? sgn * r : -sgn * r);
    return te + s.line.n * (target - sd);
  }
  const Vec2 v = te - s.round.c;
  const double d = norm(v);
  if (d < 1e-9) {
    why = "the tool is at the circle's centre: no nearest point";
    return std::nullopt;
  }
  const bool outside = d >= s.round.r;
  double rho = s.round.r;
  if (stop != Stop::On) rho += ((stop == Stop::To) == outside ? r : -r);
  if (rho < 0.0) {
    why = "the cutter is larger than the circle";
    return std::nullopt;
  }
  return s.round.c + v * (rho / d);
}

namespace {

// The offset of `s` on which the tool centre stands `stop` to it, judged
// from `te`.
std::optional<Curve> offset_for(const Curve& s, Vec2 te, Stop stop, double r, std::string& why) {
  const auto p = startup_one(s, te, stop, r, why);
  if (!p) return std::nullopt;
  Curve c = s;
  if (s.circle) {
    c.round.r = norm(*p - s.round.c);
  } else {
    c.line.d = dot(s.line.n, *p);
  }
  return c;
}

}  // namespace

std::optional<Vec2> startup_two(const Curve& ds, Stop ds_stop, const Curve& cs, Stop cs_stop,
                                Vec2 te, double r, std::string& why) {
  const auto a = offset_for(ds, te, ds_stop, r, why);
  const auto b = a ? offset_for(cs, te, cs_stop, r, why) : std::nullopt;
  if (!b) return std::nullopt;
  std::vector<Vec2> found;
  if (!a->circle && !b->circle) {
    if (const auto p = meet(a->line, b->line)) found.push_back(*p);
  } else if (a->circle && b->circle) {
    found = meet(a->round, b->round);
  } else {
    found = a->circle ? meet(b->line, a->round) : meet(a->line, b->round);
  }
  if (found.empty()) {
    why = "the offsets of the drive and check surfaces do not meet";
    return std::nullopt;
  }
  return *std::min_element(found.begin(), found.end(), [&](Vec2 x, Vec2 y) {
    return core::distance(x, te) < core::distance(y, te);
  });
}

std::optional<std::vector<Vec2>> segment_arc(const Path& path, Vec2 te, Vec2 end, double intol,
                                             double outtol, bool convex, double widen,
                                             std::size_t most, std::string& why) {
  // The tolerance band about the path: the chords' ends on its outer
  // radius, their middles on its inner one; the band lies on the side of
  // the path away from the part (convex: outside, concave: inside).
  const double band = intol + outtol + widen;
  const double rbig = convex ? path.rho + outtol : path.rho + intol;
  const double rlit = convex ? path.rho - intol : rbig - band;
  if (intol + outtol <= 0.0 || rlit <= 0.0) {
    why = intol + outtol <= 0.0 ? "INTOL and OUTTOL are both 0: no chord fits the circle"
                                : "the tolerance is larger than the circle";
    return std::nullopt;
  }
  const double half = std::atan(std::sqrt(rbig * rbig - rlit * rlit) / rlit);
  const double a0 = std::atan2(te.y - path.c.y, te.x - path.c.x);
  const double a1 = std::atan2(end.y - path.c.y, end.x - path.c.x);
  double sweep = path.sense * (a1 - a0);
  if (sweep < 0.0) sweep += 2.0 * kIbmPi;
  // Half steps, rounded up, then up to even: the first and last steps are
  // half steps, the ends lying on the path and not on the band's edge.
  const double steps = std::floor(sweep / half) + 1.0;
  if (!std::isfinite(steps)) {
    why = "the circle's numbers are out of range";
    return std::nullopt;
  }
  if (steps / 2.0 > static_cast<double>(most)) {
    why = fmt::format(
        "the tolerance would take {:.0f} points on the circle (at most {}): raise "
        "OUTTOL",
        steps / 2.0, most);
    return std::nullopt;
  }
  auto n = static_cast<long long>(steps);
  n += n % 2;
  const double step = sweep / static_cast<double>(n);
  std::vector<Vec2> out;
  for (long long i = 1; i < n; i += 2) {
    const double a = a0 + path.sense * static_cast<double>(i) * step;
    out.push_back(path.c + Vec2{std::cos(a), std::sin(a)} * rbig);
  }
  return out;
}

}  // namespace usina::apt
