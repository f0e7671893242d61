// The order in which the interpreter runs the parts of a block (step 4):
// table data a dialect gives (DialectRules::order), as its G/M table is,
// not an order written into the interpreter's code.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace usina::gcode {

// The parts of a block the interpreter runs, each once, in its dialect's
// order. A part does nothing when the block has none of its words.
enum class ExecStep : std::uint8_t {
  Comments,     // (MSG,...) and every comment, as canon comments
  FeedMode,     // G93 G94 G95
  Feed,         // F (and the feed op, when F or the mode changed)
  SpindleMode,  // G96 G97
  Speed,        // S
  SelectTool,   // T
  ChangeTool,   // M6 M61
  Spindle,      // M3 M4 M5
  Coolant,      // M7 M8 M9
  Overrides,    // M48 M49 M50 M51
  UserM,        // M100-M199 (and the machine's M codes a dialect passes on)
  Dwell,        // G4
  ModalState,   // M70 M71 M72 M73
  Plane,        // G17 G18 G19 (and their variants)
  Units,        // G20 G21
  LatheMode,    // G7 G8
  CutterComp,   // G40 G41 G42 (G41.1 G42.1)
  ToolLength,   // G43 G43.1 G43.2 G49
  CoordSystem,  // G54-G59.3
  PathControl,  // G61 G61.1 G64
  Distance,     // G90 G91
  ArcDistance,  // G90.1 G91.1
  Retract,      // G98 G99
  NonModal,     // G10 G28 G28.1 G30 G30.1 G52 G92 G92.1 G92.2 G92.3
  Motion,       // the block's move or cycle (G0-G3, G33, G38.n, G73-G89, splines)
  Resync,       // after a tool change: the position read back from the machine
  Subprogram,   // M98 M99
  Stop,         // M0 M1 M60 M2 M30
};

inline constexpr int kExecSteps = static_cast<int>(ExecStep::Stop) + 1;

// A dialect's order: every step exactly once (check_execution_order).
struct ExecutionOrder {
  std::string_view dialect;
  std::span<const ExecStep> steps;
};

// LinuxCNC's execute_block order (interp_execute.cc): comments; feed
// mode, F, S, T; convert_m (tool change, spindle, coolant, overrides, user
// M codes); convert_g (dwell, plane, units, lathe mode, compensation, tool
// length, coordinate system, path control, distance modes, retract, the
// non-modal codes, motion); convert_stop. M70-M73 run before the G codes,
// as usina has always run them; M98/M99 (fanuc's calls) after the move.
// A constant, so that the interpreter can run it without a dispatch per
// step (execute.cpp).
inline constexpr std::array<ExecStep, kExecSteps> kLinuxcncOrder = {
    ExecStep::Comments,   ExecStep::FeedMode,    ExecStep::Feed,        ExecStep::SpindleMode,
    ExecStep::Speed,      ExecStep::SelectTool,  ExecStep::ChangeTool,  ExecStep::Spindle,
    ExecStep::Coolant,    ExecStep::Overrides,   ExecStep::UserM,       ExecStep::Dwell,
    ExecStep::ModalState, ExecStep::Plane,       ExecStep::Units,       ExecStep::LatheMode,
    ExecStep::CutterComp, ExecStep::ToolLength,  ExecStep::CoordSystem, ExecStep::PathControl,
    ExecStep::Distance,   ExecStep::ArcDistance, ExecStep::Retract,     ExecStep::NonModal,
    ExecStep::Motion,     ExecStep::Resync,      ExecStep::Subprogram,  ExecStep::Stop,
};

// kLinuxcncOrder as the rs274ngc dialect's order (and the controls that
// run on its interpreter: fanuc, grbl).
const ExecutionOrder& linuxcnc_execution_order();

// "feed mode", "change tool": a step as the docs and messages name it.
std::string_view step_name(ExecStep step);

// Throws std::logic_error when `order` misses a step or names one twice:
// the dialect's table is wrong (a programming error, as for its G/M table).
void check_execution_order(const ExecutionOrder& order);

}  // namespace usina::gcode
