// Step 2 of a block: its codes sorted into modal groups, conflicts and
// words that no code of the block uses reported.
#include <string_view>

#include <fmt/format.h>

#include "gcode/interp/block_words.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {

bool Interpreter::place_g(BlockWords& w, GCode g, std::uint32_t col) {
  const InterpCodes::Code* code = codes_.find('G', g);
  if (code == nullptr) {
    return error(core::Code::UnknownGCode, col, fmt::format("unknown G code {}", g_name(g).data()));
  }
  if (code->handler == CodeRun::Unsupported) {
    return error(core::Code::Unsupported, col,
                 fmt::format("{} ({}) is not supported yet", g_name(g).data(), code->entry->what));
  }
  const int group = code->entry->group;
  const auto gi = static_cast<std::size_t>(group);
  // LinuxCNC accepts G80 beside another motion code (CAM headers write
  // "G0 G80"): the cycle is cancelled and the other code is the motion.
  // A G80 alone is the block's motion code (it ends the cycle).
  if (group == kGroupMotion && w.g[gi] != -1 && (w.g[gi] == 800 || g == 800) && w.g[gi] != g) {
    if (g != 800) w.g[gi] = g;
    return true;
  }
  if (w.g[gi] != -1) {
    return error(core::Code::ModalGroupConflict, col,
                 fmt::format("{} and {} are in the same modal group; one per block",
                             g_name(w.g[gi]).data(), g_name(g).data()));
  }
  w.g[gi] = g;
  w.gcol[gi] = col;
  return true;
}

bool Interpreter::place_m(BlockWords& w, int m, std::uint32_t col) {
  const InterpCodes::Code* code =
      m >= 0 && m <= kMaxCodeTenths / 10 ? codes_.find('M', m * 10) : nullptr;
  if (code == nullptr)
    return error(core::Code::UnknownMCode, col, fmt::format("unknown M code M{}", m));
  if (code->handler == CodeRun::Unsupported) {
    return error(core::Code::Unsupported, col,
                 fmt::format("M{} ({}) is not supported yet", m, code->entry->what));
  }
  const int group = code->entry->group;
  const auto gi = static_cast<std::size_t>(group);
  if (code->handler == CodeRun::UserM) {
    if (w.user_m_count == static_cast<int>(w.user_m.size())) {
      return error(core::Code::ModalGroupConflict, col, "too many user M codes in one block");
    }
    w.user_m[static_cast<std::size_t>(w.user_m_count++)] = m;
    return true;
  }
  if (w.m[gi] != -1) {
    // LinuxCNC lets mist and flood be turned on in one block.
    const bool coolants =
        group == kMGroupCoolant && ((w.m[gi] == 7 && m == 8) || (w.m[gi] == 8 && m == 7));
    if (!coolants) {
      return error(
          core::Code::ModalGroupConflict, col,
          fmt::format("M{} and M{} are in the same modal group; one per block", w.m[gi], m));
    }
    w.m7_and_m8 = true;
    return true;
  }
  w.m[gi] = m;
  w.mcol[gi] = col;
  return true;
}

namespace {

bool uses_axes(GCode g0) {
  return g0 == 100 || g0 == 280 || g0 == 300 || g0 == 520 || g0 == 920;
}

bool is_arc(GCode g) {
  return g == 20 || g == 30;
}

bool is_cycle(GCode g) {
  return g == 730 || g == 740 || g == 760 || (g >= 810 && g <= 890);
}

}  // namespace

bool Interpreter::check(BlockWords& w) {
  const GCode g0 = w.g[kGroupNonModal];
  const GCode g1 = w.g[kGroupMotion];
  // G43.1's X Y Z are offsets, not a move (LinuxCNC takes them for G43.1).
  const bool axes = (w.has_axis() || w.has_polar()) && w.g[kGroupToolLength] != 431;
  if (g1 != -1) {
    w.motion = g1;
  } else if (axes && !uses_axes(g0)) {
    w.motion = state_.motion;
  }
  if (w.motion == 800 && axes && !uses_axes(g0)) {
    return error(core::Code::AxisWordsConflict, w.axis_col(),
                 "axis words with G80 (motion off): give G0, G1, G2 or G3, or remove them");
  }
  if (g1 != -1 && g1 != 800 && uses_axes(g0) && axes) {
    return error(
        core::Code::AxisWordsConflict, w.gcol[kGroupNonModal],
        fmt::format("{} and {} both use the axis words", g_name(g0).data(), g_name(g1).data()));
  }
  if (g0 == 530 && w.motion != 0 && w.motion != 10) {
    return error(core::Code::NotAllowedInMode, w.gcol[kGroupNonModal], "G53 needs G0 or G1 motion");
  }
  return comp_forbids(w) && check_unused(w) && check_increments(w);
}

// A word marked as an increment (EvaluatedWord::incremental) counts from
// where a move starts: only a move to a point takes it (target()). G53's
// words are machine coordinates; a canned cycle's, G10's, G52's and G92's
// are read under G90/G91 alone.
bool Interpreter::check_increments(const BlockWords& w) {
  if (w.increments == 0) return true;
  const GCode g0 = w.g[kGroupNonModal];
  const bool to_point =
      uses_axes(g0) ? (g0 == 280 || g0 == 300) : w.motion != -1 && !is_cycle(w.motion) && g0 != 530;
  if (to_point) return true;
  char letter = 'X';
  for (const char c : std::string_view(kAxisLetters)) {
    if (w.incremental(c)) {
      letter = c;
      break;
    }
  }
  return error(core::Code::NotAllowedInMode, w.col_of(letter),
               fmt::format("{} written as an increment outside a move to a point", letter));
}

// What LinuxCNC refuses while cutter radius compensation is on.
bool Interpreter::comp_forbids(const BlockWords& w) {
  if (!comp_.active()) return true;
  auto refuse = [&](std::uint32_t col, const char* what) {
    return error(core::Code::CompNotAllowed, col,
                 fmt::format("{} with cutter radius compensation on: G40 first", what));
  };
  const GCode plane = w.g[kGroupPlane];
  const GCode current =
      state_.plane == core::Plane::XY ? 170 : (state_.plane == core::Plane::ZX ? 180 : 190);
  if (plane != -1 && plane != current) return refuse(w.gcol[kGroupPlane], "a plane change");
  if (w.m[kMGroupToolChange] == 6) return refuse(w.mcol[kMGroupToolChange], "a tool change");
  if (w.g[kGroupCoordSystem] != -1)
    return refuse(w.gcol[kGroupCoordSystem], "a work offset change");
  if (w.g[kGroupUnits] != -1 &&
      (w.g[kGroupUnits] == 200) != (state_.units == core::LengthUnit::Inch)) {
    return refuse(w.gcol[kGroupUnits], "a units change");
  }
  const GCode g0 = w.g[kGroupNonModal];
  if (g0 == 280 || g0 == 300 || g0 == 920 || g0 == 520 || g0 == 530) {
    return refuse(w.gcol[kGroupNonModal], g_name(g0).data());
  }
  const GCode mo = w.motion;
  if (mo == 330 || mo == 331 || mo == 760 || (mo >= 382 && mo <= 385) || mo == 730 ||
      (mo >= 810 && mo <= 890) || (mo >= 50 && mo <= 53) || mo == 62) {
    return refuse(w.g[kGroupMotion] != -1 ? w.gcol[kGroupMotion] : 0, g_name(mo).data());
  }
  return true;
}

bool Interpreter::check_unused(const BlockWords& w) {
  // Most blocks have none of the letters below: nothing to ask.
  constexpr std::uint32_t kAsked = [] {
    std::uint32_t bits = 0;
    for (const char c : std::string_view("IJKRPQLDHE"))
      bits |= 1u << BlockWords::slot(c);
    return bits;
  }();
  if ((w.present & kAsked) == 0) return true;
  const GCode mo = w.motion;
  const GCode g0 = w.g[kGroupNonModal];
  const bool arc = is_arc(mo);
  const bool cycle = is_cycle(mo);
  const bool spline = mo == 50 || mo == 51 || mo == 52 || mo == 62;
  const int mio = w.m[kMGroupIo];
  auto unused = [&](char letter, const char* who) {
    return error(core::Code::UnusedWord, w.col_of(letter),
                 fmt::format("{} word with no code that uses it ({})", letter, who));
  };
  if ((w.has('I') || w.has('J')) && !(arc || spline || mo == 870 || mo == 760 || g0 == 100)) {
    return unused(w.has('I') ? 'I' : 'J', "G2, G3, G5, G76, G87");
  }
  if (w.has('K') && !(arc || mo == 870 || mo == 760 || mo == 330 || mo == 331 || mo == 62)) {
    return unused('K', "G2, G3, G33, G76, G87");
  }
  if (w.has('R') && !(arc || cycle || mo == 62 || g0 == 100 || w.m[kMGroupSpindle] == 19)) {
    return unused('R', "G2, G3, canned cycles, G10");
  }
  const bool p_user = w.g[kGroupPathControl] == 640 || g0 == 40 || g0 == 100 || arc || cycle ||
                      spline || mio != -1 || w.m[kMGroupSubprogram] != -1 || w.user_m_count > 0 ||
                      w.m[kMGroupSpindle] == 19 || mo == 760;
  if (w.has('P') && !p_user) return unused('P', "G4, G10, G64, G2/G3 turns, dwell cycles, M62-M68");
  const bool q_user = w.g[kGroupPathControl] == 640 || mo == 730 || mo == 830 || mo == 760 ||
                      mo == 50 || mo == 62 || mio != -1 || w.user_m_count > 0 ||
                      w.m[kMGroupSpindle] == 19 || w.m[kMGroupToolChange] == 61;
  if (w.has('Q') && !q_user) return unused('Q', "G64, G73, G83, G5, G76");
  if (w.has('L') && mo == 740 && !rules_.g74_takes_l && g0 != 100) {
    return error(core::Code::UnusedWord, w.col_of('L'),
                 "L word with G74: LinuxCNC repeats no G74 (L is for G10, the other canned "
                 "cycles, G5.2, M98); write the holes one by one");
  }
  if (w.has('L') &&
      !(g0 == 100 || cycle || mo == 52 || w.m[kMGroupSubprogram] != -1 || mio == 66)) {
    return unused('L', "G10, canned cycles, G5.2, M98");
  }
  const GCode comp = w.g[kGroupCutterComp];
  // D: the tool of G41/G42, the diameter of G41.1/G42.1, the top speed of G96.
  if (w.has('D') && !(comp == 410 || comp == 420 || comp == 411 || comp == 421 ||
                      w.g[kGroupSpindleMode] == 960)) {
    return unused('D', "G41, G42, G41.1, G42.1, G96");
  }
  const GCode tlo = w.g[kGroupToolLength];
  if (w.has('H') && !(tlo == 430 || tlo == 432 || mo == 760)) return unused('H', "G43, G43.2");
  if (w.has('E') && mo != 760 && mio == -1) return unused('E', "G76, M62-M68");
  return true;
}

}  // namespace usina::gcode
