// usina: a workbench for CNC part programs. One file per verb.
#include <CLI/CLI.hpp>

#include "cli/verbs.hpp"

int main(int argc, char** argv) {
  CLI::App app{"usina: see, check and write CNC part programs"};
  app.set_version_flag("--version", std::string("usina ") + USINA_VERSION);
  app.require_subcommand(1);
  usina::cli::add_trace(app);
  usina::cli::add_check(app);
  usina::cli::add_calc(app);
  usina::cli::add_stats(app);
  usina::cli::add_draw(app);
  usina::cli::add_convert(app);
  usina::cli::add_gen(app);
  CLI11_PARSE(app, argc, argv);
  return usina::cli::exit_status();
}
