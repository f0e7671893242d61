// `usina stats`: a sink that times a program on a machine profile with the
// motion planner and gathers totals and per-tool figures, and the checks
// (travel limits, feeds, spindle, rapids into the stock, arcs too tight for
// their feed), each a diagnostic at the op's source location.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include "canon/sink.hpp"
#include "sim/machine_profile.hpp"
#include "sim/planner.hpp"
#include "sim/planner_geometry.hpp"
#include "sim/stats_checks.hpp"

namespace usina::sim {

// A profile for programs run without --machine: a generic three-axis mill
// with no travel limits (docs/stats.md lists its figures).
MachineProfile default_machine_profile();

struct Range {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();

  bool empty() const { return min > max; }

  void add(double v) {
    min = v < min ? v : min;
    max = v > max ? v : max;
  }

  void add(const Range& r) {
    if (!r.empty()) {
      add(r.min);
      add(r.max);
    }
  }
};

struct Box {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};

  bool empty() const { return lo.x > hi.x; }

  // Inline: four a move (the move's own box, then the tool's bounds).
  void add(const Vec3& p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }

  void add(const Box& b) {
    if (b.empty()) return;
    add(b.lo);
    add(b.hi);
  }
};

struct Counts {
  std::uint64_t rapids = 0;  // traverses
  std::uint64_t feeds = 0;   // straight feed moves
  std::uint64_t arcs = 0;
  std::uint64_t splines = 0;
  std::uint64_t probes = 0;
  std::uint64_t holes = 0;
  std::uint64_t tool_changes = 0;
  std::uint64_t dwells = 0;

  std::uint64_t moves() const { return rapids + feeds + arcs + splines + probes; }

  void add(const Counts& c);
};

// The figures of one tool, or of the whole program.
struct ToolStats {
  int tool = 0;  // 0: the tool in the spindle before the first change
  double cutting_s = 0.0;
  double rapid_s = 0.0;
  double other_s = 0.0;  // dwells, tool changes, spindle start-up, probing
  double exact_stop_s = 0.0;
  double cutting_mm = 0.0;
  double rapid_mm = 0.0;
  Counts counts;
  Box bounds;  // of the controlled point (tool tip), arcs by their true extent
  Range feed;  // mm/min, as programmed
  Range rpm;   // of the spindle starts

  double total_s() const { return cutting_s + rapid_s + other_s; }
};

struct StatsReport {
  std::vector<ToolStats> tools;  // in order of first use; tools that did nothing left out
  ToolStats total;
  double cost = 0.0;                           // total time × [cost] per_hour
  std::map<core::Code, std::uint64_t> checks;  // every check's count, shown or not
};

struct StatsOptions {
  std::optional<double> stock_top;  // mm, Z in the trace's coordinates
  // Where the trace's origin is in machine coordinates (program zero: the
  // work offset the operator sets). Without it the travel check cannot
  // place the program on the machine and compares its extent with each
  // axis's travel instead.
  std::optional<core::Vec3> work_zero;
  std::size_t max_reports_per_check = 10;
  std::size_t lookahead = 200;  // blocks
};

class StatsSink final : public canon::Sink {
 public:
  StatsSink(const MachineProfile& machine, StatsOptions options, core::DiagnosticSink& diags);

  void on(const canon::Op& op) override;

  // Runs the planner's buffer out; the interpreter calls it at the end, and
  // it may be called again.
  void finish() override;

  // The figures; call finish() first.
  StatsReport report() const;

  // Tells `observer` the time of each op as the planner runs it (ops are
  // numbered from 1 in the order on() gets them; a dwell's or a tool
  // change's wait is told as its op's), in the order of the ops.
  void observe(TimeObserver observer);

 private:
  enum Kind : std::uint32_t { Cutting = 0, Rapid = 1, Other = 2 };

  std::uint32_t account(Kind k) const { return static_cast<std::uint32_t>(tool_slot_) * 3 + k; }

  ToolStats& tool() { return tools_[tool_slot_]; }

  void traverse(const canon::Op& op, const canon::Traverse& t);
  void feed(const canon::Op& op, const Vec3& to, const canon::Abc& abc, std::optional<double> f,
            const canon::ProgrammedFeed& programmed);
  void arc(const canon::Op& op, const canon::Arc& a);
  void spline(const canon::Op& op, const canon::Spline& s);
  void probe(const canon::Op& op, const canon::Probe& p);
  void spindle(const canon::Spindle& s);
  void tool_change(const canon::ToolChange& t);

  // A straight move from the current position: its length, axis shares
  // and the rates they allow, worked out once for the checks, the cruise
  // speed and the planner. Its end is the caller's, not a copy: the copy
  // read back in 16 bytes what the caller stored in 8, and waited.
  struct Line {
    const Axes6& to;
    double length;
    AxisShare share;
    PathRates rates;
  };

  Line line_to(const Axes6& to) const;
  // Plans a straight move from the current position; returns its length.
  double straight(const Line& line, double cruise, Kind kind);
  PlannedMove straight_move(const Line& line, double cruise, Kind kind) const;
  // The cruise speed (mm/s) of a feed at `rate` mm/min (none unless above 0)
  // along `share`, reporting a clamp; the same within the axes' `limit`
  // already worked out.
  double feed_speed(const canon::Op& op, const AxisShare& share, double rate);
  double feed_speed(const canon::Op& op, double limit, int limiting_axis, double rate);
  // A plain double, not an optional: the optional's flag, stored beside the
  // value and read back with it in one load, stalled every feed move.
  double rate_of(std::optional<double> f, const canon::ProgrammedFeed& programmed,
                 double length) const;
  double block_limit(double length, double cruise) const;
  void moved_to(const Axes6& to);

  MachineProfile machine_;
  StatsOptions options_;
  core::DiagnosticSink& diags_;
  bool refused_ = false;  // an op out of canon's range was reported
  bool reported_untimed_ = false;
  StatsChecks checks_;
  std::unique_ptr<MotionPlanner> planner_;
  Axes6 pos_{};
  std::vector<ToolStats> tools_;
  std::map<int, std::size_t> slot_of_tool_;
  std::size_t tool_slot_ = 0;
  canon::SpindleDir spindle_dir_ = canon::SpindleDir::Off;
  double spindle_rpm_ = 0.0;
  std::optional<double> last_feed_;  // mm/min, for probe moves
  canon::Feed feed_in_force_;        // the last feed move: a bare hole drills at its rate
  std::uint64_t op_ = 0;             // ops taken so far: the number of the one being taken
};

}  // namespace usina::sim
