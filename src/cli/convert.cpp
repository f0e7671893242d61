// usina convert FILE --post P: a program run through the interpreter and
// written for another control as plain blocks (parametric code, polar words,
// cycles, patterns and subroutines expanded: seed 000's "Parametrizada").
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
  std::string from;
  PostOutput output;
};

// --from is --dialect under the name a conversion reads best with; both
// given must agree, never one silently win.
bool settle_dialect(CLI::App& cmd, ConvertOptions& o) {
  if (o.from.empty()) return true;
  if (cmd.count("--dialect") > 0 && o.run.dialect != o.from) {
    fmt::print(stderr, "usina: error: convert: --from {} and --dialect {} disagree; give one\n",
               o.from, o.run.dialect);
    return false;
  }
  o.run.dialect = o.from;
  return true;
}

}  // namespace

void add_convert(CLI::App& app) {
  auto opts = std::make_shared<ConvertOptions>();
  CLI::App* cmd = app.add_subcommand(
      "convert", "write a program for another control, its parametric code and cycles expanded");
  add_run_options(*cmd, opts->run);
  cmd->add_option("--from", opts->from, "the language of FILE (same as --dialect)")
      ->check(*cmd->get_option("--dialect")->get_validator());
  add_post_options(*cmd, opts->output);
  cmd->callback([opts, cmd] {
    if (!settle_dialect(*cmd, *opts)) return set_exit_status(2);
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
