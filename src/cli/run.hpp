// What the verbs that interpret a program share: the options (dialect,
// tool table, units, parameter file, subroutine path) and one run.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "canon/sink.hpp"
#include "cli/diagnostic_printer.hpp"
#include "core/source.hpp"
#include "core/vec3.hpp"

namespace usina::cli {

struct RunOptions {
  std::string file;
  std::string dialect = "rs274ngc";
  bool dialect_given = false;  // --dialect was on the command line
  // --from: a G-code dialect (as --dialect), or apt, clsf, aptcl, cldata
  // (docs/apt.md); empty: the file's extension says (.apt, .cls ...).
  std::string from;
  std::vector<std::string> dialect_options;  // name=value
  std::string tool_table;
  std::string machine_units = "mm";
  std::string var_file;
  std::string save_vars;  // the persistent variables written here at the end
  std::string offsets;    // fanuc offset registers
  std::string subroutine_path;
  double peck_clearance = 1.0;
  long max_iterations = 10'000'000;
  long max_total_iterations = 10'000'000;
  long long max_ops = canon::OpBudget::kDefaultMaxOps;  // canon operations one run may produce
  bool block_delete = false;
  DiagnosticOptions diagnostics;
  bool ignore_cutter_comp = false;  // set by a verb (draw --view part), not a flag
  core::Vec3 start{};               // set by a verb (draw --start), not a run option
};

// One: the FILE positional is added; Many: the verb adds its own (check).
enum class RunInput { One, Many };

void add_run_options(CLI::App& app, RunOptions& o, RunInput input = RunInput::One);

// The files a run reads that were named on the command line (an output may
// not be one of them).
std::vector<std::string> input_paths(const RunOptions& o);

// Interprets the program into `sink`, printing diagnostics to stderr.
// Returns the exit status: 0, 1 when the program has an error, 2 when the
// input cannot be read.
// `on_sources` is told the run's sources before the program runs (a trace
// writer names subroutine files with them).
// `observer`, when given, is told every diagnostic of the run too (stats
// lists them in its JSON).
int run_program(const RunOptions& o, canon::Sink& sink,
                const std::function<void(const core::SourceManager&)>& on_sources = {},
                core::DiagnosticSink* observer = nullptr);

}  // namespace usina::cli
