// NC blocks of the fanuc dialect: words with macro values (a vacant
// variable leaves its word out), the decimal-point rule, the codes the
// front end runs itself (M98 M99 G65 G66 G67, Fanuc's G04 P and cycle P K,
// G10 L2 in G91), and the hand-over to the RS274NGC interpreter.
#include <cctype>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "gcode/fanuc/engine.hpp"
#include "gcode/fanuc/plain_words.hpp"
#include "gcode/number_form.hpp"
#include "gcode/word_range.hpp"

namespace usina::gcode::fanuc {
namespace {

constexpr std::uint32_t kAxisLetters = Words::letters_of("XYZABCUVW");

// Distances and angles: the decimal-point rule applies (§2).
bool is_distance(char l) {
  constexpr std::uint32_t kDistances = Words::letters_of("XYZUVWABCIJKRQ");
  return (Words::letter_bit(l) & kDistances) != 0;
}

// A code as a whole number, rounded half away from zero as std::lround
// does, without a library call per word of every block (the codes are
// asked for dozens of times a block); far out of range: no code.
long whole(double v) {
  if (!(v > -1e9 && v < 1e9)) return std::numeric_limits<long>::min();
  return static_cast<long>(v < 0 ? v - 0.5 : v + 0.5);
}

// `whole` as an int; far out of range: no code any block asks for.
int as_code(long v) {
  return v >= -100'000'000 && v <= 100'000'000 ? static_cast<int>(v)
                                               : std::numeric_limits<int>::min();
}

int tenths(double v) {
  return as_code(whole(v * 10.0));
}

bool is_cycle(int g) {
  return g == 730 || g == 740 || g == 760 || (g >= 810 && g <= 890);
}

}  // namespace

std::string word_number(double v) {
  if (std::fabs(v) < 5e-11) v = 0;
  std::string s = fmt::format("{:.10f}", v);
  while (!s.empty() && s.back() == '0')
    s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

NcWord* Words::lookup(char letter) {
  for (NcWord& w : list)
    if (w.letter == letter && !w.taken && !w.vacant) return &w;
  return nullptr;
}

double Words::get(char letter, double fallback) {
  const NcWord* w = find(letter);
  return w != nullptr ? w->value : fallback;
}

int Words::code_of(const NcWord& w) {
  return w.letter == 'G' ? tenths(w.value) : as_code(whole(w.value));
}

bool Words::holds_g(int t) const {
  for (const NcWord& w : list)
    if (w.letter == 'G' && !w.taken && code(w) == t) return true;
  return false;
}

bool Words::holds_m(int m) const {
  for (const NcWord& w : list)
    if (w.letter == 'M' && !w.taken && code(w) == m) return true;
  return false;
}

void Words::drop_g(int t) {
  for (NcWord& w : list)
    if (w.letter == 'G' && code(w) == t) w.taken = true;
}

void Words::take_m(int m) {
  for (NcWord& w : list)
    if (w.letter == 'M' && code(w) == m) w.taken = true;
}

void Words::take(char letter) {
  if ((letters & letter_bit(letter)) == 0) return;
  for (NcWord& w : list)
    if (w.letter == letter) w.taken = true;
}

// The least input increment of an address (IS-B), what ROUND rounds to in
// it: 0.001 mm / 0.0001 in for distances, 0.001 deg for A B C, 1 mm/min
// (0.01 in/min) for F, 1 for the integer addresses.
// `inch`: the block's units so far (a G20/G21 read before the word counts).
double Engine::least_increment(char letter, bool inch) const {
  if (letter == 'A' || letter == 'B' || letter == 'C') return 0.001;
  if (is_distance(letter)) return inch ? 0.0001 : 0.001;
  if (letter == 'F') return inch ? 0.01 : 1.0;
  return 1.0;
}

// The word's value within usina's range (gcode/word_range.hpp), and a
// literal not followed by an exponent beyond any number ("X1e400").
bool Engine::word_in_range(const TapeBlock& b, char letter, std::size_t at, const MacroReader& r,
                           const Value& v) {
  if (r.literal()) {
    if (const auto ok = exponent_out_of_range(b.text, at + 1, r.pos()); !ok)
      return error(core::Code::NumberOutOfRange, b, at + 1, ok.error());
  }
  if (v.vacant) return true;
  if (const auto ok = word_out_of_range(letter, v.v); !ok)
    return error(core::Code::ValueOutOfRange, b, at, ok.error());
  return true;
}

namespace {

// The words of a plain block (plain_words.hpp) into `w`; false with `w`
// empty for any other block.
bool plain_block_words(std::string_view text, Words& w) {
  const bool plain = plain_words(text, [&](char l, double value, bool point, std::size_t pos) {
    NcWord& word = w.next();
    word.letter = l;
    word.value = word.raw = value;
    word.integer_literal = !point;
    word.pos = pos;
    if (l == 'G') word.code = tenths(value);
    if (l == 'M') word.code = as_code(whole(value));
    w.added();
    return true;
  });
  if (!plain) w.clear();
  return plain;
}

}  // namespace

bool Engine::read_words(const TapeBlock& b, Words& w) {
  if (plain_block_words(b.text, w)) {
    // The checks of read_words below, for the words as they are.
    for (NcWord& word : w.list) {
      if (!word_value_in_range(word.letter, word.value)) {
        return error(core::Code::ValueOutOfRange, b, word.pos,
                     word_range_error(word.letter, word.value));
      }
      word.checked = true;
    }
    return true;
  }
  MacroReader r(b.text, *this);
  // The units the words read so far are in, kept as they come: asking the
  // list for G20/G21 before each word made a block quadratic in its length.
  bool inch = interp_.state().units == core::LengthUnit::Inch;
  bool g20 = false, g21 = false;
  while (!r.at_end()) {
    const std::size_t at = r.pos();
    const char l = r.peek();
    if (l == '=' || l == '#') {
      return error(core::Code::MacroFormat, b, at,
                   "a macro statement stands alone in its block (Fanuc alarm 114)");
    }
    if (l < 'A' || l > 'Z') {
      return error(core::Code::UnexpectedCharacter, b, at,
                   fmt::format("'{}' where a word's letter was expected", b.text[at]));
    }
    r.set_pos(at + 1);
    r.set_round_step(least_increment(l, !g21 && (g20 || inch)));
    auto v = r.expression();
    if (!v) return macro_error(r, b);
    if (!word_in_range(b, l, at, r, *v)) return false;
    NcWord& word = w.next();
    word.letter = l;
    word.value = word.raw = v->v;
    word.integer_literal = r.literal() && !r.had_point();
    word.vacant = v->vacant && r.single_variable();
    word.checked = !v->vacant;  // word_in_range
    word.pos = at;
    // Codes are asked for dozens of times a block: read them once.
    if (l == 'G') word.code = tenths(word.value);
    if (l == 'M') word.code = as_code(whole(word.value));
    w.added();
    if (l == 'G') {
      g20 = g20 || tenths(word.value) == 200;
      g21 = g21 || tenths(word.value) == 210;
    }
  }
  return true;
}

void Engine::decimal_point(const TapeBlock& b, Words& w) {
  bool inch = interp_.state().units == core::LengthUnit::Inch;
  if (w.has_g(200)) inch = true;
  if (w.has_g(210)) inch = false;
  const bool cycle = is_cycle(interp_.state().motion);
  bool cycle_block = cycle;
  for (const NcWord& g : w.list)
    if (g.letter == 'G' && is_cycle(tenths(g.value))) cycle_block = true;
  for (NcWord& word : w.list) {
    if (!word.integer_literal || !is_distance(word.letter)) continue;
    if (word.letter == 'K' && cycle_block) continue;  // a repeat count
    if (word.letter == 'Q' && w.has_g(51)) continue;  // G05.1's Q1/Q0: on or off
    if (dpi_fanuc_) {
      word.value = word.raw * (inch ? 0.0001 : 0.001);
    } else if (!warned_integer_ && word.raw != 0.0) {
      warned_integer_ = true;
      warn(
          core::Code::IntegerCoordinate, b, word.pos,
          fmt::format("{}{} has no decimal point: read as {} {}; a Fanuc control with DPI = 0 "
                      "reads {} {} (--dialect-option decimal_point=fanuc)",
                      word.letter, word_number(word.raw), word_number(word.raw), inch ? "in" : "mm",
                      word_number(word.raw * (inch ? 0.0001 : 0.001)), inch ? "in" : "mm"));
    }
  }
}

// Argument specification I and II (docs/fanuc.md §6): letters to #1-#26,
// repeated I J K to the triples #4-#33.
std::array<Value, 34> Engine::arguments(Words& w) {
  static constexpr std::string_view kLetters = "ABCDEFHIJKMQRSTUVWXYZ";
  static constexpr int kVar[] = {1,  2,  3,  7,  8,  9,  11, 4,  5,  6, 13,
                                 17, 18, 19, 20, 21, 22, 23, 24, 25, 26};
  std::array<Value, 34> args = vacant_locals();
  int triples[3] = {0, 0, 0};
  for (NcWord& word : w.list) {
    if (word.taken) continue;
    const std::size_t at = kLetters.find(word.letter);
    if (at == std::string_view::npos) continue;
    int var = kVar[at];
    if (word.letter == 'I' || word.letter == 'J' || word.letter == 'K') {
      const int t = word.letter - 'I';
      var = 4 + t + 3 * triples[t]++;
      if (var > 33) continue;
    }
    word.taken = true;
    if (!word.vacant) args[static_cast<std::size_t>(var)] = Value{word.value};
  }
  return args;
}

bool Engine::macro_call(const TapeBlock& b, Words& w) {
  const bool modal = w.has_g(660);
  w.take_g(modal ? 660 : 650);
  for (const NcWord& g : w.list) {
    if ((g.letter == 'G' || g.letter == 'N' || g.letter == 'O') && !g.taken) {
      return error(core::Code::MacroFormat, b, g.pos,
                   fmt::format("{} is not an argument of G65/G66 (Fanuc alarm 114)", g.letter));
    }
  }
  const NcWord* p = w.find('P');
  if (p == nullptr)
    return error(core::Code::MissingWord, b, 0, "G65/G66 needs P (the macro's program number)");
  const long program = std::lround(p->raw);
  const long times = std::lround(w.get('L', 1));
  w.take('P');
  w.take('L');
  std::array<Value, 34> args = arguments(w);
  if (modal) {
    modal_call_ = ModalCall{program, times, args};
    return true;
  }
  return call(program, times, true, &args, b, p->pos, false);
}

bool Engine::nc_block(const TapeBlock& b) {
  if (const std::optional<bool> ran = straight_block(b)) return *ran;
  Words& w = words_;  // its list's storage serves every block
  w.clear();
  if (!read_words(b, w)) return false;
  if (plain_move(w)) return plain_move_block(b, w);
  decimal_point(b, w);
  for (const NcWord& g : w.list) {
    if (g.letter == 'M' && !g.vacant) m_ = g.value;
    if (g.letter == 'D' && !g.vacant) d_ = g.value;
    if (g.letter == 'H' && !g.vacant) h_ = g.value;
  }
  if (!machine_codes(b, w) || !machine_words(b, w)) return false;
  if (w.has_g(650) || w.has_g(660)) return macro_call(b, w);
  if (w.has_g(670)) {
    w.take_g(670);
    modal_call_.reset();
  }
  if (!fanuc_codes(b, w) || !offset_codes(b, w) || !transform_codes(b, w) || !convert_codes(b, w))
    return false;
  if (!transform_words(b, w)) return false;
  if (polar_interp_.active() && !polar_interp_move(b, w)) return false;
  // M98 / M99 run after the block's other words (the move first).
  std::optional<long> sub, back;
  long times = 1;
  std::size_t call_pos = 0;
  if (w.has_m(98)) {
    w.take_m(98);
    const NcWord* p = w.find('P');
    if (p == nullptr) return error(core::Code::MissingWord, b, 0, "M98 needs P (the program)");
    call_pos = p->pos;
    long pv = std::lround(p->raw);
    const NcWord* l = w.find('L');
    if (l != nullptr) {
      times = std::lround(l->raw);
    } else if (program_digits_ == 4 && pv >= 10000) {
      times = pv / 10000;  // M98 P30010: O0010 three times
      pv %= 10000;
    }
    sub = pv;
    w.take('P');
    w.take('L');
  } else if (w.has_m(99)) {
    w.take_m(99);
    const NcWord* p = w.find('P');
    back = p != nullptr ? std::lround(p->raw) : -1;
    if (p != nullptr) call_pos = p->pos;
    w.take('P');
  }
  bool moved = false;
  for (const NcWord& word : w.list)
    moved = moved ||
            (!word.taken && !word.vacant && (Words::letter_bit(word.letter) & kAxisLetters) != 0);
  if (w.has_g(760) || w.has_g(870) || ((cycle_ == 760 || cycle_ == 870) && !w.has_g(800))) {
    if (!fine_boring(b, w)) return false;
  }
  group_one_motion(w);
  if (!skip_move(b, w)) return false;
  // The machine's M codes after the block's moves, before its end.
  const bool ends = w.has_m(2) || w.has_m(30);
  if (ends && !passed_m_.empty()) hand_on_machine_codes(b);
  if (!hand_over(b, w)) return false;
  if (!passed_m_.empty()) hand_on_machine_codes(b);
  if (!xf_.active() && !polar_) reset_program_point();
  if (sub) return call(*sub, times, false, nullptr, b, call_pos, false);
  if (back) return give_back(*back, b, call_pos);
  bool in_modal_macro = false;
  for (const Frame& f : frames_)
    in_modal_macro = in_modal_macro || f.modal_call;
  if (modal_call_ && moved && !in_modal_macro) {
    return call(modal_call_->program, modal_call_->repeats, true, &modal_call_->args, b, 0, true);
  }
  return true;
}

// Fanuc's codes the front end keeps track of or runs itself.
bool Engine::fanuc_codes(const TapeBlock& b, Words& w) {
  if (!polar_interp_codes(b, w)) return false;  // fanuc/polar_nc.cpp
  for (const NcWord& g : w.list) {
    if (g.letter != 'G' || g.taken) continue;
    const int t = tenths(g.value);
    if (t <= 30) motion_ = t;
    if (t <= 30 || is_cycle(t) || t == 800) cycle_ = t;  // the last motion of groups 1 and 9
    if (t == 430 || t == 490) length_mode_ = t;
  }
  if (!stroke_codes(b, w) || !work_codes(b, w)) return false;
  if (w.has_g(100)) {
    offsets_written_ = true;
    const long l = std::lround(w.get('L', 0));
    if (l >= 10 && l <= 13) return write_register(b, w, l);
    return work_offset(b, w, l);  // L2, L20, L50 (fanuc/workspaces.cpp)
  }
  return true;
}

namespace {

// The block gives an axis word that is not another code's (G04, G10,
// G28, G30, G52, G92 read theirs): in a canned cycle's mode, a hole there.
bool positions_a_hole(const Words& w) {
  for (const int g : {40, 100, 280, 300, 520, 920}) {
    if (w.has_g(g)) return false;
  }
  for (const NcWord& word : w.list) {
    if (!word.taken && !word.vacant && (Words::letter_bit(word.letter) & kAxisLetters) != 0)
      return true;
  }
  return false;
}

}  // namespace

// Fanuc's meanings of words the interpreter reads otherwise.
bool Engine::convert_codes(const TapeBlock&, Words& w) {
  if (w.has_g(40)) {
    // G04: P in milliseconds, X in seconds; LinuxCNC's P is seconds.
    NcWord* x = w.find('X');
    NcWord* p = w.find('P');
    if (p != nullptr) {
      p->value = p->raw / 1000.0;
    } else if (x != nullptr) {
      w.relabel(*x, 'P');
    }
  }
  // The interpreter never enters G76/G87 (fine_boring writes its moves).
  int motion = cycle_ == 760 || cycle_ == 870 ? cycle_ : interp_.state().motion;
  bool starts = false;
  for (const NcWord& g : w.list)
    starts = starts || (g.letter == 'G' && !g.taken && is_cycle(tenths(g.value)));
  for (const NcWord& g : w.list)
    if (g.letter == 'G' && !g.taken &&
        (tenths(g.value) <= 30 || is_cycle(tenths(g.value)) || tenths(g.value) == 800))
      motion = tenths(g.value);
  if (motion == 800 || motion <= 30) {
    cycle_r_ = cycle_z_ = cycle_p_ = std::nullopt;
    g76_.initial.reset();
  }
  // A block of the cycle's mode drills only with positioning data of its
  // own (an M05 or G04 block between holes does not): only then are its
  // levels and dwell the cycle's.
  if (is_cycle(motion) && (starts || positions_a_hole(w))) {
    if (motion != 760 && motion != 870)  // fine_boring keeps its levels itself
      cycle_levels(w, w.has_g(910) || (interp_.state().incremental && !w.has_g(900)));
    if (NcWord* p = w.find('P')) {
      p->value = p->raw / 1000.0;
      cycle_p_ = p->value;
    } else if (starts && (cycle_p_ || motion == 820 || motion == 860 || motion == 890)) {
      // The dwell is modal on Fanuc; LinuxCNC wants P when a cycle starts.
      const double v = cycle_p_.value_or(0.0);
      w.add({'P', v, v, false, false, false, 0});
    }
    if (NcWord* q = w.find('Q')) q->value = std::fabs(q->value);
    if (NcWord* k = w.find('K')) w.relabel(*k, 'L');
  }
  return true;
}

std::optional<double> Engine::cycle_level() const {
  return is_cycle(interp_.state().motion) ? cycle_level_ : std::nullopt;
}

// R and Z of a cycle block: given, they are remembered as positions; left
// out, the remembered ones are written for the interpreter, which needs R
// in the block that starts a cycle and re-reads the numbers under G91.
void Engine::cycle_levels(Words& w, bool incremental) {
  const double per = core::mm_per(interp_.state().units);
  const double z_now = interp_.state().pos[2] / per;
  const double initial = cycle_level() ? *cycle_level() / per : z_now;
  NcWord* r = w.find('R');
  NcWord* z = w.find('Z');
  const std::optional<double> r_abs =
      r != nullptr ? std::optional<double>(incremental ? initial + r->value : r->value) : cycle_r_;
  if (r_abs && z != nullptr) cycle_z_ = incremental ? *r_abs + z->value : z->value;
  if (r_abs) cycle_r_ = r_abs;
  if (r == nullptr && cycle_r_) {
    const double v = incremental ? *cycle_r_ - initial : *cycle_r_;
    w.add({'R', v, v, false, false, false, 0});
  }
  if (z == nullptr && cycle_z_ && cycle_r_) {
    const double v = incremental ? *cycle_z_ - *cycle_r_ : *cycle_z_;
    w.add({'Z', v, v, false, false, false, 0});
  }
}

// G76 fine boring and G87 back boring (docs/fanuc.md §7), handed to the
// interpreter as the moves they make. R and Z are kept as positions as in
// the other cycles: in G91, R is the distance from the initial level and Z
// from the R point, X Y from the current point, and each of the K repeats
// steps the hole by X Y again (in G90 K bores the same hole K times).
bool Engine::fine_boring(const TapeBlock& b, Words& w) {
  const int code = w.has_g(870) ? 870 : w.has_g(760) ? 760 : cycle_;
  // G98/G99 go on to the interpreter, which keeps the return mode.
  const bool to_r =
      w.has_g(990) || (interp_.state().retract == RetractMode::RPlane && !w.has_g(980));
  const bool incremental = w.has_g(910) || (interp_.state().incremental && !w.has_g(900));
  const core::Vec3 here = actual_xyz();
  if (!g76_.initial) g76_.initial = here.z;
  if (NcWord* r = w.find('R')) cycle_r_ = incremental ? *g76_.initial + r->value : r->value;
  if (NcWord* z = w.find('Z')) {
    if (incremental && !cycle_r_)
      return error(core::Code::MissingWord, b, z->pos, "G76/G87 in G91 needs R before Z");
    cycle_z_ = incremental ? *cycle_r_ + z->value : z->value;
  }
  if (NcWord* q = w.find('Q')) g76_.q = std::fabs(q->value);
  if (NcWord* p = w.find('P')) g76_.p = p->value;  // seconds (convert_codes)
  if (NcWord* f = w.find('F')) g76_.f = f->value;
  const NcWord* k = w.find('L');  // K, renamed by convert_codes
  const long repeats = k != nullptr ? std::lround(k->value) : 1;
  const bool hole = w.has('X') || w.has('Y');
  const core::Vec2 step{w.get('X', incremental ? 0.0 : here.x),
                        w.get('Y', incremental ? 0.0 : here.y)};
  for (char l : std::string_view("XYZRQPFKL"))
    w.take(l);
  w.take_g(760);
  w.take_g(870);
  cycle_ = code;
  if (code == 870 && to_r)
    return error(core::Code::NotAllowedInMode, b, 0, "G87 back boring does not take G99");
  if (!hole || repeats <= 0) return true;  // K0 keeps the data without boring
  if (block_plane(w) != core::Plane::XY)
    return error(core::Code::Unsupported, b, 0, "G76/G87 outside G17 is not implemented");
  if (!cycle_r_ || !cycle_z_)
    return error(core::Code::MissingWord, b, 0, "G76 needs R and Z when it starts");
  const core::Vec2 first = incremental ? core::Vec2{here.x + step.x, here.y + step.y} : step;
  return fine_boring_holes(b, code, to_r, first, incremental ? step : core::Vec2{}, repeats);
}

// The moves of the fine/back boring holes, in G90 whatever the program's
// mode (restored after).
bool Engine::fine_boring_holes(const TapeBlock& b, int code, bool to_r, core::Vec2 first,
                               core::Vec2 step, long repeats) {
  const bool was_incremental = interp_.state().incremental;
  const double r = *cycle_r_, z = *cycle_z_, top = *g76_.initial, q = g76_.q;
  const double back = to_r ? r : std::max(top, r);
  // Parameter 5101 RD2 RD1: +X -X +Y -Y, in the machine's axes: the
  // oriented spindle points the tip one way whatever G68/G51.1 do to the
  // program, so the shift is added after them (the hole is transformed).
  const double dx = g76_.shift == 0 ? q : g76_.shift == 1 ? -q : 0.0;
  const double dy = g76_.shift == 2 ? q : g76_.shift == 3 ? -q : 0.0;
  if (!hand(b, {{'G', 90}})) return false;
  for (long n = 0; n < repeats; ++n) {
    const double x = first.x + step.x * static_cast<double>(n);
    const double y = first.y + step.y * static_cast<double>(n);
    const auto hole = [&] { return hand(b, {{'G', 0}, {'X', x}, {'Y', y}}); };
    const auto shifted = [&] { return hand(b, {{'G', 0}, {'X', x + dx}, {'Y', y + dy}}); };
    const auto orient = [&] { return hand(b, {{'M', 19}}); };
    const auto bore = [&] {
      return hand(b, {{'G', 1}, {'Z', z}, {'F', g76_.f}}) && hand(b, {{'G', 4}, {'P', g76_.p}});
    };
    const auto out = [&](double level) {
      return hand(b, {{'G', 0}, {'Z', level}}) && hole() && hand(b, {{'M', 3}});
    };
    // G76: down to Z, dwell, orient, shift off the wall, out, back on the
    // hole's axis. G87: in shifted, down to R (the bottom), back on the
    // axis, bore up to Z, dwell, orient, shift, out above the part.
    if (!hole()) return false;
    const bool ok =
        code == 760 ? hand(b, {{'G', 0}, {'Z', r}}) && bore() && orient() && shifted() && out(back)
                    : orient() && shifted() && hand(b, {{'G', 0}, {'Z', r}}) && hole() &&
                          hand(b, {{'M', 3}}) && bore() && orient() && shifted() && out(top);
    if (!ok) return false;
  }
  return !was_incremental || hand(b, {{'G', 91}});
}

// Fanuc's G80 is a group of its own: after it (and at power-on) axis words
// move in the group 1 mode (G00 at first); LinuxCNC's G80 stops motion.
// So do they after a G31 skip (one-shot; the interpreter's G38.2 is modal).
void Engine::group_one_motion(Words& w) {
  if (interp_.state().motion != 800 && interp_.state().motion != 382) return;
  bool axes = false;
  for (const NcWord& word : w.list) {
    if (word.taken || word.vacant) continue;
    if ((Words::letter_bit(word.letter) & kAxisLetters) != 0) axes = true;
    if (word.letter != 'G') continue;
    const int t = tenths(word.value);
    if (t <= 30 || is_cycle(t) || t == 800 || t == 40 || t == 100 || t == 280 || t == 300 ||
        t == 520 || t == 530 || t == 920 || t == 431 || t == 310)
      return;
  }
  if (axes) w.add_g(motion_ / 10.0);
}

// The block's words down the interpreter's one road: its G codes in
// tenths (one mirrored axis swaps the side of cutter compensation), M and L
// as whole numbers, each word at the column the user wrote it at.
bool Engine::hand_over(const TapeBlock& b, Words& w) {
  handed_.clear();
  const std::uint32_t col0 = loc_of(b, 0).col;  // a word's column is col0 + its position
  for (const NcWord& word : w.list) {
    if (word.taken || word.vacant) continue;
    // Read in range (word_in_range), a value leaves it only by the scaling
    // or rotation in force: say so at the word.
    if (!(word.checked && word.value == word.raw))
      if (const auto ok = word_out_of_range(word.letter, word.value); !ok) {
        return error(core::Code::ValueOutOfRange, b, word.pos,
                     fmt::format("{}, after the scaling, rotation or mirror in force (G51, G68, "
                                 "G51.1)",
                                 ok.error()));
      }
    double v = word.value;
    if (word.letter == 'G') {
      int t = tenths(v);
      if (xf_.reverses(interp_.state().plane) && (t == 410 || t == 420 || t == 411 || t == 421))
        t = t < 415 ? t + 10 : t - 10;
      v = t / 10.0;
    } else if (word.letter == 'M' || word.letter == 'L') {
      v = static_cast<double>(std::lround(v));
    }
    handed_.push_back({word.letter, v, col0 + static_cast<std::uint32_t>(word.pos)});
  }
  return hand(b, handed_);
}

bool Engine::hand(const TapeBlock& b, std::span<const EvaluatedWord> words) {
  return interp_.run_evaluated({b.loc, words, {}, {}});
}

bool Engine::hand(const TapeBlock& b, std::initializer_list<EvaluatedWord> words) {
  return hand(b, std::span<const EvaluatedWord>(words.begin(), words.size()));
}

}  // namespace usina::gcode::fanuc
