// What the interpreter's machining modules (canned cycles, cutter radius
// compensation) drive: moves in program coordinates, mm, in the current work
// coordinate system (before G92, rotation and G5x offsets, which the
// interpreter applies when it turns them into canon ops). Like LinuxCNC's
// canonical machining functions, seen from inside the interpreter.
#pragma once

#include <optional>
#include <string>

#include "canon/op.hpp"
#include "core/diagnostic.hpp"
#include "core/vec3.hpp"
#include "gcode/interp/interp_error.hpp"

namespace usina::gcode {

using core::Vec2;
using core::Vec3;

class MotionTarget {
 public:
  virtual ~MotionTarget() = default;
  virtual void traverse(const Vec3& to) = 0;
  // A straight move at the current feed rate.
  virtual void feed(const Vec3& to) = 0;
  // An arc in the active plane: `center` is in program coordinates (its axial
  // coordinate is ignored), `turn` > 0 counter-clockwise (RS274NGC: G3),
  // < 0 clockwise, |turn| − 1 extra full turns; the axial part of `to` makes a helix.
  virtual void arc(const Vec3& to, const Vec3& center, int turn) = 0;
  virtual void dwell(double seconds) = 0;
  virtual void spindle(canon::SpindleDir dir) = 0;
  // A drilled hole (feature): centre at the top (R plane) and depth below it.
  virtual void hole(const Vec3& top, double depth) = 0;
  // Where the tool is now, program coordinates.
  virtual Vec3 position() const = 0;
  // Later moves are attributed to this block (compensation emits queued
  // moves of earlier blocks).
  virtual void set_source(const core::SourceLoc& loc) = 0;
};

}  // namespace usina::gcode
