#include "cli/run.hpp"

#include <unistd.h>

#include <cstdio>
#include <iterator>

#include <fmt/format.h>

#include "cli/apt_run.hpp"
#include "cli/run_guard.hpp"
#include "cli/validators.hpp"
#include "core/output_file.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"
#include "gcode/dialect_guess.hpp"
#include "gcode/interp/interpreter.hpp"
#include "gcode/var_file.hpp"

namespace usina::cli {

void add_run_options(CLI::App& app, RunOptions& o, RunInput input) {
  if (input == RunInput::One)
    app.add_option("file", o.file, "NC program ('-' reads standard input)")->required();
  std::vector<std::string> dialects;
  for (const gcode::Dialect* d : gcode::all_dialects())
    dialects.emplace_back(d->name);
  dialects.emplace_back("auto");
  app.add_option("--dialect", o.dialect, "the control's language (auto: guessed from the text)")
      ->check(CLI::IsMember(dialects))
      ->each([&o](const std::string&) { o.dialect_given = true; })
      ->capture_default_str();
  std::vector<std::string> languages = dialects;
  for (const std::string_view l : kClLanguages)
    languages.emplace_back(l);
  app.add_option("--from", o.from,
                 "the language of the file: a dialect (as --dialect), apt (an APT part program), "
                 "clsf (NX CLSF), aptcl (APT CL of SolidWorks CAM, Creo), cldata (binary CLDATA); "
                 "default: the file's extension says (.apt, .cls, .clsf, .ncl, .cldata), else "
                 "--dialect")
      ->check(CLI::IsMember(languages));
  app.add_option("--dialect-option", o.dialect_options,
                 "name=value: an open choice of the dialect (repeatable; docs/dialects.md)");
  app.add_option("--tool-table", o.tool_table, "LinuxCNC tool table (lengths in machine units)");
  app.add_option(
         "--machine-units", o.machine_units,
         "units of the machine: of the tool table and stored parameters (programs start in G21)")
      ->check(CLI::IsMember({"mm", "inch"}))
      ->capture_default_str();
  app.add_option("--offsets", o.offsets,
                 "fanuc: the offset page (H and D registers) as a TOML file (docs/fanuc.md)");
  app.add_option("--var-file", o.var_file, "LinuxCNC parameter file to start from");
  app.add_option("--save-vars", o.save_vars,
                 "write the persistent variables here at the end of the run (rs274ngc: "
                 "LinuxCNC's 5161-5390; fanuc: #500-#999), also after an error");
  app.add_option(
      "--subroutine-path", o.subroutine_path,
      "folders searched for o<name> call files, separated by ':' (then the program's own)");
  app.add_option("--peck-clearance", o.peck_clearance, "G73/G83 retract above the last peck, mm")
      ->check(kFinite & CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  app.add_option("--max-iterations", o.max_iterations,
                 "iterations a loop may run before it is an error")
      ->check(CLI::Range(1L, 1'000'000'000'000L))
      ->capture_default_str();
  app.add_option("--max-total-iterations", o.max_total_iterations,
                 "loop iterations all loops together may run before it is an error")
      ->check(CLI::Range(1L, 1'000'000'000'000L))
      ->capture_default_str();
  app.add_option("--max-ops", o.max_ops,
                 "operations (moves, arcs, tool changes, ...) one run may produce before it is "
                 "stopped with an error")
      ->check(CLI::Range(1LL, 1'000'000'000'000LL))
      ->capture_default_str();
  app.add_flag("--block-delete", o.block_delete,
               "skip the blocks that start with '/' (the switch on)");
  add_diagnostic_options(app, o.diagnostics);
}

std::vector<std::string> input_paths(const RunOptions& o) {
  return {o.file, o.tool_table, o.var_file, o.offsets};
}

namespace {

// What a pipe (standard input, /dev/stdin, a shell's <(...)) may hold: a
// file is mapped and has no such bound.
constexpr std::uint64_t kMaxStreamedInput = 1ull << 30;

std::unique_ptr<core::SourceFile> open_input(const std::string& path) {
  std::string err;
  auto f = path == "-"
               ? core::SourceFile::open_descriptor(STDIN_FILENO, "<stdin>", err, kMaxStreamedInput)
               : core::SourceFile::open(path, err, kMaxStreamedInput);
  if (!f) fmt::print(stderr, "usina: error: cannot read {}: {}\n", path, err);
  return f;
}

std::vector<std::string> split_path(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size() && !s.empty()) {
    const std::size_t end = s.find(':', start);
    out.push_back(s.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

// The parameter file the run started from may be written back (LinuxCNC
// keeps its parameter file so); no other input may.
std::vector<std::string> save_vars_inputs(const RunOptions& o) {
  std::vector<std::string> inputs = input_paths(o);
  std::erase(inputs, o.var_file);
  return inputs;
}

bool save_vars(const RunOptions& o, const std::vector<gcode::VarFileEntry>& entries) {
  const auto written =
      core::write_file(o.save_vars, gcode::write_var_file(entries), save_vars_inputs(o));
  if (!written) fmt::print(stderr, "usina: error: --save-vars: {}\n", written.error());
  return static_cast<bool>(written);
}

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

}  // namespace

int run_program(const RunOptions& o, canon::Sink& sink,
                const std::function<void(const core::SourceManager&)>& on_sources,
                core::DiagnosticSink* observer) {
  // --from names a dialect as --dialect does: both given must agree, never one silently win.
  if (!o.from.empty() && o.dialect_given && o.from != o.dialect) {
    fmt::print(stderr, "usina: error: --from {} and --dialect {} disagree; give one\n", o.from,
               o.dialect);
    return 2;
  }
  if (!o.save_vars.empty()) {
    for (const std::string& input : save_vars_inputs(o)) {
      if (auto ok = core::check_not_input(o.save_vars, input); !ok) {
        fmt::print(stderr, "usina: error: --save-vars: {}\n", ok.error());
        return 2;
      }
    }
  }
  core::SourceManager sources;
  if (on_sources) on_sources(sources);
  DiagnosticPrinter diags(o.diagnostics, observer);
  diags.set_sources(&sources);
  auto program = open_input(o.file);
  if (!program) return 2;
  const std::uint32_t main_id = sources.add(std::move(program));
  // An APT part program or a CL file (issue 15, docs/apt.md): their readers' road.
  const ProgramLanguage language = program_language(o.from, o.file == "-" ? "" : o.file);
  if (language != ProgramLanguage::Gcode)
    return run_apt_program(sources, main_id, language, o.machine_units == "inch" ? 25.4 : 1.0, sink,
                           diags, static_cast<std::uint64_t>(o.max_ops));
  std::string name = o.from.empty() ? o.dialect : o.from;
  if (name == "auto") {
    const gcode::DialectGuess guess =
        gcode::guess_dialect(sources.get(main_id)->text(), o.file == "-" ? "" : o.file);
    name = std::string(guess.dialect);
    if (gcode::find_dialect(name) == nullptr) name = "rs274ngc";
    if (!o.diagnostics.quiet && o.diagnostics.print)
      fmt::print(stderr, "usina: note: --dialect auto chose {} ({}) [N_DIALECT_GUESS]\n", name,
                 guess.reason);
  }
  const gcode::Dialect* dialect = gcode::find_dialect(name);
  if (dialect == nullptr) {
    fmt::print(stderr, "usina: error: unknown dialect {}\n", name);
    return 2;
  }
  auto resolved = gcode::resolve_options(*dialect, o.dialect_options);
  if (!resolved) {
    fmt::print(stderr, "usina: error: {}\n", resolved.error());
    return 2;
  }
  gcode::OptionValues dialect_options = std::move(*resolved);

  if (!o.offsets.empty() && name != "fanuc") {
    fmt::print(stderr,
               "usina: error: --offsets is the fanuc dialect's offset page; the {} dialect takes "
               "tool lengths and diameters from --tool-table\n",
               name);
    return 2;
  }
  // The fanuc dialect's offset page (docs/fanuc.md): its own input.
  if (!o.offsets.empty()) dialect_options["offsets"] = o.offsets;
  gcode::InterpOptions opts;
  opts.machine_units = o.machine_units == "inch" ? core::LengthUnit::Inch : core::LengthUnit::Mm;
  opts.peck_clearance_mm = o.peck_clearance;
  opts.max_loop_iterations = o.max_iterations;
  opts.max_total_iterations = o.max_total_iterations;
  opts.block_delete = o.block_delete;
  opts.ignore_cutter_comp = o.ignore_cutter_comp;
  opts.start = o.start;
  opts.subroutine_path = split_path(o.subroutine_path);
  if (o.file != "-") opts.subroutine_path.push_back(folder_of(o.file));

  if (!o.tool_table.empty()) {
    auto f = open_input(o.tool_table);
    if (!f) return 2;
    const std::uint32_t id = sources.add(std::move(f));
    auto table =
        gcode::read_tool_table(*sources.get(id), id, core::mm_per(opts.machine_units), diags);
    if (!table) return 2;
    opts.tools = std::move(*table);
  }
  std::vector<gcode::VarFileEntry> vars;
  if (!o.var_file.empty()) {
    auto f = open_input(o.var_file);
    if (!f) return 2;
    const std::uint32_t id = sources.add(std::move(f));
    auto read = gcode::read_var_file(*sources.get(id), id, diags);
    if (!read) return 2;
    vars = std::move(*read);
  }
  RunGuard guard(sink, diags, static_cast<std::uint64_t>(o.max_ops));  // --max-ops, progress
  auto runner = dialect->make_runner(gcode::RunContext{
      sources, std::move(opts), std::move(dialect_options), guard.sink(), guard.diags()});
  for (const auto& v : vars)
    runner->set_parameter(v.number, v.value);
  if (!o.save_vars.empty() && !runner->persistent_variables()) {
    fmt::print(stderr, "usina: error: --save-vars: the {} dialect keeps no variables\n", name);
    return 2;
  }
  const bool ok = runner->run(main_id);
  guard.flush();
  if (!o.save_vars.empty() && !save_vars(o, *runner->persistent_variables())) return 2;
  return ok && diags.errors() == 0 ? 0 : 1;
}

}  // namespace usina::cli
