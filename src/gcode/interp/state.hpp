// The modal state of the RS274NGC interpreter: a value. A block works on a
// copy that replaces the state only when the block succeeded.
#pragma once

#include <array>

#include "canon/op.hpp"
#include "core/arc.hpp"
#include "core/units.hpp"
#include "core/vec3.hpp"

namespace usina::gcode {

using core::Vec2;
using core::Vec3;

// X Y Z A B C U V W: lengths in mm, rotary axes in degrees.
using Axes = std::array<double, 9>;
inline constexpr int kAxisCount = 9;
inline constexpr const char* kAxisLetters = "XYZABCUVW";

inline Vec3 xyz(const Axes& a) {
  return {a[0], a[1], a[2]};
}

inline void set_xyz(Axes& a, const Vec3& v) {
  a[0] = v.x;
  a[1] = v.y;
  a[2] = v.z;
}

// Tool numbers: LinuxCNC's are ints.
inline constexpr int kMaxToolNumber = 2147483646;

// G codes are kept as integers in tenths: G38.2 is 382, G1 is 10, G59.3 is 593.
using GCode = int;

enum class FeedMode { UnitsPerMinute, InverseTime, UnitsPerRev };
enum class CompSideState { Off, Left, Right };
enum class RetractMode { OldZ, RPlane };

struct ModalState {
  GCode motion = 800;  // LinuxCNC starts in G80
  core::Plane plane = core::Plane::XY;
  bool incremental = false;   // G91
  bool arc_absolute = false;  // G90.1
  FeedMode feed_mode = FeedMode::UnitsPerMinute;
  core::LengthUnit units = core::LengthUnit::Mm;
  GCode path_mode = 640;                      // G64
  RetractMode retract = RetractMode::RPlane;  // LinuxCNC starts in G99
  bool css = false;                           // G96
  bool lathe_diameter = false;                // G7
  int coord_system = 1;                       // 1 = G54 ... 9 = G59.3
  bool coord_system_chosen = false;           // a G54-G59.3 word ran (a restart writes it back)
  // The length offset as the program wrote it, for a restart's preamble:
  // G43's H (0 when it gave none: the tool in the spindle), -1 under G49,
  // -2 for G43.1 and G43.2, whose offsets a restart cannot write back.
  int length_h = -1;
  // A G10 ran, or the program wrote a home, G92 or work offset parameter
  // (#5161-#5389): offsets a restart's preamble cannot write back.
  bool offsets_written = false;

  double feed = 0.0;   // mm/min (G94), mm/rev (G95) or 1/min (G93)
  double speed = 0.0;  // rpm, or surface speed under G96
  canon::SpindleDir spindle = canon::SpindleDir::Off;
  bool mist = false;
  bool flood = false;
  int tool = 0;            // in the spindle
  int selected_tool = -1;  // T word
  Axes tool_offset{};      // active tool length offset (G43), mm
  CompSideState comp = CompSideState::Off;

  Axes pos{};                 // current point, program coordinates
  Axes g92{};                 // G92 / G52 offsets
  Axes g5x{};                 // active work offset
  double rotation_deg = 0.0;  // active work offset's XY rotation (G10 L2 R)
  bool feed_override = true;
  bool speed_override = true;
};

}  // namespace usina::gcode
