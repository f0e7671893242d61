// Step 4 of a block: its parts run in the order its dialect gives
// (DialectRules::order; LinuxCNC's execute_block order for rs274ngc,
// fanuc and grbl: execution_order.cpp), one step each.
#include <cmath>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include "gcode/interp/block_words.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {

double Interpreter::tool_diameter(int tool) const {
  const ToolEntry* t = options_.tools.find(tool);
  return t != nullptr ? t->diameter : 0.0;
}

bool Interpreter::comments(std::span<const CommentText> notes) {
  for (const CommentText& c : notes) {
    std::string_view t = c.text;
    if (rules_.comments_as_written) {
      in_order([this, text = std::string(t)] { machine_.emit(canon::Comment{text}); });
      continue;
    }
    while (!t.empty() && (t.front() == ' ' || t.front() == '\t'))
      t.remove_prefix(1);
    // (MSG, text) is an operator message; other comments are kept too, so a
    // drawing or a post-processor can show them.
    const bool msg = t.size() >= 4 && (t[0] == 'M' || t[0] == 'm') &&
                     (t[1] == 'S' || t[1] == 's') && (t[2] == 'G' || t[2] == 'g') && t[3] == ',';
    if (msg) {
      t.remove_prefix(4);
      core::SourceLoc loc = run_.loc();
      loc.col = c.col;
      run_.diags().report({core::Code::Message, core::Severity::Note, loc, std::string(t)});
    }
    in_order([this, text = std::string(t)] { machine_.emit(canon::Comment{text}); });
  }
  return true;
}

void Interpreter::in_order(std::function<void()> effect) {
  if (!comp_.holding()) {
    effect();
    return;
  }
  comp_.defer(
      run_.loc(), [effect = std::move(effect)](MotionTarget&) { effect(); }, machine_);
}

namespace {

// LinuxCNC's order unrolled at compile time: each step a constant, so its
// switch folds away and a block runs as straight-line code. A loop over
// the steps with a dispatch each cost `check` 15 % of its time.
template <typename Run, std::size_t... I>
bool run_linuxcnc_order(Run&& run, std::index_sequence<I...>) {
  return (run(std::integral_constant<ExecStep, kLinuxcncOrder[I]>{}) && ...);
}

}  // namespace

bool Interpreter::execute(std::span<const CommentText> notes, BlockWords& w) {
  if (order_.steps.data() == kLinuxcncOrder.data()) {
    return run_linuxcnc_order([&](auto step) { return run_step(step, notes, w); },
                              std::make_index_sequence<kExecSteps>{});
  }
  for (const ExecStep step : order_.steps) {
    if (!run_step(step, notes, w)) return false;
  }
  return true;
}

// The modal group whose G code a setting step runs.
constexpr int setting_group(ExecStep step) {
  switch (step) {
  case ExecStep::Plane: return kGroupPlane;
  case ExecStep::Units: return kGroupUnits;
  case ExecStep::LatheMode: return kGroupLathe;
  case ExecStep::CutterComp: return kGroupCutterComp;
  case ExecStep::ToolLength: return kGroupToolLength;
  case ExecStep::CoordSystem: return kGroupCoordSystem;
  case ExecStep::PathControl: return kGroupPathControl;
  case ExecStep::Distance: return kGroupDistance;
  case ExecStep::ArcDistance: return kGroupArcDistance;
  case ExecStep::Retract: return kGroupRetract;
  case ExecStep::SpindleMode: return kGroupSpindleMode;
  default: return kGroupNonModal;
  }
}

// One step of the dialect's order (execution_order.hpp). Each step is
// skipped here, without a call, when the block has none of its words: most
// blocks have two or three steps' worth of words.
[[gnu::always_inline]] inline bool Interpreter::run_step(ExecStep step,
                                                         std::span<const CommentText> notes,
                                                         BlockWords& w) {
  switch (step) {
  case ExecStep::Comments: return notes.empty() || comments(notes);
  case ExecStep::FeedMode:
    if (w.g[kGroupFeedMode] != -1) feed_mode(w);
    return true;
  case ExecStep::Feed: return (!w.has('F') && w.g[kGroupFeedMode] == -1) || feed(w);
  case ExecStep::Speed: return !w.has('S') || speed(w);
  case ExecStep::SelectTool: return !w.has('T') || select_tool(w);
  case ExecStep::ChangeTool: return w.m[kMGroupToolChange] == -1 || change_tool(w);
  case ExecStep::Spindle:
    if (w.m[kMGroupSpindle] != -1) spindle(w);
    return true;
  case ExecStep::Coolant:
    if (w.m[kMGroupCoolant] != -1) coolant(w);
    return true;
  case ExecStep::Overrides:
    if (w.m[kMGroupOverride] != -1) overrides(w);
    return true;
  case ExecStep::UserM:
    if (w.user_m_count > 0) user_m_codes(w);
    return true;
  case ExecStep::Dwell: return w.g[kGroupNonModal] != 40 || dwell(w);
  case ExecStep::ModalState: return w.m[kMGroupModalState] == -1 || modal_save_restore(w);
  case ExecStep::NonModal: return w.g[kGroupNonModal] == -1 || modal_zero(w);
  case ExecStep::Motion: return w.motion == -1 || motion(w);
  case ExecStep::Resync:
    if (tool_changed_) resync_after_tool_change();
    return true;
  case ExecStep::Subprogram: return w.m[kMGroupSubprogram] == -1 || subprogram(w);
  case ExecStep::Stop: return w.m[kMGroupStop] == -1 || stop(w);
  default:
    return w.g[static_cast<std::size_t>(setting_group(step))] == -1 || modal_setting(step, w);
  }
}

void Interpreter::feed_mode(const BlockWords& w) {
  if (w.g[kGroupFeedMode] == -1) return;
  const GCode g = w.g[kGroupFeedMode];
  state_.feed_mode = g == 930 ? FeedMode::InverseTime
                              : (g == 950 ? FeedMode::UnitsPerRev : FeedMode::UnitsPerMinute);
  // LinuxCNC: entering inverse time clears the feed rate.
  if (g == 930) state_.feed = 0.0;
}

bool Interpreter::feed(const BlockWords& w) {
  ModalState& s = state_;
  if (w.has('F')) {
    if (w.get('F') < 0) return error(core::Code::BadWordValue, w.col_of('F'), "negative feed rate");
    s.feed = s.feed_mode == FeedMode::InverseTime ? w.get('F') : mm(w.get('F'));
  }
  if (w.has('F') || w.g[kGroupFeedMode] != -1) {
    in_order([this, f = s.feed, mode = s.feed_mode] { machine_.set_feed(f, mode); });
  }
  return true;
}

bool Interpreter::speed(const BlockWords& w) {
  if (!w.has('S')) return true;
  if (w.get('S') < 0)
    return error(core::Code::BadWordValue, w.col_of('S'), "negative spindle speed");
  state_.speed = w.get('S');
  return true;
}

bool Interpreter::select_tool(const BlockWords& w) {
  if (!w.has('T')) return true;
  auto t = whole(w, 'T', 0, kMaxToolNumber);
  if (!t) return false;
  state_.selected_tool = *t;
  return true;
}

bool Interpreter::change_tool(const BlockWords& w) {
  ModalState& s = state_;
  const int tc = w.m[kMGroupToolChange];
  if (tc != 6 && tc != 61) return true;
  if (tc == 61 && !w.has('Q'))
    return error(core::Code::MissingWord, w.mcol[kMGroupToolChange],
                 "M61 needs Q (the tool number)");
  std::optional<int> q;
  if (tc == 61 && !(q = whole(w, 'Q', 0, kMaxToolNumber))) return false;
  const int tool = tc == 61 ? *q : s.selected_tool;
  if (tool < 0)
    return error(core::Code::MissingWord, w.mcol[kMGroupToolChange],
                 "M6 with no tool selected: give T first");
  // LinuxCNC's M6 stops the spindle before the change.
  if (tc == 6 && rules_.tool_change_stops_spindle && s.spindle != canon::SpindleDir::Off)
    machine_.spindle(canon::SpindleDir::Off);
  s.tool = tool;
  tool_changed_ = true;
  const double d = tool_diameter(tool);
  machine_.set_tool_diameter(d);
  machine_.emit(canon::ToolChange{tool, d > 0 ? std::optional<double>(d) : std::nullopt});
  return true;
}

void Interpreter::spindle(const BlockWords& w) {
  const int spin = w.m[kMGroupSpindle];
  if (spin != 3 && spin != 4 && spin != 5) return;
  const auto dir = spin == 3 ? canon::SpindleDir::Cw
                             : (spin == 4 ? canon::SpindleDir::Ccw : canon::SpindleDir::Off);
  state_.spindle = dir;
  in_order([this, dir] { machine_.spindle(dir); });
}

void Interpreter::coolant(const BlockWords& w) {
  ModalState& s = state_;
  const int cool = w.m[kMGroupCoolant];
  if (cool == -1) return;
  if (cool == 7 || w.m7_and_m8) s.mist = true;
  if (cool == 8 || w.m7_and_m8) s.flood = true;
  if (cool == 9) s.mist = s.flood = false;
  in_order([this, c = canon::Coolant{s.mist, s.flood}] { machine_.emit(c); });
}

void Interpreter::overrides(const BlockWords& w) {
  ModalState& s = state_;
  switch (w.m[kMGroupOverride]) {
  case 48: s.feed_override = s.speed_override = true; break;
  case 49: s.feed_override = s.speed_override = false; break;
  case 50: s.feed_override = !w.has('P') || w.get('P') != 0; break;
  case 51: s.speed_override = !w.has('P') || w.get('P') != 0; break;
  default: break;
  }
}

void Interpreter::user_m_codes(const BlockWords& w) {
  for (int i = 0; i < w.user_m_count; ++i) {
    machine_.emit(
        canon::Comment{fmt::format("M{} (user M code)", w.user_m[static_cast<std::size_t>(i)])});
  }
}

bool Interpreter::dwell(const BlockWords& w) {
  if (w.g[kGroupNonModal] != 40) return true;
  if (!w.has('P') || w.get('P') < 0) {
    return error(core::Code::MissingWord, w.gcol[kGroupNonModal],
                 "G4 needs P (seconds, not negative)");
  }
  in_order([this, s = w.get('P')] { machine_.dwell(s); });
  return true;
}

// After a tool change LinuxCNC re-reads the current point from the machine
// before the next block: the point last sent, so what the block did to the
// program position (G43 beside M6, G40) is undone.
void Interpreter::resync_after_tool_change() {
  if (!tool_changed_) return;
  tool_changed_ = false;
  set_xyz(state_.pos, machine_.last_emitted());
}

// The modal settings of G codes, one step each.
bool Interpreter::modal_setting(ExecStep step, BlockWords& w) {
  ModalState& s = state_;
  switch (step) {
  case ExecStep::Plane:
    if (w.g[kGroupPlane] == 170) s.plane = core::Plane::XY;
    if (w.g[kGroupPlane] == 180) s.plane = core::Plane::ZX;
    if (w.g[kGroupPlane] == 190) s.plane = core::Plane::YZ;
    return true;
  case ExecStep::Units:
    return w.g[kGroupUnits] == -1 ||
           set_units(w.g[kGroupUnits] == 200 ? core::LengthUnit::Inch : core::LengthUnit::Mm);
  case ExecStep::LatheMode:
    if (w.g[kGroupLathe] != -1) s.lathe_diameter = w.g[kGroupLathe] == 70;
    return true;
  case ExecStep::CutterComp: return w.g[kGroupCutterComp] == -1 || cutter_comp_mode(w);
  case ExecStep::ToolLength: return w.g[kGroupToolLength] == -1 || tool_length(w);
  case ExecStep::CoordSystem: return coord_system(w);
  case ExecStep::PathControl: return w.g[kGroupPathControl] == -1 || path_control(w);
  case ExecStep::Distance:
    if (w.g[kGroupDistance] != -1) s.incremental = w.g[kGroupDistance] == 910;
    return true;
  case ExecStep::ArcDistance:
    if (w.g[kGroupArcDistance] != -1) s.arc_absolute = w.g[kGroupArcDistance] == 901;
    return true;
  case ExecStep::Retract:
    if (w.g[kGroupRetract] != -1)
      s.retract = w.g[kGroupRetract] == 990 ? RetractMode::RPlane : RetractMode::OldZ;
    return true;
  case ExecStep::SpindleMode: s.css = w.g[kGroupSpindleMode] == 960; return true;
  default: return true;
  }
}

bool Interpreter::coord_system(const BlockWords& w) {
  if (w.g[kGroupCoordSystem] == -1) return true;
  const GCode g = w.g[kGroupCoordSystem];
  const int n = g <= 590 ? g / 10 - 53 : 6 + g - 590;
  const bool again = n == state_.coord_system && !rules_.reselect_reloads_work_offsets;
  if (!again && !select_coord_system(n)) return false;
  state_.coord_system_chosen = true;
  return true;
}

// G61, G61.1, G64 P Q: the mode goes to the back ends as LinuxCNC's
// SET_MOTION_CONTROL_MODE does (stats times the corners by it); Q, the naive
// CAM tolerance, is P when the block has none.
bool Interpreter::path_control(const BlockWords& w) {
  const GCode g = w.g[kGroupPathControl];
  state_.path_mode = g;
  canon::PathMode m;
  m.mode = g == 610   ? canon::PathMode::Mode::ExactPath
           : g == 611 ? canon::PathMode::Mode::ExactStop
                      : canon::PathMode::Mode::Blend;
  if (g == 640) {
    const double p = w.has('P') ? w.get('P') : 0.0;
    const double q = w.has('Q') ? w.get('Q') : p;
    for (const char c : {'P', 'Q'}) {
      if (w.has(c) && w.get(c) < 0.0) {
        return error(core::Code::NumberOutOfRange, w.col_of(c),
                     fmt::format("G64 {}{:g}: the tolerance must be 0 or more", c, w.get(c)));
      }
    }
    m.tolerance = mm(p);
    m.naive_cam = mm(q);
  }
  machine_.emit(m);
  return true;
}

bool Interpreter::set_units(core::LengthUnit u) {
  // Units change what later words mean; positions are kept in mm, so
  // nothing else moves. The feed rate keeps its value in mm/min.
  state_.units = u;
  return true;
}

// M70 save, M71 invalidate, M72 restore, M73 save and restore at the
// subroutine's return (LinuxCNC manual, M70-M73): modes, not positions.
bool Interpreter::modal_save_restore(const BlockWords& w) {
  switch (w.m[kMGroupModalState]) {
  case 70: saved_modal_ = state_; break;
  case 71: saved_modal_.reset(); break;
  case 72:
    if (!saved_modal_) {
      return error(core::Code::NotAllowedInMode, w.mcol[kMGroupModalState],
                   "M72 with no state saved by M70");
    }
    restore_modal(*saved_modal_);
    break;
  case 73:
    if (frames_.empty()) {
      return error(core::Code::NotAllowedInMode, w.mcol[kMGroupModalState],
                   "M73 outside a subroutine");
    }
    frames_.back().autorestore = state_;
    break;
  default: break;
  }
  return true;
}

void Interpreter::restore_modal(const ModalState& saved) {
  ModalState& s = state_;
  s.units = saved.units;
  s.plane = saved.plane;
  s.incremental = saved.incremental;
  s.arc_absolute = saved.arc_absolute;
  s.feed_mode = saved.feed_mode;
  s.retract = saved.retract;
  s.css = saved.css;
  s.lathe_diameter = saved.lathe_diameter;
  s.path_mode = saved.path_mode;
  s.feed = saved.feed;
  s.speed = saved.speed;
  s.feed_override = saved.feed_override;
  s.speed_override = saved.speed_override;
  machine_.set_feed(s.feed, s.feed_mode);
  if (s.mist != saved.mist || s.flood != saved.flood) {
    s.mist = saved.mist;
    s.flood = saved.flood;
    machine_.emit(canon::Coolant{s.mist, s.flood});
  }
  if (s.spindle != saved.spindle) machine_.spindle(saved.spindle);
  if (s.coord_system != saved.coord_system) select_coord_system(saved.coord_system);
}

bool Interpreter::subprogram(const BlockWords& w) {
  const int m = w.m[kMGroupSubprogram];
  if (m == 98) return fanuc_call(w);
  if (m == 99) return fanuc_return();
  return true;
}

bool Interpreter::stop(const BlockWords& w) {
  switch (w.m[kMGroupStop]) {
  case 2:
  case 30: {
    if (auto e = comp_.flush(machine_); !e) return error(e.error());
    comp_.reset();
    state_.comp = CompSideState::Off;
    // LinuxCNC's program end: spindle and coolant off, then the end.
    if (state_.spindle != canon::SpindleDir::Off) machine_.spindle(canon::SpindleDir::Off);
    machine_.emit(canon::ProgramEnd{});
    ended_ = true;
    break;
  }
  case 0:
  case 1:
  case 60:
    if (auto e = comp_.flush(machine_); !e) return error(e.error());
    {
      const int m = w.m[kMGroupStop];
      machine_.emit(canon::Comment{rules_.two_digit_stop_codes
                                       ? fmt::format("M{:02} (program stop)", m)
                                       : fmt::format("M{} (program stop)", m)});
    }
    break;
  default: break;
  }
  return true;
}

}  // namespace usina::gcode
