// G12.1/G13.1 polar coordinate interpolation (docs/fanuc.md §7): the
// geometry. The program draws its contour in a virtual Cartesian plane of a
// linear axis (X) and the rotary axis's letter (C, in mm); the machine moves
// the linear axis to the radius and the rotary axis to the angle. This file
// turns a virtual line or arc into machine points (radius, angle) close
// enough together that the machine's straight X-C moves stay within a
// chordal tolerance of the programmed contour.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "core/vec3.hpp"

namespace usina::gcode::fanuc {

// How far the machine path may stray from the programmed contour, mm.
inline constexpr double kPolarChordTolerance = 0.001;
// The most machine moves one programmed line or arc may become: a bound
// for absurd coordinates (a full circle of radius 1 km passing 20 mm from
// the centre takes ~5·10^4; 10^4 km takes more).
inline constexpr std::size_t kMaxPolarPieces = 100'000;

enum class PolarFollow { Ok, NearCentre, TooManyPieces };

// The axes of the polar plane (Fanuc parameters 5460 and 5461), as indices
// into the interpreter's axes (0 X, 1 Y, 2 Z, 3 A, 4 B, 5 C).
struct PolarAxes {
  int linear = 0;
  int rotary = 5;

  char linear_letter() const { return "XYZ"[linear]; }

  char rotary_letter() const { return "ABC"[rotary - 3]; }

  // The arc centre words: I J for X, J K for Y, K I for Z (the manual).
  char centre_first() const { return "IJK"[linear]; }

  char centre_second() const { return "JKI"[linear]; }
};

// "XC", "YB", ...: a linear and a rotary axis letter; nullopt otherwise.
std::optional<PolarAxes> polar_axes_from(std::string_view text);

// A programmed line or arc in the virtual plane, in program units.
struct VirtualPath {
  core::Vec2 start, end;
  bool arc = false;
  core::Vec2 centre{};
  double sweep = 0;  // radians, counter-clockwise > 0; the arc's turn

  core::Vec2 at(double t) const;
  double distance(core::Vec2 q) const;  // from q to the path
  double centre_distance() const;       // the least distance to the polar centre
};

// The arc from `start` to `end` about `centre`; counter-clockwise (G03) or
// not; the same start and end make a full circle.
VirtualPath virtual_arc(core::Vec2 start, core::Vec2 end, core::Vec2 centre, bool ccw);

// A machine point: the linear axis (program units), the rotary axis
// (degrees, continuous from the previous point) and where it is along the
// path (0..1, for the axes outside the plane).
struct PolarPoint {
  double linear = 0;
  double rotary = 0;
  double t = 0;
};

class PolarInterp {
 public:
  // G12.1 with the tool at `linear` and the rotary axis at `rotary`: the
  // virtual point is (linear, 0) and that rotary position is angle 0. The
  // linear axis keeps the side (sign) it starts on, as on the control.
  void start(double linear, double rotary);

  void stop() { active_ = false; }

  bool active() const { return active_; }

  core::Vec2 point() const { return at_; }

  // The machine points of `path` from point() on, within `tolerance`
  // (program units); NearCentre when the path comes within `tolerance` of
  // the centre, where the angle is undefined; nothing moves unless Ok.
  PolarFollow follow(const VirtualPath& path, double tolerance, std::vector<PolarPoint>& out);

  // The virtual point the machine position (linear, rotary) stands for.
  core::Vec2 virtual_point(double linear, double rotary) const;

 private:
  struct Raw {
    double linear, angle, t;  // angle in (-180, 180] about the rotary zero
  };

  Raw raw(const VirtualPath& path, double t) const;
  bool close(const VirtualPath& path, const Raw& a, const Raw& b, double tolerance) const;
  bool split(const VirtualPath& path, const Raw& a, const Raw& b, double tolerance, int depth,
             std::vector<Raw>& out) const;

  bool active_ = false;
  double side_ = 1;    // the linear axis' sign
  double zero_ = 0;    // the rotary position of angle 0, degrees
  double rotary_ = 0;  // the rotary axis now, degrees
  core::Vec2 at_{};    // the virtual point now
};

}  // namespace usina::gcode::fanuc
