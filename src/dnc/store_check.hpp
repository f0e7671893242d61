// A revision's check: the program run through the interpreter in its dialect
// into `stats`' sink on the machine class's profile. It records the
// diagnostics, the cycle time, the extent of the tool path and the stats
// checks (travel limits among them). A check *fails* on an error diagnostic
// or on a move past the profile's travel (W_OVERTRAVEL): a program that
// cannot run on its machine class must not be released.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/machine_profile.hpp"

namespace usina::dnc {

struct CheckDiagnostic {
  std::string code;      // "E_ARC_RADIUS_MISMATCH"
  std::string severity;  // "error", "warning", "note"
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::string message;
};

// One tool's share of the program (stats' per-tool figures): the tool-life
// counts multiply it by the parts made.
struct CheckTool {
  int tool = 0;  // 0: the tool in the spindle before the first change
  double cutting_s = 0.0;
  double total_s = 0.0;
};

struct CheckResults {
  std::string dialect;
  std::string machine;    // the profile's name
  bool complete = false;  // the run reached the program's end
  std::uint64_t errors = 0;
  std::uint64_t warnings = 0;
  std::uint64_t overtravel = 0;              // moves past the profile's travel
  std::vector<CheckDiagnostic> diagnostics;  // the first kMaxKeptDiagnostics
  double cycle_time_s = 0.0;
  double cutting_s = 0.0;
  double rapid_s = 0.0;
  std::optional<std::array<double, 6>> bounds;  // x y z min, x y z max, mm
  std::map<std::string, std::uint64_t> checks;  // stats check code → count
  // The tools, in order of first use; nothing for a check stored before the
  // tools were kept (has_tools false).
  std::vector<CheckTool> tools;
  bool has_tools = false;

  static constexpr std::size_t kMaxKeptDiagnostics = 100;

  // What makes a revision check-failed.
  std::uint64_t blocking() const { return errors + overtravel; }

  std::string to_json() const;
  static std::optional<CheckResults> from_json(std::string_view text);
};

struct CheckSettings {
  std::string dialect = "rs274ngc";
  const sim::MachineProfile* profile = nullptr;  // nullptr: stats' generic mill
  std::uint64_t max_ops = 100'000'000;           // canon operations before it stops
};

// Never throws for bad input: an unknown dialect is a result with an error.
CheckResults check_program(std::string_view text, const CheckSettings& settings);

}  // namespace usina::dnc
