// `usina simulate`: a back end of the canon stream that cuts a stock. Every
// traverse, feed, arc, helix and spline (canned cycles arrive as their
// moves) sweeps the tool in the spindle through the height map; the checks
// (a rapid that cuts, a cut below the floor) are diagnostics at the op's
// block; the volume removed is summed per tool (docs/simulate.md).
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "sim/stock/height_map.hpp"
#include "sim/stock/removal_rate.hpp"
#include "sim/stock/sweep.hpp"
#include "sim/stock/tool_shape.hpp"

namespace usina::sim::stock {

struct SimulateOptions {
  // Tools by number (from the tool table and --tool-shape): shape and diameter.
  std::map<int, ToolShape> tools;
  // A tool known only by its diameter (a tool table without a shape) is flat.
  // A tool with no diameter anywhere is this one, with W_SIM_TOOL_DEFAULTED.
  ToolShape default_tool{};
  std::optional<double> floor;    // Z mm: cuts below it are E_CUT_BELOW_FLOOR
  double rapid_tolerance = 0.01;  // mm: a rapid may graze this deep
  std::size_t max_reports_per_check = 20;
};

// One check, as the JSON report lists it.
struct Check {
  core::Code code = core::Code::Unsupported;
  core::SourceLoc loc;
  std::string message;
};

struct ToolVolume {
  int tool = 0;
  ToolShape shape;
  double removed_mm3 = 0.0;
};

// An operation: from one tool change to the next (the program's first moves,
// before any change, are one too).
struct Operation {
  int tool = 0;
  std::uint32_t first_line = 0;  // the tool change's, or the first move's
  std::uint32_t last_line = 0;   // the last move's before the next change
  double removed_mm3 = 0.0;
};

class StockSimulator final : public canon::Sink {
 public:
  StockSimulator(HeightMap& map, SimulateOptions options, core::DiagnosticSink& diags);

  void on(const canon::Op& op) override;

  // The volume each tool removed, in order of first use (the mark of a cell
  // cut by tools_[n] is n + 1).
  const std::vector<ToolVolume>& tools() const { return tools_; }

  // The volume each operation removed, in the program's order.
  const std::vector<Operation>& operations() const { return operations_; }

  double removed_mm3() const { return removed_; }

  double rapid_removed_mm3() const { return rapid_removed_; }

  const std::vector<Check>& checks() const { return checks_; }

  // The largest chord error an arc is cut with, mm (docs/simulate.md).
  double chord_tolerance() const { return chord_tol_; }

  // Tells `timeline` (kept by the caller, or nullptr) each op's volume and
  // each operation's first op; ops are numbered from 1 as on() takes them.
  void set_timeline(RemovalTimeline* timeline) { timeline_ = timeline; }

 private:
  void move(const canon::Op& op, const core::Vec3& to, const canon::Abc& abc, bool rapid);
  void arc(const canon::Op& op, const canon::Arc& a);
  void spline(const canon::Op& op, const canon::Spline& s);
  void tool_change(const canon::Op& op, const canon::ToolChange& t);
  Cut cut_to(const core::Vec3& to, bool rapid);
  void checked(const canon::Op& op, const Cut& cut, bool rapid);
  void tell(const Cut& piece, double f0, double f1);
  void check_reach(const canon::Op& op, const Cut& cut);
  void begin_operation(const canon::Op& op, int tool);
  void report(const canon::Op& op, core::Code code, core::Severity severity, std::string message);
  void ensure_tool(const canon::Op& op);
  bool abc_moves(const canon::Op& op, const canon::Abc& abc);

  HeightMap& map_;
  SimulateOptions options_;
  core::DiagnosticSink& diags_;
  core::Vec3 pos_{};
  canon::Abc abc_{};
  std::vector<ToolVolume> tools_;
  std::vector<Operation> operations_;
  std::optional<std::size_t> slot_;  // of the tool in the spindle, once it cut or was named
  int tool_number_ = 0;
  std::optional<double> tool_diameter_;  // as the stream gave it
  double removed_ = 0.0;
  double rapid_removed_ = 0.0;
  double chord_tol_ = 0.0;
  std::vector<Check> checks_;
  std::map<core::Code, std::size_t> reported_;
  bool warned_abc_ = false;
  bool started_ = false;       // a move has placed the tool
  std::uint64_t op_ = 0;       // ops taken: the number of the one being taken
  canon::Feed feed_in_force_;  // the last feed move: a bare hole drills at its rate
  RemovalTimeline* timeline_ = nullptr;
};

}  // namespace usina::sim::stock
