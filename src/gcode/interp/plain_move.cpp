// The shortcut of a plain move (issue 19): a block of G0 or G1 and X Y Z,
// F besides, in a state where the whole road (sort_words, check, the
// dialect's order of steps, motion, target, straight) would do nothing but
// set the feed rate and the motion and move. Most blocks of a long program
// are such, in every dialect (each hands its blocks to run_evaluated); the
// whole road costs each some 480 instructions more (callgrind,
// docs/performance.md). A block or a state that is not plain in every
// respect takes the whole road, and so does a plain block the whole road
// would refuse, so the error is always the whole road's. A test runs random
// programs both ways in every dialect (tests/gcode/interp/plain_move_test.cpp).
#include <algorithm>
#include <cstdint>

#include "gcode/interp/execution_order.hpp"
#include "gcode/interp/interpreter.hpp"
#include "gcode/word_range.hpp"

namespace usina::gcode {

// Once per interpreter: G0 and G1 are the dialect's straight motions, and
// its order sets the feed rate before it moves (as LinuxCNC's does).
bool Interpreter::plain_moves_allowed(const InterpOptions& options, const InterpCodes& codes,
                                      const ExecutionOrder& order) {
  if (!options.plain_move_shortcut) return false;
  for (const int tenths : {0, 10}) {
    const InterpCodes::Code* code = codes.find('G', tenths);
    if (code == nullptr || code->handler == CodeRun::Unsupported ||
        code->entry->group != kGroupMotion) {
      return false;
    }
  }
  const auto feed = std::find(order.steps.begin(), order.steps.end(), ExecStep::Feed);
  const auto motion = std::find(order.steps.begin(), order.steps.end(), ExecStep::Motion);
  return feed < motion && motion != order.steps.end();
}

// What the whole road would do more for: a tool change to resync after,
// G7 diameters, G93's F on every move, and cutter compensation in any of
// its states (on, holding a move, or refusing an arc until a straight move).
bool Interpreter::plain_state() const {
  const ModalState& s = state_;
  return !tool_changed_ && !s.lathe_diameter && s.feed_mode != FeedMode::InverseTime &&
         !comp_.active() && !comp_.holding() && comp_.arc_allowed();
}

std::optional<bool> Interpreter::plain_move(const EvaluatedBlock& block) {
  ModalState& s = state_;
  // Comments and assignments run on the whole road.
  if (!block.comments.empty() || !block.assigns.empty() || !plain_state()) return std::nullopt;
  GCode motion = s.motion;
  std::optional<double> f;
  Axes end = s.pos;
  std::uint32_t seen = 0;
  for (const EvaluatedWord& w : block.words) {
    // A letter twice, a value out of range or an increment: the whole
    // road's error (or its rule for the increment).
    const std::uint32_t bit = 1u << static_cast<unsigned>(w.letter & 31);
    if ((seen & bit) != 0 || w.incremental || !word_value_in_range(w.letter, w.value)) {
      return std::nullopt;
    }
    seen |= bit;
    if (w.letter == 'G') {
      if (w.value != 0.0 && w.value != 1.0) return std::nullopt;
      motion = w.value == 0.0 ? 0 : 10;
    } else if (w.letter == 'F') {
      if (!(w.value >= 0.0)) return std::nullopt;
      f = w.value;
    } else if (w.letter >= 'X' && w.letter <= 'Z') {
      const auto i = static_cast<std::size_t>(w.letter - 'X');
      const double v = mm(w.value);
      end[i] = s.incremental ? s.pos[i] + v : v;
    } else {
      return std::nullopt;
    }
  }
  constexpr std::uint32_t kAxes = (1u << ('X' & 31)) | (1u << ('Y' & 31)) | (1u << ('Z' & 31));
  const double feed = f ? mm(*f) : s.feed;
  // No axis word (the whole road's motion without a move), another motion
  // in force, or G1 with no feed rate (its error).
  if ((seen & kAxes) == 0 || (motion != 0 && motion != 10) || (motion == 10 && feed <= 0.0)) {
    return std::nullopt;
  }
  return plain_move_run(motion, f ? std::optional<double>(feed) : std::nullopt, end);
}

std::optional<bool> Interpreter::run_plain_move(const core::SourceLoc& loc, const PlainMove& move) {
  if (!plain_moves_ || !plain_state()) return std::nullopt;
  const ModalState& s = state_;
  // The tests of plain_move() on the words.
  const GCode motion = move.motion != -1 ? move.motion : s.motion;
  const bool has_f = (move.given & PlainMove::kF) != 0;
  if ((has_f && (!(move.f >= 0.0) || !word_value_in_range('F', move.f))) ||
      (motion != 0 && motion != 10) || (move.given & 7u) == 0) {
    return std::nullopt;
  }
  const double feed = has_f ? mm(move.f) : s.feed;
  if (motion == 10 && feed <= 0.0) return std::nullopt;
  Axes end = s.pos;
  for (std::size_t i = 0; i < 3; ++i) {
    if ((move.given & (1u << i)) == 0) continue;
    if (!word_value_in_range('X', move.xyz[i])) return std::nullopt;
    const double v = mm(move.xyz[i]);
    end[i] = s.incremental ? s.pos[i] + v : v;
  }
  // run_evaluated's start.
  checkpoint_fresh_ = false;
  if (run_.failed() || ended_) return !run_.failed();
  if (marked_ == Marked::Pending) mark_plain_move();
  run_.at(loc);
  machine_.set_source(run_.loc());
  return plain_move_run(motion, has_f ? std::optional<double>(feed) : std::nullopt, end);
}

// The plain move's steps in the whole road's order: F, the motion, the
// move. A move the canonical machine refuses puts back what the block
// changed, as the whole road puts back the modal state.
bool Interpreter::plain_move_run(GCode motion, std::optional<double> feed, const Axes& end) {
  ModalState& s = state_;
  const GCode motion_before = s.motion;
  const double feed_before = s.feed;
  const Axes pos_before = s.pos;
  if (feed) {
    s.feed = *feed;
    machine_.set_feed(s.feed, s.feed_mode);
  }
  s.motion = motion;
  cycles_.note_other_motion();
  if (motion == 0) {
    machine_.traverse_axes(end);
  } else {
    machine_.feed_axes(end);
  }
  if (!machine_faulted()) return true;
  s.motion = motion_before;
  s.feed = feed_before;
  s.pos = pos_before;
  return false;
}

}  // namespace usina::gcode
