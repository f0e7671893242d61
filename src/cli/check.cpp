// usina check FILE: diagnostics only; exit status 1 when the program has an error.
#include <memory>

#include "cli/run.hpp"
#include "cli/verbs.hpp"

namespace usina::cli {

void add_check(CLI::App& app) {
  auto opts = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("check", "report a program's errors like a compiler");
  add_run_options(*cmd, *opts);
  cmd->callback([opts] {
    canon::NullSink sink;
    set_exit_status(run_program(*opts, sink));
  });
}

}  // namespace usina::cli
