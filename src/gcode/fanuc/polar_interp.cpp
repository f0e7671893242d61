// Polar coordinate interpolation's geometry (fanuc/polar_interp.hpp).
#include "gcode/fanuc/polar_interp.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace usina::gcode::fanuc {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = 180.0 / kPi;
// Samples of each machine move checked against the contour, and how often
// a move may be halved (2^-40 of the path is far below any tolerance).
constexpr int kSamples = 8;
constexpr int kMaxDepth = 40;

// An angle difference brought into (-180, 180]: the rotary axis turns the
// short way between two points close together.
double short_way(double degrees) {
  double d = std::fmod(degrees, 360.0);
  if (d > 180.0) d -= 360.0;
  if (d <= -180.0) d += 360.0;
  return d;
}

double length(core::Vec2 v) {
  return std::hypot(v.x, v.y);
}

double segment_distance(core::Vec2 a, core::Vec2 b, core::Vec2 q) {
  const core::Vec2 ab = b - a;
  const double len2 = ab.x * ab.x + ab.y * ab.y;
  double t = len2 > 0 ? ((q.x - a.x) * ab.x + (q.y - a.y) * ab.y) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return length(q - (a + ab * t));
}

}  // namespace

std::optional<PolarAxes> polar_axes_from(std::string_view text) {
  if (text.size() != 2) return std::nullopt;
  const auto upper = [](char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 32) : c; };
  const std::string_view linear = "XYZ", rotary = "ABC";
  const std::size_t l = linear.find(upper(text[0]));
  const std::size_t r = rotary.find(upper(text[1]));
  if (l == std::string_view::npos || r == std::string_view::npos) return std::nullopt;
  return PolarAxes{static_cast<int>(l), static_cast<int>(r) + 3};
}

VirtualPath virtual_arc(core::Vec2 start, core::Vec2 end, core::Vec2 centre, bool ccw) {
  const double a0 = std::atan2(start.y - centre.y, start.x - centre.x);
  const double a1 = std::atan2(end.y - centre.y, end.x - centre.x);
  double sweep = a1 - a0;
  if (ccw) {
    while (sweep <= 1e-12)
      sweep += 2 * kPi;
  } else {
    while (sweep >= -1e-12)
      sweep -= 2 * kPi;
  }
  return {start, end, true, centre, sweep};
}

// An arc whose end radius differs a little from its start radius (within
// the interpreter's arc tolerance) is a spiral: the radius changes with the
// angle.
core::Vec2 VirtualPath::at(double t) const {
  if (!arc) return start + (end - start) * t;
  const double r0 = length(start - centre), r1 = length(end - centre);
  const double a = std::atan2(start.y - centre.y, start.x - centre.x) + sweep * t;
  const double r = r0 + (r1 - r0) * t;
  return centre + core::Vec2{std::cos(a), std::sin(a)} * r;
}

double VirtualPath::distance(core::Vec2 q) const {
  if (!arc) return segment_distance(start, end, q);
  const double a0 = std::atan2(start.y - centre.y, start.x - centre.x);
  double rel = std::atan2(q.y - centre.y, q.x - centre.x) - a0;  // along the sweep
  rel = sweep > 0 ? std::fmod(rel + 4 * kPi, 2 * kPi) : -std::fmod(-rel + 4 * kPi, 2 * kPi);
  const double t = rel / sweep;
  if (t > 1.0) return std::min(length(q - start), length(q - end));
  const double r0 = length(start - centre), r1 = length(end - centre);
  return std::fabs(length(q - centre) - (r0 + (r1 - r0) * t));
}

double VirtualPath::centre_distance() const {
  return distance({0, 0});
}

void PolarInterp::start(double linear, double rotary) {
  active_ = true;
  side_ = linear < 0 ? -1.0 : 1.0;
  zero_ = rotary_ = rotary;
  at_ = {linear, 0.0};
}

core::Vec2 PolarInterp::virtual_point(double linear, double rotary) const {
  const double a = (rotary - zero_) / kDeg;
  return core::Vec2{std::cos(a), std::sin(a)} * linear;
}

// On the negative side the tool reaches a point at angle θ by turning the
// part to θ + 180°.
PolarInterp::Raw PolarInterp::raw(const VirtualPath& path, double t) const {
  const core::Vec2 p = path.at(t);
  double angle = std::atan2(p.y, p.x) * kDeg;
  if (side_ < 0) angle = short_way(angle + 180.0);
  return {side_ * length(p), angle, t};
}

// The machine moves the linear and rotary axes together in a straight
// line (the short way round): the tool traces a spiral in the virtual
// plane, checked at kSamples points.
bool PolarInterp::close(const VirtualPath& path, const Raw& a, const Raw& b,
                        double tolerance) const {
  const double turn = short_way(b.angle - a.angle);
  for (int k = 1; k < kSamples; ++k) {
    const double s = static_cast<double>(k) / kSamples;
    const double linear = a.linear + (b.linear - a.linear) * s;
    const core::Vec2 q = virtual_point(linear, zero_ + a.angle + turn * s);
    if (path.distance(q) > tolerance) return false;
  }
  return true;
}

bool PolarInterp::split(const VirtualPath& path, const Raw& a, const Raw& b, double tolerance,
                        int depth, std::vector<Raw>& out) const {
  if (close(path, a, b, tolerance)) {
    out.push_back(b);
    return true;
  }
  if (depth >= kMaxDepth || out.size() >= kMaxPolarPieces) return false;
  const Raw mid = raw(path, (a.t + b.t) / 2);
  return split(path, a, mid, tolerance, depth + 1, out) &&
         split(path, mid, b, tolerance, depth + 1, out);
}

PolarFollow PolarInterp::follow(const VirtualPath& path, double tolerance,
                                std::vector<PolarPoint>& out) {
  if (path.centre_distance() < tolerance) return PolarFollow::NearCentre;
  // An arc starts as quarter turns, so a full circle has points to split.
  const int first =
      path.arc ? std::max(1, static_cast<int>(std::ceil(std::fabs(path.sweep) / (kPi / 2) - 1e-9)))
               : 1;
  std::vector<Raw> raws;
  Raw a = raw(path, 0.0);
  for (int k = 1; k <= first; ++k) {
    const Raw b = raw(path, static_cast<double>(k) / first);
    if (!split(path, a, b, tolerance, 0, raws)) return PolarFollow::TooManyPieces;
    a = b;
  }
  double angle = raw(path, 0.0).angle;
  for (const Raw& r : raws) {
    rotary_ += short_way(r.angle - angle);
    angle = r.angle;
    out.push_back({r.linear, rotary_, r.t});
  }
  at_ = path.end;
  return PolarFollow::Ok;
}

}  // namespace usina::gcode::fanuc
