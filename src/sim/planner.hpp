// The motion planner: moves go into a bounded look-ahead buffer, as in a
// real control (grbl's planner), so a program streams in constant memory.
//
// Each block gets the highest entry speed that (1) the corner with the block
// before allows (junction deviation), (2) both blocks' speeds allow, and
// (3) lets the machine still stop at the end of the buffer: a backward pass
// from the newest block (planned to end at rest) and a forward pass from the
// oldest (whose entry is fixed) after every new block. The backward pass
// stops at the first block it does not change and the forward pass starts
// there, so a block costs a few steps, not the buffer's length. When the buffer is full the oldest
// block runs: its time follows from its entry, its exit (the next block's entry) and its cruise
// speed.
//
// Every block is also timed with exact stop (G61: starting and ending at
// rest) for comparison. Times are summed per account: a number the caller
// chooses (stats uses one per tool and kind of time).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.hpp"
#include "sim/planner_profile.hpp"

namespace usina::sim {

struct PlannerSettings {
  double junction_deviation = 0.01;  // mm
  std::size_t lookahead = 200;       // blocks in the buffer
};

// One move as the planner sees it.
struct PlannedMove {
  double length = 0.0;   // mm along the path
  core::Vec3 start_dir;  // unit direction of travel at the start (zero: not a line, a stop)
  core::Vec3 end_dir;    // and at the end
  double cruise = 0.0;   // mm/s, the nominal speed after every limit
  Kinematics kin;        // along the path
  std::uint32_t account = 0;
};

struct AccountTime {
  double lookahead_s = 0.0;   // with look-ahead
  double exact_stop_s = 0.0;  // with exact stop (G61)
};

class Planner {
 public:
  explicit Planner(PlannerSettings settings);

  void add(const PlannedMove& move);

  // Comes to rest: runs every block in the buffer out.
  void stop();

  // Comes to rest, then waits `seconds` (dwell, tool change, spindle start).
  void wait(double seconds, std::uint32_t account);

  // Time per account; call stop() first to include the buffered blocks.
  const std::vector<AccountTime>& accounts() const { return accounts_; }

  // Moves whose time came out negative, infinite or NaN (a machine profile
  // out of range): left out of every account, so a total is never one.
  std::uint64_t untimed() const { return untimed_; }

 private:
  struct Block {
    PlannedMove move;
    double max_entry = 0.0;  // corner and speed limit at the entry
    double backward = 0.0;   // best entry the blocks after it allow
    double entry = 0.0;      // planned entry speed
  };

  Block& at(std::size_t k) { return ring_[(head_ + k) % ring_.size()]; }

  void run_oldest();
  // Adds `seconds` to `into` when it is a time (finite, not negative).
  void add_time(double& into, double seconds);
  void plan_backward_forward();
  AccountTime& account(std::uint32_t id);

  PlannerSettings settings_;
  std::vector<Block> ring_;
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  bool moving_ = false;  // the last block added did not end at rest
  PlannedMove last_;
  std::vector<AccountTime> accounts_;
  std::uint64_t untimed_ = 0;
};

}  // namespace usina::sim
