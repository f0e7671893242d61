// The checks of `usina stats`, each a warning at the op's source location.
// A check counts every op it flags, but reports only the first op of each
// run of flagged ops (a program that stays outside a travel limit for a
// thousand moves gets one warning there: an excursion ends with a move that
// ends inside the limits), and at most `cap` per check.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "canon/op.hpp"
#include "sim/machine_profile.hpp"
#include "sim/planner_geometry.hpp"

namespace usina::sim {

class StatsChecks {
 public:
  // `work_zero`: the machine coordinates of the trace's origin, or nullopt
  // when unknown (the linear axes are then checked by the program's extent).
  StatsChecks(const MachineProfile& machine, std::optional<double> stock_top,
              std::optional<Vec3> work_zero, std::size_t cap, core::DiagnosticSink& diags);

  // A move whose path spans [lo, hi] (X Y Z) and ends at `end` (A B C checked there).
  void travel(const canon::Op& op, const Vec3& lo, const Vec3& hi, const Axes6& end);

  // A feed move: with or without a rate, with the spindle running or not.
  void feed(const canon::Op& op, bool has_rate, bool spindle_running);

  // A rapid from `from` to `to`.
  void rapid(const canon::Op& op, const Vec3& from, const Vec3& to);

  // An arc of `radius` at `feed` (mm/min): when `allowed` is below it, the
  // centripetal acceleration `accel` lowers the feed to `allowed`.
  void arc_feed(const canon::Op& op, double radius, double feed, double allowed, double accel);

  // A feed move at `feed` (mm/min): when `allowed` is below it, axis `axis` clamps it.
  void feed_limit(const canon::Op& op, double feed, double allowed, int axis);

  // Ops flagged per check.
  const std::map<core::Code, std::uint64_t>& counts() const { return counts_; }

 private:
  // With no work zero: the extent of the program so far on linear axis `i`
  // against the axis's travel, reported once per axis.
  void extent(const canon::Op& op, int i, double low, double high);
  // Reports the span of axis `i` longer than its travel (apart from
  // extent(), which every move calls, so that one stays small).
  void span_too_long(const canon::Op& op, int i);
  // Axis `i` (a rotary one, or any with a work zero) against its travel
  // limits, reported once per excursion.
  void limits(const canon::Op& op, int i, const Vec3& lo, const Vec3& hi, const Axes6& end);

  // Counts the op; reports it when `first_of_run` and under the cap.
  void flag(core::Code code, const canon::Op& op, bool first_of_run, const std::string& message);

  const MachineProfile& machine_;
  std::optional<double> stock_top_;
  std::optional<Vec3> work_zero_;
  std::size_t cap_;
  core::DiagnosticSink& diags_;
  std::map<core::Code, std::uint64_t> counts_;
  std::map<core::Code, std::size_t> shown_;
  std::array<std::array<bool, 2>, 6> outside_{};  // per axis, below min / above max
  std::array<double, 3> span_lo_{}, span_hi_{};   // the program's extent (no work zero)
  bool spanned_ = false;
  std::array<bool, 3> too_long_{};
  bool in_no_rate_run_ = false;
  bool in_stopped_run_ = false;
  bool in_stock_run_ = false;
  bool in_clamp_run_ = false;
  bool in_arc_run_ = false;
};

// "X", "Y", ... for axis index 0..5.
char axis_letter(int axis);

}  // namespace usina::sim
