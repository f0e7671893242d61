// What the romi front end (romi_engine) and the handlers below it
// (romi_exec) share for one run: the block being run and its diagnostics,
// whether the run failed, the run's iteration budget, and the dialect's
// options read once. Inside the block loop an error is `false` + the
// diagnostic sink (DESIGN.md, "One road below the text").
#pragma once

#include <cstdint>
#include <string>

#include "core/diagnostic.hpp"
#include "gcode/dialect.hpp"
#include "gcode/interp/interp_error.hpp"

namespace usina::gcode::romi {

// The dialect's options (romi/dialect.cpp, docs/romi.md), from their names once a
// run instead of once a word.
struct Options {
  bool lowercase_incremental = true;
  bool typographic_dash_is_error = false;
  bool motion_cancels_cycle = false;
  bool comp_radius_from_register = true;  // comp_radius=register

  // `values` as resolve_options fills them; an option missing takes the
  // dialect's default.
  static Options from(const Dialect& dialect, const OptionValues& values);
};

class Services {
 public:
  Services(core::DiagnosticSink& diags, long max_total_iterations)
      : diags_(diags), max_iterations_(max_total_iterations) {}

  // The block the diagnostics point at.
  const core::SourceLoc& loc() const { return loc_; }

  void at(const core::SourceLoc& loc) { loc_ = loc; }

  // Reports an error at column `col` of the block (0: the block) and fails
  // the run; returns false.
  bool error(core::Code code, std::uint32_t col, std::string message);

  bool error(const InterpError& e) { return error(e.code, 0, e.message); }

  void note(core::Code code, core::Severity sev, std::uint32_t col, std::string message);

  bool failed() const { return failed_; }

  void fail() { failed_ = true; }

  // One more backward jump, call, pattern point or pocket ring: false with
  // E_TOO_MANY_ITERATIONS beyond --max-total-iterations, so a loop ends.
  bool count_jump();

 private:
  core::DiagnosticSink& diags_;
  core::SourceLoc loc_;
  long max_iterations_;
  long jumps_ = 0;
  bool failed_ = false;
};

}  // namespace usina::gcode::romi
