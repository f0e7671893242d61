#include "sim/planner.hpp"

#include <algorithm>
#include <cmath>

#include "sim/planner_geometry.hpp"

namespace usina::sim {

void merge_exact_stop(const std::vector<AccountTime>& look,
                      const std::vector<AccountTime>& exact_stop,
                      std::vector<AccountTime>& merged) {
  merged.assign(std::max(look.size(), exact_stop.size()), AccountTime{});
  for (std::size_t i = 0; i < merged.size(); ++i) {
    if (i < look.size()) merged[i] = look[i];
    if (i < exact_stop.size()) merged[i].exact_stop_s += exact_stop[i].exact_stop_s;
  }
}

Planner::Planner(PlannerSettings settings) : settings_(settings) {
  ring_.resize(std::max<std::size_t>(settings_.lookahead, 2));
}

AccountTime& Planner::account(std::uint32_t id) {
  if (id >= accounts_.size()) accounts_.resize(id + 1);
  return accounts_[id];
}

bool Planner::add_time(double& into, double seconds) {
  if (seconds >= 0.0 && std::isfinite(seconds) && std::isfinite(into + seconds)) {
    into += seconds;
    return true;
  }
  ++untimed_;
  return false;
}

void Planner::add(const PlannedMove& move) {
  // Written so that NaN is left out too.
  if (!(move.length > 0.0 && move.cruise > 0.0 && std::isfinite(move.length))) return;
  add_time(account(move.account).exact_stop_s,
           move_time(move.length, 0.0, 0.0, move.cruise, move.kin));
  double max_entry = 0.0;
  if (moving_) {
    const double corner =
        junction_speed(last_.end_dir, move.start_dir, settings_.junction_deviation,
                       std::min(last_.kin.accel, move.kin.accel));
    max_entry = std::min({corner, last_.cruise, move.cruise});
  }
  add_joined(move, max_entry);
}

Planner::Speed Planner::reach(const Speed& end, const PlannedMove& m, double cap) {
  if (m.kin.jerk <= 0.0 && m.length > 0.0) {
    const double v2 = end.v2 + 2.0 * m.kin.accel * m.length;
    if (!(v2 < cap * cap)) return {cap, cap * cap};
    return {std::sqrt(v2), v2};
  }
  const double v = reachable_speed(end.v, m.length, m.kin, cap);
  return {v, v * v};
}

void Planner::add_joined(const PlannedMove& move, double max_entry) {
  if (!(move.length >= 0.0 && move.cruise > 0.0 && std::isfinite(move.length))) return;
  if (!moving_) max_entry = 0.0;
  if (count_ == ring_.size()) run_oldest();
  Block& b = at(count_++);
  b.move = move;
  b.max_entry = max_entry;
  b.backward = reach({}, move, max_entry);
  // run_oldest() plans the entry when the block before runs; a block alone
  // in the buffer comes after a stop (the buffer never runs empty while
  // moving) and enters at rest.
  b.entry = {};
  last_ = move;
  moving_ = true;
  plan_backward();
}

double Planner::drop_last() {
  const double entry = at(count_ - 1).max_entry;
  --count_;
  if (count_ > 0) replan_last();  // which takes the new newest block as the last
  return entry;
}

void Planner::replan_last() {
  Block& b = at(count_ - 1);
  last_ = b.move;
  b.max_entry = std::min(b.max_entry, b.move.cruise);
  b.backward = reach({}, b.move, b.max_entry);
  // The blocks before may have to slow down for it, or may now go faster.
  plan_backward();
}

void Planner::plan_backward() {
  // The best entries after the newest block changed, up to the first block
  // whose best does not change: each block's is worked out from the next
  // one's alone, so the blocks before that one keep theirs (index 0's entry
  // is fixed). Each block is looked up once a pass, the one next to it
  // carried over. (Over the whole buffer after a blend's trim was a third
  // of `usina stats` with the linuxcnc model.)
  Speed after = at(count_ - 1).backward;
  for (std::size_t k = count_ - 1; k-- > 1;) {
    Block& b = at(k);
    const Speed best = reach(after, b.move, b.max_entry);
    if (best.v == b.backward.v && best.v2 == b.backward.v2) break;
    b.backward = after = best;
  }
}

void Planner::run_oldest() {
  const Block& b = at(0);
  double exit = 0.0;
  if (count_ > 1) {
    // The forward pass, one block at a time as the blocks run: the next
    // entry is what this block reaches from its own within the best the
    // blocks after allow. The same figure a pass after every new block
    // gave (the blocks before the first one the backward pass changes keep
    // theirs), for one step a block, not three.
    Block& next = at(1);
    next.entry = reach(b.entry, b.move, next.backward.v);
    exit = next.entry.v;
  }
  double t = move_time(b.move.length, b.entry.v, exit, b.move.cruise, b.move.kin);
  if (settings_.quantum > 0.0 && std::isfinite(t)) {
    stretch_s_ += t;
    if (exit == 0.0) {
      // At rest: the stretch ends on a whole tick.
      const double ticks = std::ceil(stretch_s_ / settings_.quantum - 1e-6);
      t += std::max(0.0, ticks * settings_.quantum - stretch_s_);
      stretch_s_ = 0.0;
    }
  }
  if (add_time(account(b.move.account).lookahead_s, t) && observer_) observer_(b.move.op, t);
  head_ = head_ + 1 < ring_.size() ? head_ + 1 : 0;
  --count_;
}

void Planner::stop() {
  while (count_ > 0)
    run_oldest();
  moving_ = false;
}

void Planner::wait(double seconds, std::uint32_t id) {
  stop();
  if (seconds == 0.0) return;
  AccountTime& a = account(id);
  if (add_time(a.lookahead_s, seconds) && observer_) observer_(kWaitOp, seconds);
  add_time(a.exact_stop_s, seconds);
}

}  // namespace usina::sim
