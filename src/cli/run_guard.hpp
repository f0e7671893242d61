// What stands between a run and the verb's sink: the operation budget
// (--max-ops, E_TOO_MANY_OPERATIONS), a batch of ops (canon/batch_sink.hpp,
// handed on before each diagnostic) and, when standard error is a
// terminal, a progress line for a long run, erased before each diagnostic
// and at the end. Nothing is shown when standard error is a file or a pipe.
#pragma once

#include <cstdint>

#include "canon/batch_sink.hpp"
#include "canon/sink.hpp"
#include "core/diagnostic.hpp"

namespace usina::cli {

class RunGuard {
 public:
  RunGuard(canon::Sink& sink, core::DiagnosticSink& diags, std::uint64_t max_ops);

  // What the runner is given in place of the verb's sink and diagnostics.
  canon::Sink& sink() { return progress_; }

  core::DiagnosticSink& diags() { return diags_; }

  // Hands the ops held on to the verb's sink: after the run, before the
  // verb reads its sink.
  void flush() { batch_.flush(); }

 private:
  // Hands the ops held on (their sink's diagnostics come first) and erases
  // the progress line before a diagnostic is printed.
  class Diagnostics final : public core::DiagnosticSink {
   public:
    Diagnostics(core::DiagnosticSink& next, canon::BatchSink& batch, canon::ProgressSink& progress)
        : next_(next), batch_(batch), progress_(progress) {}

    void report(core::Diagnostic d) override;

   private:
    core::DiagnosticSink& next_;
    canon::BatchSink& batch_;
    canon::ProgressSink& progress_;
  };

  canon::BatchSink batch_;
  canon::OpBudget budget_;
  canon::ProgressSink progress_;
  Diagnostics diags_;
};

}  // namespace usina::cli
