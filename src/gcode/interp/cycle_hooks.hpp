// The narrow interface through which the interpreter's canned cycles talk
// to a dialect that keeps cycle state of its own (the fanuc dialect):
// the machine settings a program may change as it runs, asked at each cycle
// block, and the initial level a cycle took, told after it ran. A dialect
// whose cycles are LinuxCNC's gives none: InterpOptions::peck_clearance_mm
// holds.
#pragma once

namespace usina::gcode {

struct PeckDistances {
  double g73_retract_mm = 1.0;    // G73 backs off this far after each peck
  double g83_clearance_mm = 1.0;  // G83 stops this far above the last peck
};

class CycleHooks {
 public:
  virtual ~CycleHooks() = default;
  // The distances in force now (Fanuc parameters 5114 and 5115, which a
  // program sets with G10 L50; LinuxCNC has one fixed clearance).
  virtual PeckDistances peck_distances() const = 0;
  // A drilling cycle ran. `initial_level_mm`: where it returns under G98,
  // and where G91's R counts from (LinuxCNC's cycle_il), on the plane's
  // normal axis; the interpreter keeps it until a motion that is not a
  // drilling cycle (G0-G3, G80, ...), i.e. while its motion mode is one.
  virtual void cycle_ran(double initial_level_mm) = 0;
};

}  // namespace usina::gcode
