// usina job JOB.toml --post P -o part.nc: a whole part from one job file
// (docs/job.md): its operations in order, each with its tool and its speeds
// and feeds, posted for one control.
//
// Exit status: 0; 1 when the job (or its tool library, materials, machine
// profile, drawing) has an error, reported at its line; 2 for a file that
// cannot be read or a bad option.
#include <memory>
#include <string>

#include <fmt/format.h>

#include "cli/post_output.hpp"
#include "cli/verbs.hpp"
#include "core/source.hpp"
#include "job/load.hpp"
#include "job/make.hpp"

namespace usina::cli {
namespace {

struct JobCli {
  std::string file;
  PostOutput output;
};

int run_job(JobCli& o) {
  core::SourceManager sources;
  DiagnosticPrinter diags;
  diags.set_sources(&sources);
  std::string io_error;
  const auto loaded = job::load_job(o.file, sources, diags, io_error);
  if (!io_error.empty()) {
    fmt::print(stderr, "usina: error: {}\n", io_error);
    return 2;
  }
  if (!loaded) return 1;
  // The output may be none of the files the job reads.
  o.output.inputs = {o.file, loaded->job.tools, loaded->job.materials};
  if (!loaded->job.drawing.empty()) o.output.inputs.push_back(loaded->job.drawing);
  if (!loaded->job.machine.empty()) o.output.inputs.push_back(loaded->job.machine);
  return write_program(o.output, [&](canon::Sink& sink, PostDiagnostics& post_diags) {
    post_diags.set_sources(&sources);
    return job::make_job(*loaded, sink, diags) && diags.errors() == 0 ? 0 : 1;
  });
}

}  // namespace

void add_job(CLI::App& app) {
  auto o = std::make_shared<JobCli>();
  CLI::App* cmd = app.add_subcommand(
      "job", "a whole part from a job file: stock, material, tools, operations (docs/job.md)");
  cmd->add_option("JOB", o->file, "the job file (TOML)")->required();
  add_post_options(*cmd, o->output);
  cmd->callback([o] { set_exit_status(run_job(*o)); });
}

}  // namespace usina::cli
