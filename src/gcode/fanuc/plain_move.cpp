// The shortcut of a plain move: a block of G00-G03 and X Y Z I J K R F S
// words written with a point, outside every mode the front end changes
// moves in (transformations, polar coordinates or interpolation, canned
// cycles, a modal macro call, the move after G69). Such a block is most
// blocks of a long program, and each pass of nc_block would let it by
// unchanged: it goes straight to the hand-over with what those passes would
// have recorded (issue 19). A block that is not plain in every respect
// takes the whole road; a test compares the two
// (tests/gcode/fanuc/plain_move_test.cpp).
#include <bit>

#include "gcode/fanuc/engine.hpp"

namespace usina::gcode::fanuc {

bool Engine::plain_move(const Words& w) const {
  constexpr std::uint32_t kPlain = Words::letters_of("GXYZIJKRFS");
  constexpr std::uint32_t kDistances = Words::letters_of("XYZIJKR");
  if (!plain_move_shortcut_ || (w.letters & ~kPlain) != 0) return false;
  // The modes that change moves or add words (nc_block's passes).
  if (xf_.active() || polar_ || polar_interp_.active() || after_g69_ || modal_call_) return false;
  if (interp_.state().motion > 30 || cycle_ == 760 || cycle_ == 870) return false;
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
  if (const std::optional<bool> ran = straight_past_words(b, w)) {
    if (!*ran) return false;
    reset_program_point();
    return true;
  }
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

// G00 or G01 and X Y Z F only, each once: handed to the interpreter as a
// plain move, past the words, when it takes it as one (issue 19).
std::optional<bool> Engine::straight_past_words(const TapeBlock& b, const Words& w) {
  constexpr std::uint32_t kStraight = Words::letters_of("GXYZF");
  if ((w.letters & ~kStraight) != 0 ||
      w.list.size() != static_cast<std::size_t>(std::popcount(w.letters))) {
    return std::nullopt;
  }
  PlainMove move;
  for (const NcWord& word : w.list) {
    if (word.letter == 'G') {
      if (word.code != 0 && word.code != 10) return std::nullopt;
      move.motion = word.code;
    } else if (word.letter == 'F') {
      move.f = word.value;
      move.given |= PlainMove::kF;
    } else {
      const auto i = static_cast<unsigned>(word.letter - 'X');
      move.xyz[i] = word.value;
      move.given |= 1u << i;
    }
  }
  const std::optional<bool> ran = interp_.run_plain_move(b.loc, move);
  if (ran && move.motion != -1) motion_ = cycle_ = move.motion;  // fanuc_codes
  return ran;
}

}  // namespace usina::gcode::fanuc
