// Three-component vectors for positions and directions (mm).
#pragma once

#include <cmath>

namespace usina::core {

struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }

  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }

  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }

  constexpr Vec3 operator/(double s) const { return {x / s, y / s, z / s}; }

  constexpr Vec3 operator-() const { return {-x, -y, -z}; }

  constexpr Vec3& operator+=(const Vec3& o) { return *this = *this + o; }

  constexpr Vec3& operator-=(const Vec3& o) { return *this = *this - o; }

  constexpr bool operator==(const Vec3&) const = default;

  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

constexpr double dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

inline double norm(const Vec3& v) {
  return std::sqrt(dot(v, v));
}

inline double distance(const Vec3& a, const Vec3& b) {
  return norm(a - b);
}

// 2-D vector in a plane's own (first, second) coordinates.
struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2 operator+(const Vec2& o) const { return {x + o.x, y + o.y}; }

  constexpr Vec2 operator-(const Vec2& o) const { return {x - o.x, y - o.y}; }

  constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }

  constexpr Vec2 operator/(double s) const { return {x / s, y / s}; }

  constexpr Vec2 operator-() const { return {-x, -y}; }

  constexpr bool operator==(const Vec2&) const = default;
};

constexpr double dot(const Vec2& a, const Vec2& b) {
  return a.x * b.x + a.y * b.y;
}

constexpr double cross(const Vec2& a, const Vec2& b) {
  return a.x * b.y - a.y * b.x;
}

inline double norm(const Vec2& v) {
  return std::hypot(v.x, v.y);
}

inline double distance(const Vec2& a, const Vec2& b) {
  return norm(a - b);
}

// Counter-clockwise perpendicular.
constexpr Vec2 perp(const Vec2& v) {
  return {-v.y, v.x};
}

inline Vec2 rotate(const Vec2& v, double rad) {
  const double c = std::cos(rad);
  const double s = std::sin(rad);
  return {v.x * c - v.y * s, v.x * s + v.y * c};
}

}  // namespace usina::core
