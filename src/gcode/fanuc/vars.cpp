// Macro B variables of the fanuc dialect (docs/fanuc.md §3): #0 vacant,
// #1-#33 local per macro level, #100-#199 and #500-#999 common, and the
// system variables usina provides from the interpreter's state.
#include <cmath>

#include <fmt/format.h>

#include "gcode/fanuc/engine.hpp"

namespace usina::gcode::fanuc {
namespace {

bool is_common(long i) {
  return (i >= 100 && i <= 199) || (i >= 500 && i <= 999);
}

// #3003 (single block / FIN wait suppression) and #3004 (feed hold,
// override, exact stop suppression) hold bits of the servo with no
// geometric effect: stored, read back.
bool is_writable_system(long i) {
  return i == 3001 || i == 3002 || i == 3003 || i == 3004 || i == 3901 || i == 3902;
}

// #1000-#1015 interface input signals UI000-UI015, #1032 all 16 as one
// number: the machine sets them, a program reads them.
bool is_input_signal(long i) {
  return (i >= 1000 && i <= 1015) || i == 1032;
}

double g_number(int tenths) {
  return tenths / 10.0;
}

}  // namespace

std::optional<Value> Engine::read(long index, MacroError& err) {
  if (index == 0) return Value{0.0, true};
  if (index >= 1 && index <= 33) return locals_.back()[static_cast<std::size_t>(index)];
  if (is_common(index) || is_writable_system(index)) {
    auto it = common_.find(index);
    return it == common_.end() ? Value{0.0, !is_writable_system(index)} : it->second;
  }
  if (index >= 1000 && index <= 1015)
    return Value{static_cast<double>((inputs_ >> (index - 1000)) & 1u)};
  if (index == 1032) return Value{static_cast<double>(inputs_)};
  if (auto v = system_variable(index)) return Value{*v};
  err.code = core::Code::ParameterOutOfRange;
  err.message = index >= 1000
                    ? fmt::format(
                          "#{} is not a system variable usina provides "
                          "(docs/fanuc.md §3.2)",
                          index)
                    : fmt::format("#{} is not a Macro B variable (Fanuc alarm 115)", index);
  return std::nullopt;
}

double Engine::modal_group(int group) const {
  const ModalState& s = interp_.state();
  switch (group) {
  case 1: return g_number(motion_);
  case 2: return s.plane == core::Plane::XY ? 17 : s.plane == core::Plane::ZX ? 18 : 19;
  case 3: return s.incremental ? 91 : 90;
  case 5:
    return s.feed_mode == FeedMode::UnitsPerRev   ? 95
           : s.feed_mode == FeedMode::InverseTime ? 93
                                                  : 94;
  case 6: return s.units == core::LengthUnit::Inch ? 20 : 21;
  case 7: return s.comp == CompSideState::Left ? 41 : s.comp == CompSideState::Right ? 42 : 40;
  case 8: return g_number(length_mode_);
  case 9: return (cycle_ >= 730 && cycle_ != 800) ? g_number(cycle_) : 80;
  case 10: return s.retract == RetractMode::OldZ ? 98 : 99;
  case 11: return xf_.scaling ? 51 : 50;
  case 12: return modal_call_ ? 66 : 67;
  case 13: return s.css ? 96 : 97;
  case 4: return stroke_.armed() ? 22 : 23;
  case 14:
    if (additional_p_ != 0) return 54.1;
    return s.coord_system <= 6 ? 53 + s.coord_system : 59 + (s.coord_system - 6) / 10.0;
  case 15: return g_number(s.path_mode);
  case 16: return xf_.rotation ? 68 : 69;
  case 17: return polar_ ? 16 : 15;
  case 21: return polar_interp_.active() ? 12.1 : 13.1;
  case 22: return xf_.mirrored() ? 51.1 : 50.1;
  default: return 0;
  }
}

std::optional<double> Engine::system_variable(long index) const {
  const ModalState& s = interp_.state();
  const double per = core::mm_per(s.units);
  auto length = [&](int axis, double mm) { return axis >= 3 && axis <= 5 ? mm : mm / per; };
  if (auto r = register_variable(index)) return r;
  if (index >= 4001 && index <= 4030) return modal_group(static_cast<int>(index - 4000));
  switch (index) {
  case 4107: return d_;
  case 4109: return s.feed / per;
  case 4111: return h_;
  case 4113: return m_;
  case 4114: return n_;
  case 4115: return o_;
  case 4119: return s.speed;
  case 4120: return static_cast<double>(s.selected_tool >= 0 ? s.selected_tool : s.tool);
  default: break;
  }
  const auto block = static_cast<int>(index % 20);
  if (index >= 5001 && index <= 5085 && block >= 1 && block <= 5) {
    const auto a = static_cast<std::size_t>(block - 1);
    const int ai = block - 1;
    switch ((index - 5001) / 20) {
    case 0: return length(ai, s.pos[a]);
    case 1: return length(ai, s.pos[a] + s.g5x[a] + s.g92[a] + s.tool_offset[a]);
    case 2: return length(ai, s.pos[a] + s.tool_offset[a]);
    case 3: return interp_.parameters().get(static_cast<int>(5061 + a));
    default: return length(ai, s.tool_offset[a]);
    }
  }
  return work_variable(index);  // #4130, EXT, G54-G59, G54.1
}

bool Engine::write(long index, Value v, const TapeBlock& b, std::size_t pos) {
  if ((index >= 1 && index <= 33)) {
    locals_.back()[static_cast<std::size_t>(index)] = v;
    return true;
  }
  if (index == 3003 || index == 3004) {
    const double most = index == 3003 ? 3 : 7;
    if (!v.vacant && !(v.v >= 0 && v.v <= most && v.v == std::floor(v.v))) {
      return error(core::Code::ValueOutOfRange, b, pos,
                   fmt::format("#{} = {}: its bits make a whole number from 0 to {}", index,
                               word_number(v.v), most));
    }
  }
  if (is_common(index) || is_writable_system(index)) {
    common_[index] = v;
    return true;
  }
  if (is_input_signal(index)) {
    return error(core::Code::ReadOnlyParameter, b, pos,
                 fmt::format("#{} is an interface input signal: the machine sets it, a program "
                             "cannot write it (Fanuc alarm 116); set it with --var-file",
                             index));
  }
  if (index == 3000) {
    const long n = std::lround(v.v);
    return error(core::Code::MacroAlarm, b, pos,
                 fmt::format("alarm {}: {}", 3000 + n,
                             b.comment.empty() ? std::string_view("#3000 alarm") : b.comment));
  }
  if (index == 3006) {
    diags_.report({core::Code::Message, core::Severity::Note, loc_of(b, pos),
                   fmt::format("#3006 stop: {}", b.comment)});
    return true;
  }
  if (auto written = write_work_variable(index, v.v, b)) {
    offsets_written_ = true;
    return *written;
  }
  return error(core::Code::ReadOnlyParameter, b, pos,
               index == 0
                   ? std::string("#0 is always vacant; it cannot be written (Fanuc alarm 116)")
                   : fmt::format("#{} cannot be written (Fanuc alarm 116)", index));
}

}  // namespace usina::gcode::fanuc
