// The "grbl" planner model: grbl 1.1's planner (grbl/planner.c and
// motion_control.c), written anew from what they do:
// - a buffer of 16 blocks, one kept free (BLOCK_BUFFER_SIZE): 15 planned;
// - a block's acceleration and rate are the axes' limits along its
//   direction (limit_value_by_axis_maximum);
// - corners by junction deviation ($11, [planner] junction_deviation) with
//   the acceleration the axes allow along the junction's own direction
//   (the difference of the two unit vectors), not the blocks';
// - an arc runs as chords whose middle leaves the arc by at most the arc
//   tolerance ($12, [planner] arc_tolerance) (mc_arc), each a block at the
//   programmed feed, joined by junction deviation: no v²/r limit of its own.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/machine_profile.hpp"
#include "sim/planner.hpp"

namespace usina::sim {

// grbl's BLOCK_BUFFER_SIZE: 16 blocks, one kept free.
inline constexpr std::size_t kGrblBlockBuffer = 15;

class GrblPlanner final : public MotionPlanner {
 public:
  explicit GrblPlanner(const MachineProfile& machine);

  void add(const PlannedMove& move) override;
  void stop() override;
  void wait(double seconds, std::uint32_t account) override;
  const std::vector<AccountTime>& accounts() const override;

  std::uint64_t untimed() const override { return look_.untimed(); }

  void observe(TimeObserver observer) override { look_.observe(std::move(observer)); }

  // The most of `limits` (one per axis X Y Z) along unit vector `u`: each
  // axis that moves caps it at limit_i / |u_i| (planner.c
  // limit_value_by_axis_maximum).
  static double along(const core::Vec3& u, const double limits[3]);

  // Chords mc_arc cuts an arc of `radius` and `sweep` (rad) into, so that
  // each leaves the arc by at most `tolerance` (at least 1).
  static std::uint64_t arc_segments(double radius, double sweep, double tolerance);

 private:
  void block(const PlannedMove& move);

  MachineProfile machine_;
  double accel_[3]{};
  double rate_[3]{};
  Planner look_;
  core::Vec3 prev_dir_;
  double prev_cruise_ = 0.0;
  bool moving_ = false;
  std::vector<AccountTime> exact_stop_;
  mutable std::vector<AccountTime> merged_;
};

}  // namespace usina::sim
