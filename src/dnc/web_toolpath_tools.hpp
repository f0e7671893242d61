// The figures of each tool of a revision, for the program page's figures
// (docs/web.md, "The figures"): `usina stats`'s per-tool times and distances,
// on the profile of the program's machine class as the check times it. The
// check's results keep the totals only; this is the breakdown, computed on
// the tool-path service's pool and cached there like the stream.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "sim/machine_profile.hpp"
#include "sim/stats.hpp"

namespace usina::dnc {

struct ToolFiguresSettings {
  std::string dialect = "rs274ngc";
  sim::MachineProfile profile = sim::default_machine_profile();  // or the machine class's
  std::uint64_t max_ops = 100'000'000;                           // canon operations, as the check
};

// {"machine", "complete", "tools": [{"tool", "total_s", "cutting_s",
// "rapid_s", "other_s", "cutting_mm", "rapid_mm", "moves"}...], "total": {...}},
// the tools in the order of first use.
std::string tool_figures_json(std::string_view text, const ToolFiguresSettings& settings);

}  // namespace usina::dnc
