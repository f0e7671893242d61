// The planner model a machine profile names ([planner] model): "textbook"
// (sim/planner.hpp, the default), "linuxcnc" (sim/planner_linuxcnc.hpp),
// "grbl" (sim/planner_grbl.hpp).
#pragma once

#include <cstddef>
#include <memory>

#include "sim/machine_profile.hpp"
#include "sim/planner.hpp"

namespace usina::sim {

// `lookahead`: blocks in the textbook model's buffer (the others have their own).
std::unique_ptr<MotionPlanner> make_planner(const MachineProfile& machine, std::size_t lookahead);

}  // namespace usina::sim
