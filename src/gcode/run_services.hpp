// What every dialect's runner shares for one run (DESIGN.md, "One road
// below the text"): the block the diagnostics point at, the reports at a
// column of it, whether the run failed, and the run's budget of backward
// jumps (--max-total-iterations) that makes every loop end. Inside the
// block loop an error is `false` + the diagnostic sink.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "core/diagnostic.hpp"
#include "gcode/interp/interp_error.hpp"

namespace usina::gcode {

class RunServices {
 public:
  RunServices(core::DiagnosticSink& diags, long max_total_iterations)
      : diags_(diags), max_iterations_(max_total_iterations) {}

  // The block the diagnostics point at.
  const core::SourceLoc& loc() const { return loc_; }

  void at(const core::SourceLoc& loc) { loc_ = loc; }

  // Reports an error at column `col` of the block (0: the whole block) and
  // fails the run; returns false.
  bool error(core::Code code, std::uint32_t col, std::string message);

  bool error(const InterpError& e, std::uint32_t col = 0) { return error(e.code, col, e.message); }

  // A warning or a note at column `col` of the block (0: the block).
  void note(core::Code code, core::Severity sev, std::uint32_t col, std::string message);

  void warn(core::Code code, std::uint32_t col, std::string message) {
    note(code, core::Severity::Warning, col, std::move(message));
  }

  bool failed() const { return failed_; }

  void fail() { failed_ = true; }

  // A front end that reports a refused block and reads on (grbl) puts the
  // run back as it was before the block.
  void clear_failure() { failed_ = false; }

  // One more backward jump, call or repetition (`what` names those the
  // dialect counts, "loops"): false with E_TOO_MANY_ITERATIONS past the
  // run's budget, so a loop ends.
  bool count_jump(std::string_view what);

  core::DiagnosticSink& diags() { return diags_; }

 private:
  core::DiagnosticSink& diags_;
  core::SourceLoc loc_;
  long max_iterations_;
  long jumps_ = 0;
  bool failed_ = false;
};

}  // namespace usina::gcode
