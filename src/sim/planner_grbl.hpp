// The "grbl" planner model: grbl 1.1's planner (planner.c): a buffer of
// 16 blocks (15 planned), junction deviation $11 for the corners.
#pragma once

#include <memory>

#include "sim/machine_profile.hpp"
#include "sim/planner.hpp"

namespace usina::sim {

// grbl's BLOCK_BUFFER_SIZE: 16 blocks, one kept free.
inline constexpr std::size_t kGrblBlockBuffer = 15;

std::unique_ptr<MotionPlanner> make_grbl_planner(const MachineProfile& machine);

}  // namespace usina::sim
