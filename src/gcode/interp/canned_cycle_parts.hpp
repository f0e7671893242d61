// What the canned cycles' files share (canned_cycles.cpp: the drilling
// cycles; canned_cycle_g76.cpp: the threading cycle): program units as
// LinuxCNC reads them, the moves of a cycle, its errors. Only those two files
// include it.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "canon/op.hpp"
#include "core/arc.hpp"
#include "gcode/interp/motion.hpp"

namespace usina::gcode::cycle_parts {

inline tl::unexpected<InterpError> error(core::Code code, std::string message) {
  return interp_error(code, std::move(message));
}

// LinuxCNC computes in program units; usina holds mm (v = u * 25.4). v / 25.4
// can miss the number LinuxCNC read by an ulp, and then a depth that is an
// exact multiple of Q gets one peck more or less; 15 significant digits bring
// it back. But a number the program computed (an R of [-7.192 + 7.57577])
// has all 17 digits, whose last ones decide "above R or at R" for LinuxCNC:
// the 15-digit number is taken only when it multiplies back to v, else a
// double next to v / 25.4 that does (several may: any is on R's side).
struct Units {
  double mm = 1.0;  // mm per program unit

  double in(double v) const {
    if (mm == 1.0) return v;
    const double q = v / mm;
    std::array<char, 40> buf{};
    const auto res =
        std::to_chars(buf.data(), buf.data() + buf.size(), q, std::chars_format::general, 15);
    double rounded = q;
    std::from_chars(buf.data(), res.ptr, rounded);
    if (rounded * mm == v) return rounded;
    for (const double c : {q, std::nextafter(q, -HUGE_VAL), std::nextafter(q, HUGE_VAL)}) {
      if (c * mm == v) return c;
    }
    return rounded;
  }

  double out(double u) const { return u * mm; }

  // A length for a message, in the program's unit: "0.5 in", "12 mm".
  std::string show(double v) const {
    return fmt::format("{:g} {}", in(v), mm == 1.0 ? "mm" : "in");
  }

  Vec3 in(const Vec3& v) const { return {in(v.x), in(v.y), in(v.z)}; }

  Vec3 out(const Vec3& u) const { return u * mm; }
};

// A whole number as LinuxCNC reads one (read_integer_value): within 0.0001.
inline std::optional<long> whole_number(double v) {
  if (!(std::abs(v) < 1e9)) return std::nullopt;
  const double f = std::floor(v);
  if (v - f > 0.9999) return static_cast<long>(f) + 1;
  if (v - f > 0.0001) return std::nullopt;
  return static_cast<long>(f);
}

// LinuxCNC's cycle_traverse and cycle_feed: (a, b) in the plane, c on its normal.
class Mover {
 public:
  Mover(MotionTarget& target, core::Plane plane, Units units)
      : target_(target), plane_(plane), units_(units) {}

  Vec3 at(double a, double b, double c) const {
    return units_.out(core::from_plane({a, b}, c, plane_));
  }

  void traverse(double a, double b, double c) { target_.traverse(at(a, b, c)); }

  void feed(double a, double b, double c) { target_.feed(at(a, b, c)); }

  void dwell(double s) { target_.dwell(s); }

  void spindle(canon::SpindleDir d) { target_.spindle(d); }

  void hole(double a, double b, double r, double bottom) {
    target_.hole(at(a, b, r), units_.out(r - bottom));
  }

 private:
  MotionTarget& target_;
  core::Plane plane_;
  Units units_;
};

// LinuxCNC checks the spindle inside each cycle (convert_cycle_g74_g84, _g86,
// _g87, _g88, convert_threading_cycle); the message names the cycle.
InterpResult check_spindle(int motion, canon::SpindleDir dir);

}  // namespace usina::gcode::cycle_parts
