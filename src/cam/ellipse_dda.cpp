#include "cam/ellipse_dda.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace usina::cam {

double dda_increment(double rx, double ry, double resolution) {
  const double res = rx > ry ? resolution * ry / rx : resolution;
  const double steps = std::max(1.0, std::ceil(ry / res - 1e-9));
  return ry / steps;
}

std::vector<Vec2> dda_quadrant(double rx, double ry, double resolution) {
  const double inc = dda_increment(rx, ry, resolution);
  // The registers count increments: the circle's radius is n of them.
  const auto n = static_cast<std::int64_t>(std::llround(ry / inc));
  const double kx = rx / ry;  // equation 1
  std::int64_t px = n;        // Y register: the X integrator adds it (dx/dt = y)
  std::int64_t py = 0;        // X register: the Y integrator adds it (dy/dt = −x)
  std::int64_t qx = 0;
  std::int64_t qy = 0;
  std::vector<Vec2> pts;
  pts.reserve(static_cast<std::size_t>(2 * n + 2));
  pts.push_back({0.0, ry});
  while (py < n || px > 0) {
    if (px == 0) {
      // The interpolator reached the X axis before X reached the radius
      // (it never did in testing): end the quadrant on the axis.
      pts.push_back({rx, 0.0});
      break;
    }
    qx += px;
    qy += py;
    bool stepped = false;
    if (qx >= n && py < n) {  // X overflows at Ry (figure 2)
      qx -= n;
      ++py;
      stepped = true;
    }
    if (qy >= n && px > 0) {
      qy -= n;
      --px;
      stepped = true;
    }
    if (stepped) pts.push_back({static_cast<double>(py) * inc * kx, static_cast<double>(px) * inc});
  }
  pts.back() = {rx, 0.0};  // exact end (the counts are exact; the scale may round)
  return pts;
}

std::vector<Vec2> dda_ellipse(double rx, double ry, double resolution) {
  const std::vector<Vec2> q1 = dda_quadrant(rx, ry, resolution);  // (0,ry) → (rx,0)
  const std::size_t m = q1.size();
  std::vector<Vec2> pts;
  pts.reserve(4 * m);
  // Quadrant 2 (equation 3): (0,ry) → (−rx,0).
  for (std::size_t i = 0; i < m; ++i)
    pts.push_back({-q1[i].x, q1[i].y});
  // Quadrant 3 (equations 2 and 3): (−rx,0) → (0,−ry).
  for (std::size_t i = m - 1; i-- > 0;)
    pts.push_back({-q1[i].x, -q1[i].y});
  // Quadrant 4 (equation 2): (0,−ry) → (rx,0).
  for (std::size_t i = 1; i < m; ++i)
    pts.push_back({q1[i].x, -q1[i].y});
  // Quadrant 1: (rx,0) → (0,ry).
  for (std::size_t i = m - 1; i-- > 0;)
    pts.push_back(q1[i]);
  return pts;
}

}  // namespace usina::cam
