// The "linuxcnc" planner model: the rules of LinuxCNC 2.9's trajectory
// planner (tpmod; src/emc/tp/tp.c, tc.c and blendmath.c at f1270d6ed7, the
// Debian 12 build of 2.9.0~pre1), written anew from what those files do, so
// that `usina stats` gives the cycle time that controller gives.
// docs/stats.md, "Planner models", lists the rules and where each comes from;
// tests/programs/timing/ holds the times LinuxCNC itself took.
//
// The moves go through the same look-ahead buffer as the textbook model
// (sim/planner.hpp), but this model decides every corner itself, as
// LinuxCNC does when a move is queued:
// - before the program's first G61/G61.1/G64: G64 with a tolerance of a few
//   µm (measured: LinuxCNC's start mode nearly stops at corners);
// - G61.1 (exact stop): the move before ends at rest, full acceleration.
// - a rapid next to a feed move: an exact stop.
// - a reversal (more than 178°): an exact stop too.
// - a corner the planner can take as a "kink" (the change of direction
//   needs less than ARC_BLEND_KINK_RATIO of the axes' acceleration in one
//   servo cycle): no stop; both moves lose that share of their acceleration.
// - any other corner: both moves lose the kink ratio (10 %) of their
//   acceleration; under G61 (exact path) they stop there, under G64 a blend
//   arc within P (or a quarter of the shorter move) replaces the corner and
//   the moves keep their acceleration.
// - the last move before the machine comes to rest under G64 keeps its
//   "parabolic" end and runs at half its acceleration.
// - arcs: speed at most √(√3/2·a·r) and then half the acceleration along
//   the path (more when the machine's speed is well below that).
// - G64 P Q merges nearly collinear feed moves within Q (naive CAM).
// - a move runs at most its length per servo cycle; the motion between two
//   rests lasts whole servo cycles.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/machine_profile.hpp"
#include "sim/planner.hpp"

namespace usina::sim {

using core::Vec3;

class LinuxcncPlanner final : public MotionPlanner {
 public:
  LinuxcncPlanner(const MachineProfile& machine, std::size_t lookahead);

  void add(const PlannedMove& move) override;
  void path_mode(const canon::PathMode& mode) override;
  void stop() override;
  void wait(double seconds, std::uint32_t account) override;
  const std::vector<AccountTime>& accounts() const override;

  std::uint64_t untimed() const override { return look_.untimed(); }

  void observe(TimeObserver observer) override { look_.observe(std::move(observer)); }

  // A move as LinuxCNC's planner queues it (its TC_STRUCT, what matters of it).
  struct Segment {
    PlannedMove move;         // length left after blends, cruise, acceleration in force
    canon::PathMode mode;     // the path mode it was programmed in
    double nominal = 0.0;     // length as programmed (before blends trim it)
    double requested = 0.0;   // mm/s, the feed (reqvel)
    double base_accel = 0.0;  // mm/s² along the path, before kinks and parabolic ends
    double kink_prev = 0.0;   // acceleration share lost to the corner before
    double kink_next = 0.0;   // and to the corner after
    bool parabolic = false;   // ends (or starts) in a parabolic blend: a/2
  };

 private:
  Segment segment_of(const PlannedMove& move) const;
  void naive_cam(const Segment& s);
  bool links(const Segment& s, const Vec3& end) const;
  void flush_chain();
  void queue(Segment s);

  // A blend arc for the corner between the newest move and `next`.
  struct Arc {
    bool ok = false;
    PlannedMove move;
    double trim = 0.0;  // mm taken off each move
    double v_plan = 0.0;
  };

  double corner(Segment& next);
  double parabolic_speed(const Segment& next) const;
  Arc blend_arc(const Segment& next) const;
  void join_by_arc(Segment& next, Arc arc);
  bool coplanar(const Segment& prev, const Segment& next) const;
  void update_last();
  void finish_last();
  double plane_limit(const Vec3& u1, const Vec3& u2, bool speed) const;

  MachineProfile machine_;
  LinuxcncPlannerSettings settings_;
  Planner look_;
  canon::PathMode mode_;  // LinuxCNC starts in G64 without P
  Segment last_;          // the newest queued move (its geometry is look_.last_move())
  bool have_last_ = false;
  // Naive CAM: feed moves waiting to be merged into one line.
  Segment chain_;
  std::vector<Vec3> chain_points_;  // the corners so far, from the chain's start
  bool have_chain_ = false;
  std::vector<AccountTime> exact_stop_;
  mutable std::vector<AccountTime> merged_;
};

}  // namespace usina::sim
