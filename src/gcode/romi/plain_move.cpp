// The shortcut of a plain move: a block of G00 or G01 and absolute X Y Z
// (F besides), with no blend arc waiting, no drilling cycle in force and
// G90. Such a block is most blocks of a long program; importing its words
// into the groups, running the motion handler and working out its end by
// the general road would let it by unchanged: it is handed over with what
// those steps would have recorded (issue 19). A block that is not plain in
// every respect takes the whole road; a test compares the two
// (tests/gcode/romi/plain_move_test.cpp).
#include "gcode/romi/translate.hpp"

namespace usina::gcode::romi {

bool Translator::plain_move(const EvaluatedBlock& block) const {
  if (!dialect_options_.plain_move_shortcut || !block.comments.empty() || !block.assigns.empty())
    return false;
  if (work_.blend || work_.drill.active || work_.machine.incremental) return false;
  GCode motion = work_.machine.motion;
  double feed = work_.machine.feed;
  std::uint32_t seen = 0;
  bool position = false;
  for (const EvaluatedWord& w : block.words) {
    // Lower case under lowercase_incremental; a letter twice: an error the
    // whole road reports.
    if (w.incremental || w.letter < 'A' || w.letter > 'Z') return false;
    const std::uint32_t bit = 1u << (w.letter - 'A');
    if ((seen & bit) != 0) return false;
    seen |= bit;
    if (w.letter == 'G') {
      if (w.value != 0.0 && w.value != 1.0) return false;
      motion = w.value == 0.0 ? 0 : 10;
    } else if (w.letter == 'F') {
      if (!(w.value >= 0.0)) return false;  // a negative feed rate: its error
      feed = mm(w.value);
    } else if (w.letter == 'X' || w.letter == 'Y' || w.letter == 'Z') {
      position = true;
    } else {
      return false;
    }
  }
  // G01 with no feed rate: the whole road says so.
  return position && (motion == 0 || (motion == 10 && feed > 0.0));
}

// run_evaluated's steps for the block: values() (F), the motion handler,
// move() (the end point, absolute in program units), then as for any block.
bool Translator::plain_move_block(const EvaluatedBlock& block, const std::function<bool()>& after) {
  begin_block(block);
  Vec3 end = work_.pos;
  for (const EvaluatedWord& w : block.words) {
    if (w.letter == 'G') {
      work_.machine.motion = w.value == 0.0 ? 0 : 10;
    } else if (w.letter == 'F') {
      work_.machine.feed = mm(w.value);
      give('F', work_.machine.feed);
    } else if (w.letter == 'X') {
      // By name, not end[letter - 'X']: an indexed store kept `end` in
      // memory, read back whole before the store had landed (issue 19).
      end.x = mm(w.value);
    } else if (w.letter == 'Y') {
      end.y = mm(w.value);
    } else {
      end.z = mm(w.value);
    }
  }
  bool ok = emit_line(end, work_.machine.motion == 0);
  ok = ok && (!after || after());
  if (!interp_failed_) {
    at(block.loc);
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
