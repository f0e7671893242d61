// Putting back what one block changed, for a front end that reports a
// refused block and reads on (interpreter.hpp, Interpreter::checkpoint).
#include "core/copy_in_pieces.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {

void Interpreter::checkpoint() {
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
  checkpoint_fresh_ = true;
}

void Interpreter::roll_back() {
  if (!checkpoint_) return;
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
  run_.clear_failure();
}

}  // namespace usina::gcode
