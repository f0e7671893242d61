// The modal state of the romi dialect: a value (DESIGN.md, "Inside the gcode
// front end"). A block works on a copy that replaces the state only when the
// block succeeded (grbl's gc_execute_line: copy, import and check the words,
// execute, commit), so a failed block changes no mode, and "run from block
// N" or a look-ahead is a copy.
//
// The ops a block sent before its error stay sent, as a control's moves
// stay made: the state rolls back, the canon stream does not.
#pragma once

#include <optional>

#include "core/diagnostic.hpp"
#include "core/units.hpp"
#include "gcode/interp/state.hpp"

namespace usina::gcode::romi {

// Mirror, scale, rotation: applied to a programmed point in the order
// rotation, scale, mirror (spec/romi.md, "Transformations").
struct Transform {
  bool mirror_x = false;  // X coordinates flip about X = mirror_at.x
  bool mirror_y = false;
  Vec2 mirror_at;
  double scale_x = 1.0;
  double scale_y = 1.0;
  double rotation_deg = 0.0;
  Vec2 rotation_at;

  Vec2 apply(Vec2 p) const;

  Vec3 apply(const Vec3& p) const {
    const Vec2 q = apply(Vec2{p.x, p.y});
    return {q.x, q.y, p.z};
  }

  // One axis mirrored: arcs and compensation sides swap.
  bool flips() const { return mirror_x != mirror_y; }

  bool uniform() const { return scale_x == scale_y; }
};

// G81, modal until G80.
struct DrillCycle {
  bool active = false;
  double r = 0.0;      // approach plane above the work surface, mm
  double depth = 0.0;  // below the surface, mm
  double dwell = 0.0;  // s
  bool defined = false;
};

// An arc with only R: it blends into the next block's move, which decides
// where it ends.
struct PendingBlend {
  core::SourceLoc loc;
  Vec2 center;
  double radius = 0.0;
  bool ccw = true;
  Vec3 start;
};

// The direction of travel at the programmed point, for the tangent arcs
// (R C, R A, R alone). A straight move leaves its step and the angle is
// worked out only when an arc asks: an arctangent per move was a twentieth
// of a long program's run (issue 19).
class Heading {
 public:
  void set_step(Vec2 step) {
    known_ = true;
    step_ = step;
    angle_.reset();
  }

  void set_degrees(double degrees) {
    known_ = true;
    angle_ = degrees;
  }

  // std::nullopt before the first move; the angle in degrees after it.
  std::optional<double> degrees() const;

 private:
  bool known_ = false;
  Vec2 step_;
  std::optional<double> angle_;
};

// The modes a romi program reads its words by, in the interpreter's words
// (GCode tenths, RetractMode): romi's own, since the interpreter is handed
// absolute millimetres.
struct Modes {
  GCode motion = 0;                               // G00-G03 in tenths
  bool incremental = false;                       // G91
  core::LengthUnit units = core::LengthUnit::Mm;  // G70/G71
  RetractMode retract = RetractMode::RPlane;      // G98/G99
  double feed = 0.0;                              // mm/min
  double speed = 0.0;                             // rpm
  int selected_tool = -1;                         // T
  int tool = 0;                                   // in the spindle
};

// The RS274NGC interpreter below the front end runs the machine (its
// position, tool, spindle, coolant and cutter compensation, its own state a
// value too); this is romi's part.
struct Modal {
  // Program coordinates.
  DrillCycle drill;
  Transform tf;
  int offset_register = 0;     // O
  Vec3 pos;                    // the programmed point
  Vec3 machine_at;             // where the last move handed over ended (transformed)
  Heading direction;           // of travel at pos
  double tool_diameter = 0.0;  // of the tool in the spindle
  std::optional<PendingBlend> blend;

  Modes machine;
  // G41/G42 in force (the interpreter holds the compensation itself).
  bool comp_on = false;

  // G00..G03: 0..3.
  int motion() const { return machine.motion / 10; }

  double mm(double v) const { return v * core::mm_per(machine.units); }
};

}  // namespace usina::gcode::romi
