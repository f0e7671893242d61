// How the verbs say diagnostics: on standard error as a compiler does, at
// most --max-errors of each severity (a 50 MB program of errors prints a
// page, not 50 MB), warnings and notes left out with --quiet.
#pragma once

#include <array>
#include <cstdint>

#include <CLI/CLI.hpp>

#include "core/diagnostic.hpp"
#include "core/source.hpp"

namespace usina::cli {

struct DiagnosticOptions {
  bool quiet = false;   // errors only
  long max_shown = 50;  // of each severity; 0: every one
  bool print = true;    // false: only counted and observed (check --format json)
};

void add_diagnostic_options(CLI::App& app, DiagnosticOptions& o);

class DiagnosticPrinter final : public core::DiagnosticSink {
 public:
  explicit DiagnosticPrinter(DiagnosticOptions options = {},
                             core::DiagnosticSink* observer = nullptr)
      : options_(options), observer_(observer) {}

  DiagnosticPrinter(const DiagnosticPrinter&) = delete;
  DiagnosticPrinter& operator=(const DiagnosticPrinter&) = delete;
  // Says how many were not shown.
  ~DiagnosticPrinter() override;

  void set_sources(const core::SourceManager* sources) { sources_ = sources; }

  // Counted, shown within the limits, and always told to the observer.
  void report(core::Diagnostic d) override;

  int errors() const { return static_cast<int>(count(core::Severity::Error)); }

  long count(core::Severity s) const { return counts_[static_cast<std::size_t>(s)]; }

  // Whether a diagnostic of this severity is shown (the observer's rule too).
  static bool within(const DiagnosticOptions& o, core::Severity s, long seen_before);

 private:
  DiagnosticOptions options_;
  core::DiagnosticSink* observer_;
  const core::SourceManager* sources_ = nullptr;
  std::array<long, 3> counts_{};
  std::array<long, 3> hidden_{};
};

}  // namespace usina::cli
