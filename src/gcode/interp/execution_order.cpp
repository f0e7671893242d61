#include "gcode/interp/execution_order.hpp"

#include <array>
#include <stdexcept>

#include <fmt/format.h>

namespace usina::gcode {
namespace {

constexpr std::array<std::string_view, kExecSteps> kNames = {
    "comments",
    "feed mode",
    "feed",
    "spindle mode",
    "speed",
    "select tool",
    "change tool",
    "spindle",
    "coolant",
    "overrides",
    "user M codes",
    "dwell",
    "modal state",
    "plane",
    "units",
    "lathe mode",
    "cutter compensation",
    "tool length",
    "coordinate system",
    "path control",
    "distance mode",
    "arc distance",
    "retract mode",
    "non-modal codes",
    "motion",
    "resync",
    "subprogram",
    "stop",
};

}  // namespace

const ExecutionOrder& linuxcnc_execution_order() {
  static const ExecutionOrder kOrder{"rs274ngc", kLinuxcncOrder};
  return kOrder;
}

std::string_view step_name(ExecStep step) {
  return kNames[static_cast<std::size_t>(step)];
}

void check_execution_order(const ExecutionOrder& order) {
  std::array<int, kExecSteps> seen{};
  for (const ExecStep s : order.steps) {
    const auto i = static_cast<std::size_t>(s);
    if (i >= seen.size()) {
      throw std::logic_error(fmt::format("{} execution order: step {} is not a step", order.dialect,
                                         static_cast<int>(i)));
    }
    ++seen[i];
  }
  for (std::size_t i = 0; i < seen.size(); ++i) {
    if (seen[i] != 1) {
      throw std::logic_error(fmt::format("{} execution order: '{}' appears {} times, not once",
                                         order.dialect, kNames[i], seen[i]));
    }
  }
}

}  // namespace usina::gcode
