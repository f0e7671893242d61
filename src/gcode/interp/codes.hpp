// The G and M codes of RS274NGC (LinuxCNC) and their modal groups.
#pragma once

#include <array>
#include <cstdint>

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

// The modal group of a G code (in tenths), or -1 when usina does not know it.
int g_group(GCode g);
// The modal group of an M code, or -1.
int m_group(int m);
// "G38.2" for 382.
std::array<char, 32> g_name(GCode g);

}  // namespace usina::gcode
