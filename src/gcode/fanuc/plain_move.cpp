// The shortcut of a plain move: a block of G00-G03 and X Y Z I J K R F S
// words written with a point, outside every mode the front end changes
// moves in (transformations, polar coordinates or interpolation, canned
// cycles, a modal macro call, the move after G69). Such a block is most
// blocks of a long program, and each pass of nc_block would let it by
// unchanged: it goes straight to the hand-over with what those passes would
// have recorded (issue 19). A block of G00 or G01 and X Y Z F only goes
// further: read from the tape into the interpreter's plain move, with no
// list of words (straight_block). A block that is not plain in every
// respect takes the whole road; a test compares the two
// (tests/gcode/fanuc/plain_move_test.cpp).
#include "gcode/fanuc/engine.hpp"
#include "gcode/fanuc/plain_words.hpp"

namespace usina::gcode::fanuc {

namespace {

// A block of G00 or G01 and X Y Z F, each once, the distances written with
// a point: the move it is, read from the tape in one pass. False for any
// other block, which is read word by word. A value out of range is
// Interpreter::run_plain_move's to find (it answers nullopt, and the words
// give the error).
bool read_straight(std::string_view text, PlainMove& move) {
  constexpr std::uint32_t kStraight = Words::letters_of("GXYZF");
  std::uint32_t seen = 0;
  return plain_words(text, [&](char l, double value, bool point, std::size_t) {
    const std::uint32_t bit = Words::letter_bit(l);
    if ((kStraight & bit) == 0 || (seen & bit) != 0) return false;
    seen |= bit;
    // An integer distance is the decimal-point rule's (it may warn).
    if (!point && l != 'G' && l != 'F') return false;
    return move.take(l, value);
  });
}

}  // namespace

// The modes that change moves or add words (nc_block's passes).
bool Engine::plain_modes() const {
  return plain_move_shortcut_ && !xf_.active() && !polar_ && !polar_interp_.active() &&
         !after_g69_ && !modal_call_ && interp_.state().motion <= 30 && cycle_ != 760 &&
         cycle_ != 870;
}

bool Engine::plain_move(const Words& w) const {
  constexpr std::uint32_t kPlain = Words::letters_of("GXYZIJKRFS");
  constexpr std::uint32_t kDistances = Words::letters_of("XYZIJKR");
  if ((w.letters & ~kPlain) != 0 || !plain_modes()) return false;
  for (const NcWord& word : w.list) {
    // A vacant word, a value to check after its rule, or a distance the
    // decimal-point rule reads (it may also warn).
    if (word.vacant || !word.checked) return false;
    if (word.integer_literal && (Words::letter_bit(word.letter) & kDistances) != 0) return false;
    if (word.letter == 'G' && (word.code < 0 || word.code > 30 || word.code % 10 != 0))
      return false;
  }
  return true;
}

bool Engine::plain_move_block(const TapeBlock& b, const Words& w) {
  passed_m_.clear();  // machine_codes: no M word
  handed_.clear();
  const std::uint32_t col0 = loc_of(b, 0).col;
  for (const NcWord& word : w.list) {
    double v = word.value;
    if (word.letter == 'G') {
      motion_ = cycle_ = word.code;  // fanuc_codes
      v = word.code / 10.0;
    }
    handed_.push_back({word.letter, v, col0 + static_cast<std::uint32_t>(word.pos)});
  }
  // A cycle's levels (convert_codes) were forgotten by the block that left
  // its mode: the interpreter's motion is group 1's by now.
  if (!hand(b, handed_)) return false;
  reset_program_point();
  return true;
}

// G00 or G01 and X Y Z F only (read_straight): handed to the interpreter as
// a plain move, past the words, when the modes and the interpreter take it
// as one (issue 19); what plain_move_block would do for it.
std::optional<bool> Engine::straight_block(const TapeBlock& b) {
  if (!plain_modes()) return std::nullopt;
  PlainMove move;
  if (!read_straight(b.text, move)) return std::nullopt;
  const std::optional<bool> ran = interp_.run_plain_move(b.loc, move);
  if (!ran) return std::nullopt;
  if (move.motion != -1) motion_ = cycle_ = move.motion;  // fanuc_codes
  if (!*ran) return false;
  reset_program_point();
  return true;
}

}  // namespace usina::gcode::fanuc
