// usina check FILE...: diagnostics only, like a compiler's; exit status 1
// when a program has an error, 2 when one cannot be read (the worst of the
// files). --format json prints them for editors and the web page
// (docs/cli.md).
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/run.hpp"
#include "cli/verbs.hpp"

namespace usina::cli {
namespace {

struct CheckOptions {
  RunOptions run;
  std::vector<std::string> files;
  std::string format = "text";
};

// Keeps the diagnostics --format json shows, within the same limits as the
// text (--max-errors, --quiet).
class JsonDiagnostics final : public core::DiagnosticSink {
 public:
  JsonDiagnostics(const DiagnosticOptions& options, const core::SourceManager*& sources)
      : options_(options), sources_(sources) {}

  void report(core::Diagnostic d) override {
    const auto i = static_cast<std::size_t>(d.severity);
    if (!DiagnosticPrinter::within(options_, d.severity, seen_[i]++)) return;
    const core::SourceFile* f = sources_ != nullptr ? sources_->get(d.loc.file) : nullptr;
    list_.push_back({{"file", f != nullptr ? f->name() : "<input>"},
                     {"line", d.loc.line},
                     {"column", d.loc.col},
                     {"length", d.loc.length},
                     {"severity", core::severity_name(d.severity)},
                     {"code", core::code_name(d.code)},
                     {"message", d.message}});
  }

  nlohmann::ordered_json file_entry(const std::string& file, int status) const {
    return {{"file", file},
            {"status", status},
            {"errors", seen_[static_cast<std::size_t>(core::Severity::Error)]},
            {"warnings", seen_[static_cast<std::size_t>(core::Severity::Warning)]},
            {"diagnostics", list_}};
  }

 private:
  const DiagnosticOptions& options_;
  const core::SourceManager*& sources_;
  std::array<long, 3> seen_{};
  nlohmann::ordered_json list_ = nlohmann::ordered_json::array();
};

int check_text(CheckOptions& o) {
  int worst = 0;
  for (const std::string& file : o.files) {
    o.run.file = file;
    canon::NullSink sink;
    worst = std::max(worst, run_program(o.run, sink));
  }
  return worst;
}

int check_json(CheckOptions& o) {
  o.run.diagnostics.print = false;
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  int worst = 0;
  for (const std::string& file : o.files) {
    o.run.file = file;
    const core::SourceManager* sources = nullptr;
    JsonDiagnostics json(o.run.diagnostics, sources);
    canon::NullSink sink;
    const int status = run_program(
        o.run, sink, [&sources](const core::SourceManager& s) { sources = &s; }, &json);
    files.push_back(json.file_entry(file, status));
    worst = std::max(worst, status);
  }
  // Bytes that are not UTF-8 (a Latin-1 comment) become U+FFFD: the
  // document stays valid JSON.
  fmt::print("{}\n", nlohmann::ordered_json{{"files", files}}.dump(
                         2, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
  return worst;
}

}  // namespace

void add_check(CLI::App& app) {
  auto opts = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand("check", "report programs' errors like a compiler");
  add_run_options(*cmd, opts->run, RunInput::Many);
  cmd->add_option("file", opts->files, "NC programs ('-' reads standard input)")->required();
  cmd->add_option("--format", opts->format,
                  "text (on standard error) or json (on standard output: file, line, column, "
                  "code, severity, message)")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  cmd->callback(
      [opts] { set_exit_status(opts->format == "json" ? check_json(*opts) : check_text(*opts)); });
}

}  // namespace usina::cli
