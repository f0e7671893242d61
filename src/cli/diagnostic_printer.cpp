#include "cli/diagnostic_printer.hpp"

#include <cstdio>
#include <string>

#include <fmt/format.h>

namespace usina::cli {

void add_diagnostic_options(CLI::App& app, DiagnosticOptions& o) {
  app.add_flag("-q,--quiet", o.quiet, "say errors only: no warnings, no notes");
  app.add_option("--max-errors", o.max_shown,
                 "show at most N errors, N warnings and N notes (0: all); the rest are counted")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

bool DiagnosticPrinter::within(const DiagnosticOptions& o, core::Severity s, long seen_before) {
  if (o.quiet && s != core::Severity::Error) return false;
  return o.max_shown == 0 || seen_before < o.max_shown;
}

void DiagnosticPrinter::report(core::Diagnostic d) {
  const auto i = static_cast<std::size_t>(d.severity);
  const long before = counts_[i]++;
  if (!within(options_, d.severity, before)) {
    if (!options_.quiet || d.severity == core::Severity::Error) ++hidden_[i];
  } else if (options_.print) {
    static const core::SourceManager kNone;
    const std::string text = core::render(d, sources_ != nullptr ? *sources_ : kNone);
    std::fwrite(text.data(), 1, text.size(), stderr);
  }
  if (observer_ != nullptr) observer_->report(std::move(d));
}

DiagnosticPrinter::~DiagnosticPrinter() {
  const auto e = hidden_[static_cast<std::size_t>(core::Severity::Error)];
  const auto w = hidden_[static_cast<std::size_t>(core::Severity::Warning)];
  const auto n = hidden_[static_cast<std::size_t>(core::Severity::Note)];
  if (!options_.print || e + w + n == 0) return;
  fmt::print(stderr,
             "usina: note: not shown: {} more error(s), {} warning(s), {} note(s) "
             "(--max-errors {}; 0 shows all)\n",
             e, w, n, options_.max_shown);
}

}  // namespace usina::cli
