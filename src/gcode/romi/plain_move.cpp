// The shortcut of a plain move: a block of G00 or G01 and absolute X Y Z
// (F besides), with no blend arc waiting, no drilling cycle in force and
// G90. Such a block is most blocks of a long program; evaluating its words,
// importing them into the groups, running the motion handler and working
// out its end by the general road would let it by unchanged: the engine
// reads the move from the parsed words (Engine::plain_words) and the
// translator hands it over with what those steps would have recorded
// (issue 19). A block that is not plain in every respect takes the whole
// road; a test compares the two (tests/gcode/romi/plain_move_test.cpp).
#include "gcode/romi/engine.hpp"
#include "gcode/romi/translate.hpp"
#include "gcode/word_range.hpp"

namespace usina::gcode::romi {

// The block's words as a plain move, read where the parser left them (no
// evaluated words): G00 or G01, F, X Y Z, each once, plain numbers in
// range. False for any other block: the whole road reads it (and says what
// is wrong with it). Plain numbers (kPlainNumber) come from
// parse_plain_romi_block alone, which reads a block of upper-case words and
// nothing else: no comment, statement, typographic dash or lower case.
bool Engine::plain_words(PlainMove& move) const {
  if (!dialect_options_.plain_move_shortcut) return false;
  std::uint32_t seen = 0;
  for (const RomiWord& w : block_.words) {
    // A letter twice: an error the whole road reports, as a value out of
    // range. (A plain letter is upper case: the second test guards the shift.)
    if (w.value != kPlainNumber || w.letter < 'A' || w.letter > 'Z' ||
        !word_value_in_range(w.letter, w.number))
      return false;
    constexpr std::uint32_t kPlain = (1u << ('G' - 'A')) | (1u << ('F' - 'A')) |
                                     (1u << ('X' - 'A')) | (1u << ('Y' - 'A')) |
                                     (1u << ('Z' - 'A'));
    const std::uint32_t bit = 1u << (w.letter - 'A');
    if ((kPlain & bit) == 0 || (seen & bit) != 0) return false;
    seen |= bit;
    if (w.letter == 'F' && !(w.number >= 0.0)) return false;  // a negative feed rate: its error
    if (!move.take(w.letter, w.number)) return false;
  }
  return (move.given & 7u) != 0;
}

// The plain move in romi's modes: nullopt when one of them changes how a
// move is read (a blend waiting, a drilling cycle, G91), or for G01 with
// no feed rate (the whole road says so); else the block's result.
std::optional<bool> Translator::run_plain_move(const core::SourceLoc& loc, const PlainMove& move) {
  if (work_.blend || work_.drill.active || work_.machine.incremental) return std::nullopt;
  const bool feed_given = (move.given & PlainMove::kF) != 0;
  const GCode motion = move.motion >= 0 ? move.motion : work_.machine.motion;
  const double feed = feed_given ? mm(move.f) : work_.machine.feed;
  if (motion != 0 && (motion != 10 || !(feed > 0.0))) return std::nullopt;
  PlainWords words{move.motion, feed_given, feed, work_.pos};
  // By name, not end[axis]: an indexed store kept `end` in memory, read
  // back whole before the store had landed (issue 19).
  if ((move.given & 1u) != 0) words.end.x = mm(move.xyz[0]);
  if ((move.given & 2u) != 0) words.end.y = mm(move.xyz[1]);
  if ((move.given & 4u) != 0) words.end.z = mm(move.xyz[2]);
  return plain_move_block(loc, words);
}

// run_evaluated's steps for the block: values() (F), the motion handler,
// move() (the end point, absolute in program units), then as for any block.
bool Translator::plain_move_block(const core::SourceLoc& loc, const PlainWords& move) {
  begin_block(EvaluatedBlock{loc, {}, {}, {}});
  if (move.motion >= 0) work_.machine.motion = move.motion;
  if (move.feed_given) {
    work_.machine.feed = move.feed;
    give('F', move.feed);
  }
  bool ok = emit_line(move.end, work_.machine.motion == 0);
  if (!interp_failed_) {
    at(loc);
    ok = hand() && ok;
  }
  end_plain_move(ok);
  return ok;
}

// end_block for a plain move: what it changed (the motion, the feed rate,
// the point, where the tool is, the heading) committed or put back, not
// the whole modal state copied back and forth (issue 19).
void Translator::end_plain_move(bool ok) {
  comments_ = {};
  Modal& to = ok ? modal_ : work_;
  const Modal& from = ok ? work_ : modal_;
  to.machine.motion = from.machine.motion;
  to.machine.feed = from.machine.feed;
  to.pos = from.pos;
  to.machine_at = from.machine_at;
  to.direction = from.direction;
}

}  // namespace usina::gcode::romi
