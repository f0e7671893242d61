// The motion planner: moves go into a bounded look-ahead buffer, as in a
// real control (grbl's planner), so a program streams in constant memory.
//
// Each block gets the highest entry speed that (1) the corner with the block
// before allows (junction deviation), (2) both blocks' speeds allow, and
// (3) lets the machine still stop at the end of the buffer: a backward pass
// from the newest block (planned to end at rest) after every new block,
// which stops at the first block it does not change, so a block costs a few
// steps, not the buffer's length. When the buffer is full the oldest block
// runs: the forward pass takes its step then, the next block's entry being
// what this one reaches from its own entry (fixed) within that best, and
// the block's time follows from its entry, that exit and its cruise speed.
//
// Every block is also timed with exact stop (G61: starting and ending at
// rest) for comparison. Times are summed per account: a number the caller
// chooses (stats uses one per tool and kind of time).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "canon/op.hpp"
#include "core/vec3.hpp"
#include "sim/planner_profile.hpp"

namespace usina::sim {

struct PlannerSettings {
  double junction_deviation = 0.01;  // mm
  std::size_t lookahead = 200;       // blocks in the buffer
  // A control whose planner ticks every `quantum` s ends each stretch between
  // two rests on a whole tick (LinuxCNC's servo period); 0: no ticks (textbook).
  double quantum = 0.0;
};

// One move as the planner sees it.
struct PlannedMove {
  double length = 0.0;   // mm along the path
  core::Vec3 start_dir;  // unit direction of travel at the start (zero: not a line, a stop)
  core::Vec3 end_dir;    // and at the end
  double cruise = 0.0;   // mm/s, the nominal speed after every limit
  Kinematics kin;        // along the path
  std::uint32_t account = 0;
  // What a control's own planner model needs besides (the textbook one
  // ignores them): an arc's radius (0: a straight move) and sweep (rad),
  // its cruise before the centripetal limit, the speed the axes allow along
  // the move (their rapid rates), and whether the move is a rapid.
  double radius = 0.0;
  double sweep = 0.0;
  core::Vec3 normal;   // an arc's axis (unit)
  double axial = 0.0;  // mm an arc moves along its axis (a helix)
  bool helix = false;  // an arc that also moves along its axis
  double uncapped = 0.0;
  double max_speed = 0.0;
  bool rapid = false;
  // The canon op the move ends (a number its caller gives, in the order of
  // the ops): a move made of several ops (a merged chain, a blend arc) carries
  // the last whose end it reaches, so its time can be told back per op.
  std::uint64_t op = 0;
};

// Told each stretch of time as the planner runs it, in order: the move's op
// and its seconds with look-ahead; a wait (dwell, tool change) as kWaitOp.
using TimeObserver = std::function<void(std::uint64_t op, double seconds)>;
inline constexpr std::uint64_t kWaitOp = ~std::uint64_t{0};

struct AccountTime {
  double lookahead_s = 0.0;   // with look-ahead
  double exact_stop_s = 0.0;  // with exact stop (G61)
};

// `look`'s accounts with the exact-stop time of `exact_stop` added, into
// `merged` (the models that run the textbook look-ahead and time exact stop
// on their own: planner_linuxcnc, planner_grbl).
void merge_exact_stop(const std::vector<AccountTime>& look,
                      const std::vector<AccountTime>& exact_stop, std::vector<AccountTime>& merged);

// What stats asks of a planner model ([planner] model in the profile).
class MotionPlanner {
 public:
  virtual ~MotionPlanner() = default;

  virtual void add(const PlannedMove& move) = 0;

  // G61, G61.1, G64 P Q from here on; the textbook model plans every
  // program with its own look-ahead and ignores it.
  virtual void path_mode(const canon::PathMode& mode) { (void)mode; }

  // Comes to rest: runs every block in the buffer out.
  virtual void stop() = 0;

  // Comes to rest, then waits `seconds` (dwell, tool change, spindle start).
  virtual void wait(double seconds, std::uint32_t account) = 0;

  // Time per account; call stop() first to include the buffered blocks.
  virtual const std::vector<AccountTime>& accounts() const = 0;

  // Moves whose time came out negative, infinite or NaN (a machine profile
  // out of range): left out of every account, so a total is never one.
  virtual std::uint64_t untimed() const = 0;

  // Tells `observer` every move's and wait's time as it is run (none: nothing).
  virtual void observe(TimeObserver observer) = 0;
};

class Planner final : public MotionPlanner {
 public:
  explicit Planner(PlannerSettings settings);

  void add(const PlannedMove& move) override;
  void stop() override;
  void wait(double seconds, std::uint32_t account) override;

  const std::vector<AccountTime>& accounts() const override { return accounts_; }

  std::uint64_t untimed() const override { return untimed_; }

  void observe(TimeObserver observer) override { observer_ = std::move(observer); }

  // For a model that decides its corners itself: the move enters at most at
  // `max_entry` (0: from rest); no exact-stop time is counted for it.
  void add_joined(const PlannedMove& move, double max_entry);

  // The newest block (while moving), to change before the next one comes
  // (trimmed by a blend, its acceleration lowered); replan_last() after.
  bool has_last() const { return count_ > 0; }

  PlannedMove& last_move() { return at(count_ - 1).move; }

  void replan_last();

  // Takes the newest block out (a blend arc swallowed it); returns the most
  // it could be entered at, for the block that replaces it.
  double drop_last();

 private:
  // A speed the passes carry, with its square: a trapezoidal move reaches
  // sqrt(v² + 2aL), so the passes chain the squares (an add a block) and take
  // each root apart, off the chain: each pass waited on a root a block, 3-5 %
  // of `usina stats`. The square carried is not always the square of the
  // root taken, so a speed can differ from the root-to-root chain's in its
  // last bit: the same figures for every program of the repository, the
  // grbl model's total on the 100,000 block bench program 4e-16 apart.
  struct Speed {
    double v = 0.0;
    double v2 = 0.0;
  };

  struct Block {
    PlannedMove move;
    double max_entry = 0.0;  // corner and speed limit at the entry
    Speed backward;          // best entry the blocks after it allow
    Speed entry;             // planned entry speed
  };

  // reachable_speed() from `end` over `m`, at most `cap`.
  static Speed reach(const Speed& end, const PlannedMove& m, double cap);

  // The k-th block from the oldest (k < count_). head_ and k are both
  // below the ring's size, so one subtraction wraps the sum: the passes
  // ask for blocks a dozen times a move, and a division each time was 3 %
  // of `usina stats`.
  Block& at(std::size_t k) {
    const std::size_t i = head_ + k;
    return ring_[i < ring_.size() ? i : i - ring_.size()];
  }

  void run_oldest();
  // Adds `seconds` to `into` when it is a time (finite, not negative): true;
  // else counts the move untimed.
  bool add_time(double& into, double seconds);
  void plan_backward();
  AccountTime& account(std::uint32_t id);

  PlannerSettings settings_;
  std::vector<Block> ring_;
  std::size_t head_ = 0;
  std::size_t count_ = 0;
  bool moving_ = false;  // the last block added did not end at rest
  PlannedMove last_;
  std::vector<AccountTime> accounts_;
  std::uint64_t untimed_ = 0;
  double stretch_s_ = 0.0;  // since the last rest, for the quantum
  TimeObserver observer_;
};

}  // namespace usina::sim
