// Putting back what one block changed, for a front end that reports a
// refused block and reads on (interpreter.hpp, Interpreter::checkpoint).
#include <utility>

#include "core/copy_in_pieces.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {

void Interpreter::checkpoint() {
  marked_ = Marked::Pending;
  checkpoint_fresh_ = true;
}

// The whole state, before a block of the whole road (run_evaluated).
void Interpreter::take_checkpoint() {
  if (!checkpoint_) {
    checkpoint_.emplace(Checkpoint{state_, machine_, cycles_, ended_, {}});
  } else {
    core::copy_in_pieces(checkpoint_->state, state_);
    checkpoint_->machine = machine_;
    checkpoint_->cycles = cycles_;
    checkpoint_->ended = ended_;
    checkpoint_->parameters.clear();  // keeps its capacity: nothing allocated a block
  }
  params_.record_writes(&checkpoint_->parameters);
  marked_ = Marked::Whole;
}

// What a plain move changes (plain_move_run), before it runs.
void Interpreter::mark_plain_move() {
  plain_mark_.motion = state_.motion;
  plain_mark_.feed = state_.feed;
  plain_mark_.pos = state_.pos;
  plain_mark_.initial_level = cycles_.initial_level();
  plain_mark_.machine = machine_.mark();
  marked_ = Marked::Plain;
}

void Interpreter::roll_back() {
  const Marked marked = std::exchange(marked_, Marked::None);
  if (marked == Marked::Plain) {
    const PlainMark& m = plain_mark_;
    state_.motion = m.motion;
    state_.feed = m.feed;
    state_.pos = m.pos;
    cycles_.put_back_initial_level(m.initial_level);
    machine_.put_back(m.machine);
  } else if (marked == Marked::Whole) {
    Checkpoint& c = *checkpoint_;
    state_ = c.state;
    machine_ = c.machine;
    cycles_ = c.cycles;
    ended_ = c.ended;
    params_.record_writes(nullptr);
    for (auto it = c.parameters.rbegin(); it != c.parameters.rend(); ++it)
      params_.set(it->first, it->second);
    c.parameters.clear();
    params_.record_writes(&c.parameters);
  }
  run_.clear_failure();
}

}  // namespace usina::gcode
