// usina convert FILE --post P: a program run through the interpreter and
// written for another control as plain blocks (parametric code, polar words,
// cycles, patterns and subroutines expanded: seed 000's "Parametrizada").
#include <memory>

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
  // --from is --dialect under the name a conversion reads best with; it
  // accepts what --dialect accepts.
  cmd->add_option("--from", opts->run.dialect, "the language of FILE (same as --dialect)")
      ->check(*cmd->get_option("--dialect")->get_validator());
  add_post_options(*cmd, opts->output);
  cmd->callback([opts] {
    set_exit_status(write_program(opts->output, [&](canon::Sink& sink, PostDiagnostics& diags) {
      const int status = run_program(
          opts->run, sink, [&diags](const core::SourceManager& s) { diags.set_sources(&s); });
      diags.set_sources(nullptr);
      return status;
    }));
  });
}

}  // namespace usina::cli
