// The material removal rate over the program's time: the volume each op of
// the canon stream cut (told by the stock simulator) laid on the time the
// motion planner gives the same op (told by the stats sink through its
// TimeObserver), summed into bins of time (docs/simulate.md, "Removal rate").
//
// Ops are numbered from 1 in the order both sinks take them. The planner runs
// its moves some blocks behind the simulator (its look-ahead), always in the
// ops' order, and may tell one op in several pieces (an arc in chords), one
// stretch for several ops (a merged chain, a blend arc: the last op it ends)
// or none for an op it skips (no length). So an op's volume waits until the
// planner has told a later op or a wait, then is laid on the time told for
// it: each of kParts equal stretches of the op's length on its share of the
// time (the speed taken as even along the op); the volume of untold ops
// before it evenly over the same time.
//
// The bins start at 10 ms; whenever the program outgrows kBins of them,
// neighbours merge and the width doubles: the memory is fixed, and the width
// ends between 1/kBins and 2/kBins of the program's time.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <vector>

namespace usina::sim::stock {

class RemovalTimeline {
 public:
  static constexpr std::size_t kBins = 1000;
  static constexpr std::size_t kParts = 16;
  // Ops waiting for their time at most: a planner that times nothing (a
  // profile whose times come out undefined) must not make them grow with
  // the program. Past it the two oldest are taken as one.
  static constexpr std::size_t kMaxPending = 4096;
  static constexpr double kFirstBinSeconds = 0.01;

  // From the simulator: op `op` cut `mm3` in the stretch [f0, f1] of its
  // length (0 to 1), in the ops' order; an op may be told in pieces, one
  // that cut nothing need not be told.
  void cut(std::uint64_t op, double mm3, double f0 = 0.0, double f1 = 1.0);

  // From the simulator: operation `index` (0, 1, ... in order) starts at op `op`.
  void operation_begins(std::uint64_t op);

  // From the planner: `seconds` of op `op` ran.
  void timed(std::uint64_t op, double seconds);

  // The end of the program: the last op's time closes; volume never timed
  // (ops the planner did not time) is laid at the end.
  void finish();

  double total_s() const { return clock_; }

  // Seconds the tool was in the material: the time of each sixteenth of an
  // op that removed some (all of a stretch the planner told for several ops).
  double cutting_s() const { return cutting_s_; }

  double bin_s() const { return bin_s_; }

  // mm³ removed in each bin, from time 0; the last bin may be partly used.
  const std::vector<double>& bins() const { return bins_; }

  // Each operation's seconds (moves and waits), by index.
  const std::vector<double>& operation_s() const { return operation_s_; }

  // Ops whose volume waits for their time.
  std::size_t waiting() const { return pending_.size(); }

  // The bin with the most volume (the first of equals); 0 when none cut.
  std::size_t peak_bin() const;

 private:
  struct Pending {
    std::uint64_t op = 0;
    std::array<double, kParts> parts{};  // mm³ by stretch of the op's length

    double mm3() const;
  };

  void close();
  void merge_oldest();
  void spread(double mm3, double t0, double t1);
  void add_to_bin(std::size_t bin, double mm3);
  void grow_to(double t);
  std::size_t operation_of(std::uint64_t op) const;

  std::deque<Pending> pending_;
  std::uint64_t current_op_ = 0;  // the op being timed (0: none)
  double current_start_ = 0.0;    // when it started
  double clock_ = 0.0;            // s, the end of what was told
  double cutting_s_ = 0.0;
  double bin_s_ = kFirstBinSeconds;
  std::vector<double> bins_;
  std::vector<std::uint64_t> operation_first_op_;
  std::vector<double> operation_s_;
  double before_operations_s_ = 0.0;
};

}  // namespace usina::sim::stock
