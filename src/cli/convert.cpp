// usina convert FILE --post P: a program run through the interpreter and
// written for another control as plain blocks (parametric code, polar words,
// cycles, patterns and subroutines expanded: seed 000's "Parametrizada").
// --from (a run option) names FILE's language: a dialect, or an APT program
// or CL file.
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/post_output.hpp"
#include "cli/run.hpp"
#include "cli/verbs.hpp"

namespace usina::cli {
namespace {

struct ConvertOptions {
  RunOptions run;
  PostOutput output;
};

}  // namespace

void add_convert(CLI::App& app) {
  auto opts = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand(
      "convert", "write a program for another control, its parametric code and cycles expanded");
  add_run_options(*cmd, opts->run);
  add_post_options(*cmd, opts->output);
  cmd->callback([opts] {
    opts->output.inputs = input_paths(opts->run);
    set_exit_status(write_program(opts->output, [&](canon::Sink& sink, PostDiagnostics& diags) {
      const int status = run_program(
          opts->run, sink, [&diags](const core::SourceManager& s) { diags.set_sources(&s); });
      diags.set_sources(nullptr);
      return status;
    }));
  });
}

}  // namespace usina::cli
