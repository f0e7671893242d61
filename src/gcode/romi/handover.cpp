// Handing romi's blocks to the RS274NGC interpreter: the words a handler
// gave, at the block's loc, as one evaluated block (the entry every dialect
// uses, interp/evaluated_block.hpp). Moves and arcs are handed at once, so
// their ops come out where romi's handlers run them; the words before a
// move (F, S, T, M03-M09, G40-G42) wait and go with it, where the
// interpreter's order of execution is romi's.
#include <cmath>

#include "gcode/romi/translate.hpp"

namespace usina::gcode::romi {

DialectRules romi_rules() {
  DialectRules rules;
  rules.start_motion = 0;  // G00
  rules.tool_change_stops_spindle = false;
  rules.comments_as_written = true;
  rules.two_digit_stop_codes = true;
  return rules;
}

bool Translator::hand() {
  if (pending_.empty()) return true;
  const EvaluatedBlock block{run_.loc(), pending_, {}, {}};
  const bool ok = interp_.run_evaluated(block);
  pending_.clear();
  if (!ok) {
    // Reported by the interpreter: the run stops at it.
    interp_failed_ = true;
    run_.fail();
  }
  return ok;
}

bool Translator::hand_comments() {
  if (comments_.empty()) return true;
  const EvaluatedBlock block{run_.loc(), {}, {}, comments_};
  if (interp_.run_evaluated(block)) return true;
  interp_failed_ = true;
  run_.fail();
  return false;
}

// G0 or G1 (g: 0 or 1) to `to`, absolute millimetres of the machine.
bool Translator::hand_move(int g, const Vec3& to) {
  // With nothing else waiting but F, past the words when the interpreter
  // takes it as a plain move (issue 19).
  if (pending_.empty() || (pending_.size() == 1 && pending_[0].letter == 'F')) {
    PlainMove move{g * 10, 7u, 0.0, {to.x, to.y, to.z}};
    if (!pending_.empty()) {
      move.f = pending_[0].value;
      move.given |= PlainMove::kF;
    }
    if (const std::optional<bool> ran = interp_.run_plain_move(run_.loc(), move)) {
      work_.machine_at = to;
      pending_.clear();
      if (!*ran) {
        interp_failed_ = true;
        run_.fail();
      }
      return *ran;
    }
  }
  give('G', g);
  give('X', to.x);
  give('Y', to.y);
  give('Z', to.z);
  work_.machine_at = to;
  return hand();
}

// G2/G3 to `to` about `center` (absolute, G90.1), `turns` times round.
bool Translator::hand_arc(const Vec3& to, Vec2 center, bool ccw, int turns) {
  give('G', ccw ? 3 : 2);
  give('X', to.x);
  give('Y', to.y);
  give('Z', to.z);
  give('I', center.x);
  give('J', center.y);
  if (turns > 1) give('P', turns);
  work_.machine_at = to;
  return hand();
}

}  // namespace usina::gcode::romi
