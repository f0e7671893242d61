// Work offsets (G54-G59.3, G10 L2/L20), G92/G52 offsets, G28/G30 homes, tool
// length offsets (G43) and the cutter compensation mode. Offsets are stored in
// the numbered parameters in machine units, as LinuxCNC stores them.
#include <cmath>

#include <fmt/format.h>

#include "canon/limits.hpp"
#include "gcode/interp/block_words.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {
namespace {

constexpr int kG92Base = 5211;
constexpr int kG92Enabled = 5210;
constexpr int kCoordSystemParam = 5220;

int work_offset_base(int n) {
  return 5201 + 20 * n;
}

bool is_rotary(int axis) {
  return axis >= 3 && axis <= 5;
}

// The point `abs` (machine, tool tip) in the program coordinates of work
// system n, less the G92 offset `g92` (mm): LinuxCNC's find_current_in_system.
Vec3 in_system(const Parameters& params, double machine_mm, const Vec3& g92, const Vec3& abs,
               int n) {
  const int base = work_offset_base(n);
  Vec3 d;
  for (int a = 0; a < 3; ++a)
    d[a] = abs[a] - params.get(base + a) * machine_mm;
  const Vec2 r = core::rotate({d.x, d.y}, -core::deg_to_rad(params.get(base + 9)));
  return Vec3{r.x, r.y, d.z} - g92;
}

}  // namespace

// An offset a block sets (or a tool length it applies) within canon's
// range, reported at the word it came from: every later move adds it.
bool Interpreter::offset_in_range(const char* what, char letter, double value, std::uint32_t col) {
  const std::string name = fmt::format("{} {}", what, letter);
  if (auto in_range = canon::check_length(name.c_str(), value); !in_range) {
    return error(core::Code::ValueOutOfRange, col,
                 fmt::format("{} (usina's range: docs/rs274ngc.md, Numbers)", in_range.error()));
  }
  return true;
}

void Interpreter::apply_work_offsets(int n) {
  const int base = work_offset_base(n);
  for (int a = 0; a < kAxisCount; ++a) {
    const double v = params_.get(base + a);
    state_.g5x[static_cast<std::size_t>(a)] = is_rotary(a) ? v : v * machine_mm();
  }
  state_.rotation_deg = params_.get(base + 9);
}

bool Interpreter::select_coord_system(int n) {
  // The tool stays where it is; its program coordinates change.
  const Vec3 abs = machine_.to_absolute(xyz(state_.pos));
  const Axes old = state_.g5x;
  state_.coord_system = n;
  params_.set(kCoordSystemParam, n);
  apply_work_offsets(n);
  set_xyz(state_.pos, machine_.to_program(abs));
  for (std::size_t a = 3; a < static_cast<std::size_t>(kAxisCount); ++a) {
    state_.pos[a] += old[a] - state_.g5x[a];
  }
  return true;
}

void Interpreter::write_g92_params() {
  for (int a = 0; a < kAxisCount; ++a) {
    const double v = state_.g92[static_cast<std::size_t>(a)];
    params_.set(kG92Base + a, is_rotary(a) ? v : v / machine_mm());
  }
}

bool Interpreter::g92(BlockWords& w) {
  ModalState& s = state_;
  const GCode g = w.g[kGroupNonModal];
  const Axes old = s.g92;
  if (g == 920 || g == 520) {
    if (!w.has_axis()) {
      return error(core::Code::MissingWord, w.gcol[kGroupNonModal],
                   fmt::format("{} needs at least one axis word", g_name(g).data()));
    }
    for (int a = 0; a < kAxisCount; ++a) {
      const char letter = kAxisLetters[a];
      if (!w.has(letter)) continue;
      const auto i = static_cast<std::size_t>(a);
      const double v = is_rotary(a) ? w.get(letter) : mm(w.get(letter));
      // G92: the current point takes the given value. G52: the offset is the value.
      s.g92[i] = g == 920 ? s.pos[i] + old[i] - v : v;
      if (!offset_in_range("the offset", letter, s.g92[i], w.col_of(letter))) return false;
    }
    params_.set(kG92Enabled, 1.0);
    write_g92_params();
  } else if (g == 921 || g == 922) {
    s.g92 = Axes{};
    if (g == 921) write_g92_params();
    params_.set(kG92Enabled, 0.0);
  } else if (g == 923) {
    for (int a = 0; a < kAxisCount; ++a) {
      const double v = params_.get(kG92Base + a);
      s.g92[static_cast<std::size_t>(a)] = is_rotary(a) ? v : v * machine_mm();
    }
    params_.set(kG92Enabled, 1.0);
  }
  for (std::size_t a = 0; a < static_cast<std::size_t>(kAxisCount); ++a)
    s.pos[a] += old[a] - s.g92[a];
  return true;
}

bool Interpreter::g10(BlockWords& w) {
  state_.offsets_written = true;
  if (!w.has('L')) return error(core::Code::MissingWord, w.gcol[kGroupNonModal], "G10 needs L");
  const auto lw = whole(w, 'L', 0, 100);
  if (!lw) return false;
  const int l = *lw;
  if (!w.has('P'))
    return error(core::Code::MissingWord, w.gcol[kGroupNonModal],
                 fmt::format("G10 L{} needs P", l));
  const double p = w.get('P');
  if (l == 2 || l == 20) {
    if (p < 0 || p > 9 || std::floor(p) != p) {
      return error(core::Code::BadWordValue, w.col_of('P'),
                   fmt::format("G10 L{} P{}: P must be 0 to 9", l, p));
    }
    const int n = p == 0 ? state_.coord_system : static_cast<int>(p);
    const int base = work_offset_base(n);
    if (w.has('R')) params_.set(base + 9, w.get('R'));
    // L20: offsets that make the current point read the given values, in
    // the system's own (rotated) frame: g5x = m − R(v + g92). The axes not
    // named keep what the current point reads in that system (LinuxCNC's
    // find_current_in_system), so their offsets stay.
    const Vec3 abs = machine_.to_absolute(xyz(state_.pos));
    Vec3 v = in_system(params_, machine_mm(), xyz(state_.g92), abs, n);
    bool linear = false;
    for (int a = 0; a < kAxisCount; ++a) {
      const char letter = kAxisLetters[a];
      if (!w.has(letter)) continue;
      const auto i = static_cast<std::size_t>(a);
      const double value = is_rotary(a) ? w.get(letter) : mm(w.get(letter));
      if (l == 20 && a < 3) {
        v[a] = value;
        linear = true;
        continue;
      }
      const double offset = l == 20 ? state_.pos[i] + state_.g5x[i] - value : value;
      if (!offset_in_range("the work offset", letter, offset, w.col_of(letter))) return false;
      params_.set(base + a, is_rotary(a) ? offset : offset / machine_mm());
    }
    if (linear) {
      Vec3 q = v + xyz(state_.g92);
      const Vec2 r = core::rotate({q.x, q.y}, core::deg_to_rad(params_.get(base + 9)));
      q = {r.x, r.y, q.z};
      const bool plane = w.has('X') || w.has('Y');  // the rotation ties X and Y
      for (int a = 0; a < 3; ++a) {
        if (!(a < 2 ? plane : w.has('Z'))) continue;
        const char letter = kAxisLetters[a];
        const std::uint32_t col = w.has(letter) ? w.col_of(letter) : w.gcol[kGroupNonModal];
        if (!offset_in_range("the work offset", letter, abs[a] - q[a], col)) return false;
      }
      for (int a = 0; a < 3; ++a) {
        if (a < 2 ? plane : w.has('Z')) params_.set(base + a, (abs[a] - q[a]) / machine_mm());
      }
    }
    if (n == state_.coord_system) select_coord_system(n);
    return true;
  }
  if (l == 1 || l == 10 || l == 11) {
    const auto number = whole(w, 'P', 0, kMaxToolNumber);
    if (!number) return false;
    ToolEntry t;
    if (const ToolEntry* old = options_.tools.find(*number)) t = *old;
    t.number = *number;
    if (w.has('R')) t.diameter = 2.0 * mm(w.get('R'));
    for (int a = 0; a < 3; ++a) {
      const char letter = kAxisLetters[a];
      if (!w.has(letter)) continue;
      const double v = mm(w.get(letter));
      // L10: the offset that makes the current point read the value.
      t.offset[a] = l == 1 ? v
                           : state_.pos[static_cast<std::size_t>(a)] +
                                 state_.tool_offset[static_cast<std::size_t>(a)] - v;
      if (!offset_in_range("the tool offset", letter, t.offset[a], w.col_of(letter))) return false;
    }
    options_.tools.define(t);
    return true;
  }
  return error(core::Code::BadWordValue, w.col_of('L'),
               fmt::format("G10 L{} is not supported (L1, L2, L10, L11, L20)", l));
}

bool Interpreter::home(BlockWords& w, int g) {
  const int base = g == 280 ? 5161 : 5181;
  // Through the intermediate point given by the axis words, if any.
  // LinuxCNC moves there even without axis words (a move to where it is).
  machine_.traverse_axes(target(w, false));
  // Then to the stored position: every axis, or only those named, each
  // taking the stored position's program coordinate (convert_home: under an
  // XY rotation a named X moves the machine's X and Y).
  Vec3 abs;
  for (int a = 0; a < 3; ++a)
    abs[a] = params_.get(base + a) * machine_mm() - state_.tool_offset[static_cast<std::size_t>(a)];
  const Vec3 home = machine_.to_program(abs);
  Axes end = state_.pos;
  for (int a = 0; a < kAxisCount; ++a) {
    if (w.has_axis() && !w.has(kAxisLetters[a])) continue;
    const double v = params_.get(base + a);
    end[static_cast<std::size_t>(a)] = a < 3 ? home[a] : is_rotary(a) ? v : v * machine_mm();
  }
  machine_.traverse_axes(end);
  return true;
}

bool Interpreter::tool_length(BlockWords& w) {
  ModalState& s = state_;
  const GCode g = w.g[kGroupToolLength];
  Axes next{};
  if (g == 490) s.length_h = -1;
  if (g == 430 || g == 432) {
    std::optional<int> h;
    if (w.has('H') && !(h = whole(w, 'H', 0, kMaxToolNumber))) return false;
    // LinuxCNC's find_tool_index: H0 is pocket 0, the spindle's tool.
    const int tool = h && *h != 0 ? *h : s.tool;
    const ToolEntry* t = options_.tools.find(tool);
    // No tool table: the tool's length is unknown, taken as 0.
    if (t == nullptr && tool != 0 && options_.tools.lists_tools()) {
      return error(core::Code::UnknownTool, w.has('H') ? w.col_of('H') : w.gcol[kGroupToolLength],
                   fmt::format("tool {} is not in the tool table", tool));
    }
    s.length_h = g == 430 ? h.value_or(0) : -2;
    if (g == 432) next = s.tool_offset;
    if (t != nullptr) {
      for (int a = 0; a < 3; ++a)
        next[static_cast<std::size_t>(a)] += t->offset[a];
    }
  } else if (g == 431) {
    s.length_h = -2;
    for (int a = 0; a < 3; ++a) {
      if (w.has(kAxisLetters[a])) next[static_cast<std::size_t>(a)] = mm(w.get(kAxisLetters[a]));
    }
  }
  for (int a = 0; a < 3; ++a) {
    const char letter = kAxisLetters[a];
    const std::uint32_t col = g == 431 && w.has(letter) ? w.col_of(letter)
                              : w.has('H')              ? w.col_of('H')
                                                        : w.gcol[kGroupToolLength];
    if (!offset_in_range("the tool length offset", letter, next[static_cast<std::size_t>(a)], col))
      return false;
  }
  if (g == 431) {
    w.clear_letter('X');
    w.clear_letter('Y');
    w.clear_letter('Z');
  }
  // LinuxCNC keeps the machine still: the current point's program
  // coordinates change by the difference of the offsets.
  for (std::size_t a = 0; a < 3; ++a)
    s.pos[a] += s.tool_offset[a] - next[a];
  s.tool_offset = next;
  return true;
}

bool Interpreter::cutter_comp_mode(BlockWords& w) {
  ModalState& s = state_;
  const GCode g = w.g[kGroupCutterComp];
  if (g == 400) {
    // LinuxCNC: the current point becomes the programmed point.
    const auto programmed = comp_.programmed_position();
    if (auto e = comp_.stop(machine_); !e) return error(e.error());
    if (programmed) set_xyz(s.pos, *programmed);
    s.comp = CompSideState::Off;
    return true;
  }
  if (s.comp != CompSideState::Off) {
    return error(core::Code::CompNotAllowed, w.gcol[kGroupCutterComp],
                 "cutter compensation is already on: G40 first");
  }
  if (s.plane == core::Plane::YZ) {
    return error(core::Code::CompNotAllowed, w.gcol[kGroupCutterComp],
                 "cutter compensation works in the XY (G17) and XZ (G18) planes only");
  }
  double radius = 0.0;
  int orientation = 0;
  if (g == 411 || g == 421) {
    if (!w.has('D'))
      return error(core::Code::MissingWord, w.gcol[kGroupCutterComp],
                   "G41.1/G42.1 need D (the tool diameter)");
    radius = mm(w.get('D')) / 2.0;
  } else {
    std::optional<int> d;
    if (w.has('D') && !(d = whole(w, 'D', 0, kMaxToolNumber))) return false;
    const int tool = d && *d != 0 ? *d : s.tool;  // D0: the spindle's tool, as H0
    const ToolEntry* t = options_.tools.find(tool);
    // No tool table: the tool's diameter is unknown, taken as 0.
    if (t == nullptr && tool != 0 && options_.tools.lists_tools()) {
      return error(core::Code::UnknownTool, w.has('D') ? w.col_of('D') : w.gcol[kGroupCutterComp],
                   fmt::format("tool {} is not in the tool table", tool));
    }
    radius = t != nullptr ? t->diameter / 2.0 : 0.0;
    orientation = t != nullptr ? t->orientation : 0;
  }
  // A negative radius (G41.1 D-1) puts the tool on the other side, as in LinuxCNC.
  const CompSide side = (g == 410 || g == 411) ? CompSide::Left : CompSide::Right;
  if (options_.ignore_cutter_comp) radius = 0.0;
  const bool metric = s.units == core::LengthUnit::Mm;
  if (auto e = comp_.start(side, radius, s.plane, orientation, metric); !e) {
    return error(e.error(), w.gcol[kGroupCutterComp]);
  }
  s.comp = side == CompSide::Left ? CompSideState::Left : CompSideState::Right;
  return true;
}

bool Interpreter::modal_zero(BlockWords& w) {
  switch (w.g[kGroupNonModal]) {
  case 100: return g10(w);
  case 280:
  case 300: return home(w, w.g[kGroupNonModal]);
  case 281:
  case 301: {
    const int base = w.g[kGroupNonModal] == 281 ? 5161 : 5181;
    const Vec3 abs = machine_.to_absolute(xyz(state_.pos));
    for (int a = 0; a < kAxisCount; ++a) {
      const auto i = static_cast<std::size_t>(a);
      const double v = a < 3 ? (abs[a] + state_.tool_offset[i]) / machine_mm() : state_.pos[i];
      params_.set(base + a, v);
    }
    return true;
  }
  case 520:
  case 920:
  case 921:
  case 922:
  case 923: return g92(w);
  default: return true;
  }
}

}  // namespace usina::gcode
