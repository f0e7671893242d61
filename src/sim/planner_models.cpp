#include "sim/planner_models.hpp"

#include "sim/planner_grbl.hpp"
#include "sim/planner_linuxcnc.hpp"

namespace usina::sim {

std::unique_ptr<MotionPlanner> make_planner(const MachineProfile& machine, std::size_t lookahead) {
  switch (machine.model) {
  case PlannerModel::Linuxcnc: return std::make_unique<LinuxcncPlanner>(machine, lookahead);
  case PlannerModel::Grbl: return std::make_unique<GrblPlanner>(machine);
  case PlannerModel::Textbook: break;
  }
  return std::make_unique<Planner>(PlannerSettings{machine.junction_deviation, lookahead});
}

}  // namespace usina::sim
