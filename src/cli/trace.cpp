// usina trace FILE: the canonical operations of a program (spec/trace.md).
#include <cstdio>
#include <memory>

#include "canon/trace_writer.hpp"
#include "cli/run.hpp"
#include "cli/verbs.hpp"

namespace usina::cli {
namespace {

int status = 0;

struct TraceOptions {
  RunOptions run;
  std::string format = "jsonl";
};

}  // namespace

int exit_status() {
  return status;
}

void set_exit_status(int s) {
  status = s;
}

void add_trace(CLI::App& app) {
  auto opts = std::make_shared<TraceOptions>();
  CLI::App* cmd = app.add_subcommand("trace", "print the canonical operations of a program");
  add_run_options(*cmd, opts->run);
  cmd->add_option("--format", opts->format, "jsonl (one operation a line, JSON) or text")
      ->check(CLI::IsMember({"jsonl", "text"}))
      ->capture_default_str();
  cmd->callback([opts] {
    canon::TraceWriter writer(
        stdout, opts->format == "text" ? canon::TraceFormat::Text : canon::TraceFormat::Jsonl);
    set_exit_status(run_program(opts->run, writer, [&writer](const core::SourceManager& sources) {
      writer.set_sources(&sources);
    }));
  });
}

}  // namespace usina::cli
