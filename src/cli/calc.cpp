// usina calc: the positioning and cutting calculators of seed 004 (issue 6).
#include "cli/verbs.hpp"

namespace usina::cli {

void add_calc(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("calc", "positioning and cutting calculators (seed 004, 7.5)");
  cmd->require_subcommand(1);
}

}  // namespace usina::cli
