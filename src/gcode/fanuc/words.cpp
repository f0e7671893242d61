// Fanuc words real macros use that LinuxCNC has no word for (issue 12 §2,
// docs/fanuc.md §7 "Words of real macros"): the M codes of the machine's
// logic, handed on; a bare G53; G31 skip as a probe move; the look-ahead
// and exact-stop modes with no geometric effect; and the codes usina cannot
// run, named as unsupported.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "gcode/fanuc/engine.hpp"

namespace usina::gcode::fanuc {
namespace {

constexpr std::uint32_t kAxisLetters = Words::letters_of("XYZABCUVW");

// The M codes of the control are the M codes of the dialect's table
// (fanuc/codes.cpp); any other is the machine's.
const InterpCodes::Code* control_m_code(int m) {
  return m >= 0 && m <= kMaxCodeTenths / 10 ? code_table().find('M', m * 10) : nullptr;
}

// A code of the control usina cannot run (fanuc/codes.cpp): what it is.
const CodeEntry* unsupported_g(int tenths) {
  const InterpCodes::Code* c = code_table().find('G', tenths);
  return c != nullptr && c->handler == CodeRun::Unsupported ? c->entry : nullptr;
}

// The bits (Words::g_bit) of every code machine_words looks for: a block
// with none of them (most blocks) costs one test.
std::uint64_t words_bits() {
  static const std::uint64_t bits = [] {
    std::uint64_t b = Words::g_bit(51) | Words::g_bit(50) | Words::g_bit(80) | Words::g_bit(90) |
                      Words::g_bit(530);
    for (const CodeEntry& e : code_table().index().entries())
      if (e.letter == 'G' && unsupported_g(e.code) != nullptr) b |= Words::g_bit(e.code);
    return b;
  }();
  return bits;
}

// A G code as Fanuc's manuals write it: G05.1, G68.2, G08.
std::string g_name(int tenths) {
  return tenths % 10 != 0 ? fmt::format("G{:02}.{}", tenths / 10, tenths % 10)
                          : fmt::format("G{:02}", tenths / 10);
}

// A G code of the block that takes P or Q (G04, G10, cycles, G05, G31,
// G54.1 P, G65, ...): any but the plain modal codes of the usual block.
bool g_takes_p_or_q(const Words& w) {
  if ((w.letters & Words::letter_bit('G')) == 0) return false;
  for (const NcWord& g : w.list) {
    if (g.letter != 'G' || g.taken || g.vacant) continue;
    switch (Words::code(g)) {
    case 0:
    case 10:
    case 20:
    case 30:
    case 170:
    case 180:
    case 190:
    case 200:
    case 210:
    case 400:
    case 430:
    case 440:
    case 490:
    case 800:
    case 900:
    case 910:
    case 940:
    case 950:
    case 980:
    case 990: continue;
    default: return true;
    }
  }
  return false;
}

bool has_axis_word(const Words& w) {
  for (const NcWord& word : w.list)
    if (!word.taken && !word.vacant && (Words::letter_bit(word.letter) & kAxisLetters) != 0)
      return true;
  return false;
}

}  // namespace

bool Engine::machine_codes(const TapeBlock& b, Words& w) {
  passed_m_.clear();
  if (!w.has('M')) return true;
  for (NcWord& word : w.list) {
    if (word.letter != 'M' || word.taken || word.vacant) continue;
    // Not a whole number, or no code at all: the interpreter says so.
    if (word.value != std::floor(word.value) || word.value < 0 || word.value > 99999999) continue;
    const int m = Words::code(word);
    if (const InterpCodes::Code* c = control_m_code(m)) {
      if (c->handler != CodeRun::Unsupported) continue;
      return error(
          core::Code::Unsupported, b, word.pos,
          fmt::format("M{} ({}) is not supported by usina's fanuc dialect", m, c->entry->what));
    }
    const bool listed = machine_m_codes_ && machine_m_codes_->contains(m);
    if (m == 97 && !listed) {
      return error(core::Code::Unsupported, b, word.pos,
                   "M97 (Haas's local subprogram call) is not supported by usina's fanuc "
                   "dialect; call a program with M98 P");
    }
    if (machine_m_codes_ && !listed) {
      return error(core::Code::UnknownMCode, b, word.pos,
                   fmt::format("M{} is neither the control's nor one of the machine's M codes "
                               "(--dialect-option machine_m_codes lists them)",
                               m));
    }
    word.taken = true;
    passed_m_.push_back({'M', m, {}, {}});
  }
  // P and Q go with the machine's code ("M59 P2") when no code of the
  // control in the block takes them.
  const int motion = interp_.state().motion;
  const bool cycle = motion > 30 && motion != 800 && motion != 382;  // a repeat takes P, Q
  if (!passed_m_.empty() && !cycle && !g_takes_p_or_q(w) && !w.has_m(98) && !w.has_m(99) &&
      !w.has_m(198)) {
    for (NcWord& word : w.list) {
      if ((word.letter != 'P' && word.letter != 'Q') || word.taken || word.vacant) continue;
      (word.letter == 'P' ? passed_m_.front().p : passed_m_.front().q) = word.raw;
      word.taken = true;
    }
  }
  return true;
}

void Engine::hand_on_machine_codes(const TapeBlock& b) {
  for (const canon::MachineCode& m : passed_m_)
    stroke_.on(canon::Op{m, b.loc});
  passed_m_.clear();
}

// Before the block's other codes: the codes usina cannot run, the modes
// with no geometric effect, a bare G53. One pass over the block's G words;
// G00-G03 (most blocks) go by at once.
bool Engine::machine_words(const TapeBlock& b, Words& w) {
  if ((w.g_bits & words_bits()) == 0) return true;
  bool modes = false, g53 = false;
  for (NcWord& g : w.list) {
    if (g.letter != 'G' || g.taken || g.vacant) continue;
    const int t = Words::code(g);
    if (t <= 30 && t % 10 == 0) continue;
    if (const CodeEntry* e = unsupported_g(t)) {
      return error(
          core::Code::Unsupported, b, g.pos,
          fmt::format("{} ({}) is not supported by usina's fanuc dialect", g_name(t), e->what));
    }
    modes = modes || t == 51 || t == 50 || t == 80;
    g53 = g53 || t == 530;
    if (t == 90) g.taken = true;  // G09 exact stop: a one-shot of the servo, no geometric effect
  }
  if (modes && !look_ahead_modes(b, w)) return false;
  // A bare G53 moves nothing; on the control it stops the look-ahead, so
  // that system variables read after it are current.
  if (g53 && !has_axis_word(w)) w.take_g(530);
  return true;
}

// G05.1 Q1/Q0 (AI contour control), G05 P10000/P0 (high-precision contour
// control), G08 P1/P0 (look-ahead control): modes of the servo with no
// geometric effect. Their Q or P is theirs.
bool Engine::look_ahead_modes(const TapeBlock& b, Words& w) {
  struct Mode {
    int tenths;
    char letter;
    double on, off;
    const char* name;
  };

  static constexpr Mode kModes[] = {{51, 'Q', 1, 0, "AI contour control"},
                                    {50, 'P', 10000, 0, "high-precision contour control"},
                                    {80, 'P', 1, 0, "look-ahead control"}};
  for (const Mode& m : kModes) {
    if (!w.has_g(m.tenths)) continue;
    const std::string code = g_name(m.tenths);
    NcWord* v = w.find(m.letter);
    if (v == nullptr) {
      return error(core::Code::MissingWord, b, 0,
                   fmt::format("{} ({}) needs {}{} (on) or {}0 (off)", code, m.name, m.letter,
                               word_number(m.on), m.letter));
    }
    if (v->raw != m.on && v->raw != m.off) {
      return error(core::Code::Unsupported, b, v->pos,
                   fmt::format("{} {}{} is not supported by usina's fanuc dialect ({}: {}{} on, "
                               "{}0 off)",
                               code, m.letter, word_number(v->raw), m.name, m.letter,
                               word_number(m.on), m.letter));
    }
    w.take_g(m.tenths);
    v->taken = true;
  }
  return true;
}

}  // namespace usina::gcode::fanuc

namespace usina::gcode::fanuc {

// G31 skip (group 00): the move runs as the interpreter's G38.2 probe
// (docs/fanuc.md "Words of real macros": traced to its target, the stop
// and #5061-#5065 as LinuxCNC's stand-alone G38.2 reports them). The next
// blocks move in the group 1 mode (group_one_motion): the one before, or
// the G00-G03 of the G31 block.
bool Engine::skip_move(const TapeBlock& b, Words& w) {
  if (!w.has_g(310)) return true;
  const int before = interp_.state().motion;
  if (before > 30 && before != 800 && before != 382) {
    return error(core::Code::NotAllowedInMode, b, 0,
                 fmt::format("G31 skip in canned cycle mode (G{}): cancel the cycle with G80 first",
                             word_number(before / 10.0)));
  }
  if (NcWord* p = w.find('P')) {
    // P1..P4 choose the skip signal (multi-step skip); one probe here.
    if (p->raw != 1 && p->raw != 2 && p->raw != 3 && p->raw != 4) {
      return error(core::Code::BadWordValue, b, p->pos,
                   fmt::format("G31 P{}: the skip signal is P1 to P4", word_number(p->raw)));
    }
    p->taken = true;
  }
  for (NcWord& g : w.list) {
    if (g.letter != 'G' || g.taken) continue;
    const int t = Words::code(g);
    if (t <= 30) {
      g.taken = true;  // the mode after the block (motion_ holds it)
    } else if (t == 310) {
      g.value = 38.2;
      g.code = 382;
      w.g_bits |= Words::g_bit(382);
    }
  }
  return true;
}

}  // namespace usina::gcode::fanuc
