// Canned cycle blocks: the block's words, in mm, handed to CannedCycles.
#include "gcode/interp/block_words.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {

bool Interpreter::cycle(BlockWords& w, GCode g, GCode previous) {
  if (g != 760 && !require_feed(w)) return false;
  auto length = [&](char c) -> std::optional<double> {
    if (!w.has(c)) return std::nullopt;
    return mm(w.get(c));
  };
  auto raw = [&](char c) -> std::optional<double> {
    if (!w.has(c)) return std::nullopt;
    return w.get(c);
  };
  const bool threading = g == 760;
  CycleWords cw;
  cw.x = length('X');
  if (cw.x && state_.lathe_diameter) *cw.x /= 2.0;  // G7: X is a diameter
  cw.y = length('Y');
  cw.z = length('Z');
  cw.r = threading ? raw('R') : length('R');
  cw.q = threading ? raw('Q') : length('Q');
  cw.i = length('I');
  cw.j = length('J');
  cw.k = length('K');
  cw.p = threading ? length('P') : raw('P');
  cw.l = raw('L');
  cw.h = raw('H');
  cw.e = length('E');
  cw.polar_radius = length('@');
  cw.polar_angle = raw('^');
  CycleModal cm;
  cm.motion = g;
  cm.plane = state_.plane;
  cm.incremental = state_.incremental;
  cm.retract_to_r = state_.retract == RetractMode::RPlane;
  cm.motion_mode_changed = previous != g;
  cm.spindle = state_.spindle;
  cm.peck_clearance = options_.peck_clearance_mm;
  if (cycle_hooks_ != nullptr) {
    const PeckDistances d = cycle_hooks_->peck_distances();
    cm.peck_clearance = d.g83_clearance_mm;
    cm.peck_retract = d.g73_retract_mm;
  }
  cm.length_unit = core::mm_per(state_.units);
  cm.diameter_mode = state_.lathe_diameter;
  machine_.set_origin(canon::Origin::Cycle);
  auto e = cycles_.run(cw, cm, machine_);
  machine_.set_origin(canon::Origin::Program);
  if (!e) return error(e.error());
  set_xyz(state_.pos, cycles_.end_point());
  if (cycle_hooks_ != nullptr && cycles_.initial_level()) {
    cycle_hooks_->cycle_ran(*cycles_.initial_level());
  }
  return true;
}

}  // namespace usina::gcode
