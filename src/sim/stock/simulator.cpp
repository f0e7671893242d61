#include "sim/stock/simulator.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "canon/bare_hole.hpp"
#include "canon/limits.hpp"
#include "sim/planner_geometry.hpp"

namespace usina::sim::stock {
namespace {

// The checks kept for the report beyond those printed: enough for any
// reader, finite for a program that rapids through the stock a million times.
constexpr std::size_t kMaxChecksKept = 10'000;

// An arc is cut as chords: at most this many (a helix of many turns on a
// huge radius), which keeps a hostile arc finite.
constexpr double kMaxChords = 10'000'000.0;

// Mark of tools past the 254th: they share the last colour.
constexpr std::size_t kLastToolMark = 254;

}  // namespace

StockSimulator::StockSimulator(HeightMap& map, SimulateOptions options, core::DiagnosticSink& diags)
    : map_(map), options_(std::move(options)), diags_(diags) {
  // Chords a thousandth of a cell off the arc: the volume they miss or add
  // is at most 2 × tol × length × depth (docs/simulate.md, tested), far
  // below what the grid itself resolves.
  chord_tol_ = std::min(map_.dx(), map_.dy()) / 1000.0;
}

void StockSimulator::on(const canon::Op& op) {
  ++op_;  // every op counts, as the stats sink counts them (RemovalTimeline)
  if (auto in_range = canon::check_range(op.kind); !in_range) return;  // the front end said why
  std::visit(
      [&](const auto& k) {
        using T = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<T, canon::Traverse>) {
          move(op, k.to, k.abc, true);
        } else if constexpr (std::is_same_v<T, canon::Feed>) {
          feed_in_force_ = k;
          move(op, k.to, k.abc, false);
        } else if constexpr (std::is_same_v<T, canon::Arc>) {
          arc(op, k);
        } else if constexpr (std::is_same_v<T, canon::Spline>) {
          spline(op, k);
        } else if constexpr (std::is_same_v<T, canon::Probe>) {
          pos_ = k.to;  // a probe's stylus cuts nothing
          started_ = true;
          abc_ = k.abc;
        } else if constexpr (std::is_same_v<T, canon::ToolChange>) {
          tool_change(op, k);
        } else if constexpr (std::is_same_v<T, canon::Hole>) {
          for (const canon::Op& m : canon::bare_hole_moves(op, k, pos_, abc_, feed_in_force_))
            on(m);
        }
      },
      op.kind);
}

void StockSimulator::report(const canon::Op& op, core::Code code, core::Severity severity,
                            std::string message) {
  if (checks_.size() < kMaxChecksKept) checks_.push_back({code, op.src, message});
  if (reported_[code]++ < options_.max_reports_per_check) {
    diags_.report({code, severity, op.src, std::move(message)});
  }
}

void StockSimulator::ensure_tool(const canon::Op& op) {
  // The tool in the spindle before any change: known at its first move.
  if (!slot_) tool_change(op, canon::ToolChange{tool_number_, tool_diameter_});
}

void StockSimulator::begin_operation(const canon::Op& op, int tool) {
  operations_.push_back({tool, op.src.line, op.src.line, 0.0});
  if (timeline_ != nullptr) timeline_->operation_begins(op_);
}

void StockSimulator::tool_change(const canon::Op& op, const canon::ToolChange& t) {
  begin_operation(op, t.tool);
  tool_number_ = t.tool;
  tool_diameter_ = t.diameter;
  for (std::size_t i = 0; i < tools_.size(); ++i) {
    if (tools_[i].tool == t.tool) {
      slot_ = i;
      return;
    }
  }
  const bool stream_has_diameter =
      t.diameter && *t.diameter > 0.0 && *t.diameter <= kMaxToolDiameter;
  std::optional<ToolShape> shape;
  if (auto it = options_.tools.find(t.tool); it != options_.tools.end()) {
    shape = it->second;
    if (shape->diameter <= 0.0 && stream_has_diameter) shape->diameter = *t.diameter;
  } else if (stream_has_diameter) {
    shape = ToolShape{};
    shape->diameter = *t.diameter;
  }
  if (!shape || !check_shape(*shape)) {
    shape = options_.default_tool;
    report(op, core::Code::SimToolDefaulted, core::Severity::Warning,
           fmt::format("tool {} has no diameter (no --tool-table, or not in it): it is "
                       "simulated as the default tool, {}; give its diameter in the tool table "
                       "or with --tool-shape {}=SHAPE/D",
                       t.tool, shape_name(*shape), t.tool));
  }
  tools_.push_back({t.tool, *shape, 0.0});
  slot_ = tools_.size() - 1;
}

bool StockSimulator::abc_moves(const canon::Op& op, const canon::Abc& abc) {
  if (abc == abc_) return false;
  abc_ = abc;
  if (!warned_abc_) {
    warned_abc_ = true;
    report(op, core::Code::SimMotionNotModeled, core::Severity::Warning,
           "the move turns a rotary axis (A, B or C), which a height map cannot model: it and "
           "every later such move cut nothing in the simulation");
  }
  return true;
}

Cut StockSimulator::cut_to(const core::Vec3& to, bool rapid) {
  const std::size_t slot = slot_.value_or(0);
  const auto mark =
      rapid ? kRapidMark : static_cast<std::uint8_t>(std::min(slot + 1, kLastToolMark));
  // Where the tool was before the program's first move is unknown (the
  // stream starts at 0,0,0 by convention): that move cuts only where it ends.
  const core::Vec3 from = started_ ? pos_ : to;
  started_ = true;
  const Cut cut = sweep(map_, tools_[slot].shape, from, to, mark);
  pos_ = to;
  return cut;
}

void StockSimulator::checked(const canon::Op& op, const Cut& cut, bool rapid) {
  removed_ += cut.removed_mm3;
  tools_[slot_.value_or(0)].removed_mm3 += cut.removed_mm3;
  operations_.back().removed_mm3 += cut.removed_mm3;
  operations_.back().last_line = op.src.line;
  check_reach(op, cut);
  if (rapid) rapid_removed_ += cut.removed_mm3;
  if (rapid && cut.deepest > options_.rapid_tolerance) {
    report(op, core::Code::RapidCutsStock, core::Severity::Error,
           fmt::format("a rapid move cuts {:.3f} mm³ of stock, up to {:.3f} mm deep: feed into "
                       "the material, or rapid to a clearance height first",
                       cut.removed_mm3, cut.deepest));
  }
  if (options_.floor && cut.lowest < *options_.floor - 1e-9) {
    report(op, core::Code::CutBelowFloor, core::Severity::Error,
           fmt::format("the tool cuts down to Z{:.4f}, {:.4f} mm below the floor Z{:g}", cut.lowest,
                       *options_.floor - cut.lowest, *options_.floor));
  }
}

void StockSimulator::check_reach(const canon::Op& op, const Cut& cut) {
  const ToolVolume& t = tools_[slot_.value_or(0)];
  if (cut.shank_rub > 0.0) {
    report(op, core::Code::ShankRubsStock, core::Severity::Error,
           fmt::format("stock stands {:.3f} mm above the flutes of tool {} ({:g} mm long) where "
                       "the tool enters it: the shank rubs it; cut in steps no deeper than the "
                       "flutes, or use a tool with longer flutes",
                       cut.shank_rub, t.tool, t.shape.flutes));
  }
  if (cut.holder_hit > 0.0) {
    report(op, core::Code::HolderHitsStock, core::Severity::Error,
           fmt::format("the holder of tool {} (diameter {:g} mm, {:g} mm above the tip) goes "
                       "{:.3f} mm into the stock: give the tool a longer stick-out, or a slimmer "
                       "holder",
                       t.tool, t.shape.holder, t.shape.stickout, cut.holder_hit));
  }
  if (cut.plunge_into > 0.0) {
    report(op, core::Code::PlungeNotCentreCutting, core::Severity::Warning,
           fmt::format("tool {} does not cut at its centre (no-plunge) and goes down steeper "
                       "than {:g}° into stock standing {:.3f} mm above its tip under its axis: "
                       "ramp or helix in no steeper than that, or drill a start hole",
                       t.tool, t.shape.plunge_ramp, cut.plunge_into));
  }
}

void StockSimulator::move(const canon::Op& op, const core::Vec3& to, const canon::Abc& abc,
                          bool rapid) {
  if (abc_moves(op, abc)) {
    pos_ = to;
    started_ = true;
    return;
  }
  ensure_tool(op);
  const Cut cut = cut_to(to, rapid);
  tell(cut, 0.0, 1.0);
  checked(op, cut, rapid);
}

// The timeline gets a piece's volume by the stretch of the op it cut in:
// the piece is [f0, f1] of the op, each of its parts an equal share of that.
void StockSimulator::tell(const Cut& piece, double f0, double f1) {
  if (timeline_ == nullptr || !(piece.removed_mm3 > 0.0)) return;
  const double step = (f1 - f0) / static_cast<double>(kCutParts);
  for (std::size_t k = 0; k < kCutParts; ++k) {
    const double from = f0 + step * static_cast<double>(k);
    timeline_->cut(op_, piece.parts_mm3[k], from, from + step);
  }
}

void StockSimulator::arc(const canon::Op& op, const canon::Arc& a) {
  if (abc_moves(op, a.abc)) {
    pos_ = a.to;
    started_ = true;
    return;
  }
  ensure_tool(op);
  const auto path = arc_path(pos_, a);
  if (!path) {
    const Cut cut = cut_to(a.to, false);
    tell(cut, 0.0, 1.0);
    return checked(op, cut, false);
  }
  // The sagitta of a chord of angle t on radius R is R (1 − cos(t/2)).
  const double half = std::acos(std::max(-1.0, 1.0 - chord_tol_ / path->radius));
  const double chords =
      std::clamp(std::ceil(std::abs(path->sweep) / (2.0 * half)), 1.0, kMaxChords);
  const auto n = static_cast<std::uint64_t>(chords);
  Cut total;
  for (std::uint64_t i = 1; i <= n; ++i) {
    const double f = static_cast<double>(i) / chords;
    const Cut chord = cut_to(i < n ? path->at(path->sweep * f) : a.to, false);
    tell(chord, static_cast<double>(i - 1) / chords, f);
    total.add(chord);
  }
  checked(op, total, false);
}

void StockSimulator::spline(const canon::Op& op, const canon::Spline& s) {
  ensure_tool(op);
  Cut total;
  const double pieces = static_cast<double>(s.points.size() + 1);
  for (std::size_t i = 0; i <= s.points.size(); ++i) {
    const Cut piece = cut_to(i < s.points.size() ? s.points[i] : s.to, false);
    tell(piece, static_cast<double>(i) / pieces, static_cast<double>(i + 1) / pieces);
    total.add(piece);
  }
  checked(op, total, false);
}

}  // namespace usina::sim::stock
