// What stands between a run and the verb's sink: the operation budget
// (--max-ops, E_TOO_MANY_OPERATIONS) and, when standard error is a
// terminal, a progress line for a long run, erased before each diagnostic
// and at the end. Nothing is shown when standard error is a file or a pipe.
#pragma once

#include <cstdint>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"

namespace usina::cli {

class RunGuard {
 public:
  RunGuard(canon::Sink& sink, core::DiagnosticSink& diags, std::uint64_t max_ops);

  // What the runner is given in place of the verb's sink and diagnostics.
  canon::Sink& sink() { return progress_; }

  core::DiagnosticSink& diags() { return diags_; }

 private:
  // Erases the progress line before a diagnostic is printed.
  class Diagnostics final : public core::DiagnosticSink {
   public:
    Diagnostics(core::DiagnosticSink& next, canon::ProgressSink& progress)
        : next_(next), progress_(progress) {}

    void report(core::Diagnostic d) override;

   private:
    core::DiagnosticSink& next_;
    canon::ProgressSink& progress_;
  };

  canon::OpBudget budget_;
  canon::ProgressSink progress_;
  Diagnostics diags_;
};

}  // namespace usina::cli
