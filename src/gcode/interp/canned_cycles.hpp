// RS274NGC canned cycles as LinuxCNC 2.10 executes them: the drilling,
// tapping and boring cycles G73 G74 G81-G89 (any of G17/G18/G19, G98/G99,
// G90/G91, L repeats, sticky words) and the lathe threading cycle G76.
// Sources: LinuxCNC src/emc/rs274ngc/interp_cycles.cc (convert_cycle,
// convert_cycle_xy/_zx/_yz, CYCLE_MACRO, convert_cycle_g73 ... _g89) and
// interp_convert.cc (convert_motion, convert_threading_cycle); the G-code
// reference (docs/gcode/g-code, "Canned Cycles", "G76").
#pragma once

#include <optional>

#include "canon/op.hpp"
#include "core/arc.hpp"
#include "gcode/interp/motion.hpp"

namespace usina::gcode {

// The words of one block of a canned cycle, as written: absolute under G90,
// increments under G91. Every length is in mm (the interpreter multiplies by
// 25.4 under G20); X is a radius coordinate under G7 as for any move.
struct CycleWords {
  std::optional<double> x{}, y{}, z{};   // hole position and, on the plane's normal, the bottom
  std::optional<double> r{};             // retract plane (G76: depth degression, no unit)
  std::optional<double> q{};             // G73/G83 peck depth (G76: compound angle, degrees)
  std::optional<double> i{}, j{}, k{};   // G87 offsets and top of the back bore (G76: depths)
  std::optional<double> p{};             // dwell, seconds (G76: pitch, mm per revolution)
  std::optional<double> l{};             // repeats (G76: taper ends 0-3), a whole number
  std::optional<double> h{};             // G76 spring passes, a whole number
  std::optional<double> e{};             // G76 taper length along Z
  std::optional<double> polar_radius{};  // @ (G17 only)
  std::optional<double> polar_angle{};   // ^ degrees (G17 only)
};

// The modal state a cycle needs, read from the interpreter's state before the block.
struct CycleModal {
  // The cycle's G code in tenths, as the interpreter keeps G codes:
  // 730, 740, 760, 810, 820, ..., 890.
  int motion = 810;
  core::Plane plane = core::Plane::XY;
  bool incremental = false;   // G91
  bool retract_to_r = false;  // G99; G98 (retract to the initial level) otherwise
  // The motion mode in effect before this block was not this same cycle: the
  // cycle starts, so R, the bottom, P, Q and I/J/K are not taken from before.
  bool motion_mode_changed = true;
  canon::SpindleDir spindle = canon::SpindleDir::Off;
  double peck_clearance = 1.0;  // mm; G73/G83 stop this far above the last peck
  // mm G73 backs off after each peck; empty: the clearance.
  std::optional<double> peck_retract;
  // mm per program unit (25.4 under G20): LinuxCNC computes in program units,
  // and so must usina where a comparison decides how many pecks or passes.
  double length_unit = 1.0;
  bool diameter_mode = false;  // G7: G76 halves I, J and K
};

// Runs cycle blocks and keeps what LinuxCNC keeps between them.
class CannedCycles {
 public:
  // Executes one cycle block (motion mode G73/G74/G76/G81-G89) on `target`,
  // starting from target.position(). On error nothing has moved and no
  // sticky value changed.
  InterpResult run(const CycleWords& words, const CycleModal& modal, MotionTarget& target);

  // A motion that is not G73/G74/G81-G89 ran (G0-G3, G33, G38.x, G76, G80,
  // ...): the next cycle takes its initial level (G98) from where it starts.
  // LinuxCNC: convert_motion clears cycle_il_flag.
  void note_other_motion() { initial_level_.reset(); }

  // LinuxCNC's cycle_il as it holds it (program units), if a cycle runs.
  std::optional<double> initial_level() const { return initial_level_; }

  // A refused block's note_other_motion() undone (Interpreter::roll_back).
  void put_back_initial_level(std::optional<double> level) { initial_level_ = level; }

  // Program start: every sticky value back to LinuxCNC's initial one.
  void reset() { *this = CannedCycles{}; }

  // The interpreter's current point after the last run(). It is where the
  // last move went, except after G74/G84 in G18/G19, whose retract LinuxCNC
  // sends elsewhere (see canned_cycles.cpp) while its interpreter carries on
  // from here. Keep it unchanged as the current point: the next run() then
  // starts from LinuxCNC's own numbers for it.
  Vec3 end_point() const { return end_point_; }

  // Sticky values (LinuxCNC's cycle_r, cycle_cc, cycle_p, ...), in mm as written.
  struct Sticky {
    double r = 0.0;
    double bottom = 0.0;  // the word on the plane's normal (Z in G17), as written
    double p = 0.0;       // dwell, seconds
    double q = 0.0;
    double i = 0.0, j = 0.0, k = 0.0;
  };

 private:
  InterpResult run_drilling(const CycleWords& words, const CycleModal& modal, MotionTarget& target);
  InterpResult run_threading(const CycleWords& words, const CycleModal& modal,
                             MotionTarget& target);

  Sticky sticky_;
  // LinuxCNC's cycle_il, on the plane's normal, in mm and as LinuxCNC holds
  // it (program units of `unit_` mm); likewise the end point.
  std::optional<double> initial_level_;
  double initial_level_u_ = 0.0;
  Vec3 end_point_;
  Vec3 end_point_u_;
  double unit_ = 1.0;
};

}  // namespace usina::gcode
