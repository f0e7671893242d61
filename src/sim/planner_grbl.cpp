#include "sim/planner_grbl.hpp"

namespace usina::sim {

// planner.c plans the buffered blocks with junction deviation as the
// textbook model does (sim/planner.hpp, whose rules are grbl's), but over
// 16 blocks only: a program of short moves cannot reach the speed a deeper
// look-ahead would allow.
std::unique_ptr<MotionPlanner> make_grbl_planner(const MachineProfile& machine) {
  return std::make_unique<Planner>(PlannerSettings{machine.junction_deviation, kGrblBlockBuffer});
}

}  // namespace usina::sim
