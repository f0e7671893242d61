// What the romi front end (romi/engine) and the handlers below it
// (romi/exec) share for one run: the run services every dialect's runner
// has (gcode/run_services.hpp) and the dialect's options read once.
#pragma once

#include <cstdint>
#include <string>

#include "core/diagnostic.hpp"
#include "gcode/dialect.hpp"
#include "gcode/interp/interp_error.hpp"
#include "gcode/run_services.hpp"

namespace usina::gcode::romi {

// The dialect's options (romi/dialect.cpp, docs/romi.md), from their names once a
// run instead of once a word.
struct Options {
  bool lowercase_incremental = true;
  bool typographic_dash_is_error = false;
  bool motion_cancels_cycle = false;
  bool comp_radius_from_register = true;  // comp_radius=register
  // Not a dialect option (the command line refuses it): a test runs every
  // block down the whole road to compare with the plain-move shortcut.
  bool plain_move_shortcut = true;

  // `values` as resolve_options fills them; an option missing takes the
  // dialect's default.
  static Options from(const Dialect& dialect, const OptionValues& values);
};

// The run's block, diagnostics and budget: the services every runner
// shares (gcode/run_services.hpp).
using Services = RunServices;

// What romi counts against the run's budget of jumps (RunServices::count_jump).
inline constexpr std::string_view kJumps = "backward jumps, calls and pattern points";

}  // namespace usina::gcode::romi
