// The interpreter's G/M tables: LinuxCNC's modal groups, how a code of
// the table is run, and the rs274ngc table (rs274ngc/codes.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "gcode/code_table.hpp"
#include "gcode/interp/state.hpp"

namespace usina::gcode {

// Modal groups, numbered as LinuxCNC numbers them.
inline constexpr int kGroupNonModal = 0;
inline constexpr int kGroupMotion = 1;
inline constexpr int kGroupPlane = 2;
inline constexpr int kGroupDistance = 3;
inline constexpr int kGroupArcDistance = 4;
inline constexpr int kGroupFeedMode = 5;
inline constexpr int kGroupUnits = 6;
inline constexpr int kGroupCutterComp = 7;
inline constexpr int kGroupToolLength = 8;
inline constexpr int kGroupRetract = 10;
inline constexpr int kGroupCoordSystem = 12;
inline constexpr int kGroupPathControl = 13;
inline constexpr int kGroupSpindleMode = 14;
inline constexpr int kGroupLathe = 15;
inline constexpr int kGGroups = 16;

inline constexpr int kMGroupStop = 4;
inline constexpr int kMGroupIo = 5;
inline constexpr int kMGroupToolChange = 6;
inline constexpr int kMGroupSpindle = 7;
inline constexpr int kMGroupCoolant = 8;
inline constexpr int kMGroupOverride = 9;
inline constexpr int kMGroupUser = 10;
inline constexpr int kMGroupModalState = 11;
inline constexpr int kMGroupSubprogram = 12;
inline constexpr int kMGroups = 13;

// How the interpreter runs a code of its dialect's table (the handler
// names of the rs274ngc and fanuc tables).
enum class CodeRun : std::uint8_t {
  None,         // no such handler: the table is wrong
  GroupStep,    // "group_step": in its group's step of LinuxCNC's execute_block order
  UserM,        // "user_m": a user M code (M100-M199), in the block's order
  Unsupported,  // "unsupported": a code of the control usina cannot run (CodeEntry::what)
};

CodeRun code_run_named(std::string_view handler);

// The interpreter's tables hold G0 to G999.9 and M0 to M999; a larger
// number is no code of theirs.
inline constexpr int kMaxCodeTenths = 9999;

using InterpCodes = CodeTable<CodeRun>;

// A dialect's table resolved for the interpreter (kept by the dialect: the
// result points into `codes`). A group out of the interpreter's range or an
// unknown handler is a programming error (std::logic_error).
InterpCodes interp_code_table(std::string_view dialect, const std::vector<CodeEntry>& codes);

// LinuxCNC's codes (rs274ngc/codes.cpp): the rs274ngc dialect's table and
// the start of fanuc's.
std::vector<CodeEntry> linuxcnc_codes();
// The rs274ngc dialect's table resolved: the interpreter's unless its
// dialect gives another (DialectRules::codes).
const InterpCodes& rs274ngc_code_table();
// "G38.2" for 382.
std::array<char, 32> g_name(GCode g);

}  // namespace usina::gcode
