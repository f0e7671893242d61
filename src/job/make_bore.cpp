// Boring (docs/job.md, "Boring"): the holes of a layer, already drilled,
// finished to their drawn diameter with a single-point boring bar or an
// adjustable boring head, as G85 does it (fed in and fed back out: a rapid
// out would drag the bar's edge along the finished wall). A boring bar
// finishes a hole; it does not cut from solid, so each hole must have been
// drilled by an earlier operation of the job, narrower and deep enough, or
// the job must say the holes are there (`predrilled = true`).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cam/drill.hpp"
#include "job/make_support.hpp"
#include "job/stock_check.hpp"

namespace usina::job {
namespace {

constexpr double kSameCentre = 0.01;  // mm: a pilot hole drilled at the bore's centre

core::Diagnostic pilot_error(const Operation& op, std::string message) {
  return {core::Code::JobPilotHole, core::Severity::Error, op.layer_loc, std::move(message)};
}

// The widest hole made so far at `c`: the last that widened it.
const MadeHole* pilot_at(const Context& cx, cam::Vec2 c) {
  const MadeHole* best = nullptr;
  for (const MadeHole& h : cx.holes) {
    if (std::hypot(h.centre.x - c.x, h.centre.y - c.y) > kSameCentre) continue;
    if (best == nullptr || h.diameter > best->diameter) best = &h;
  }
  return best;
}

// The narrowest pilot hole of the group, after checking each is there,
// narrower than the bore and deep enough; nullopt after an error.
std::optional<double> pilot_of(Context& cx, const Operation& op, const HoleGroup& g) {
  double narrowest = std::numeric_limits<double>::infinity();
  for (const cam::Vec2& c : g.centers) {
    const MadeHole* h = pilot_at(cx, c);
    if (h == nullptr) {
      cx.diags.report(pilot_error(
          op, fmt::format("the D{:g} hole at X{:g} Y{:g} of layer \"{}\" is drilled by no "
                          "earlier operation: a boring bar finishes a hole, it does not cut "
                          "from solid. Drill it first (a drill operation on the pilot "
                          "circles), or give predrilled = true if it is there before the job",
                          g.diameter, c.x, c.y, op.layer)));
      return std::nullopt;
    }
    if (h->diameter >= g.diameter - 0.005) {
      cx.diags.report(pilot_error(
          op, fmt::format("the hole at X{:g} Y{:g} is already D{:g}: nothing is left to bore "
                          "to D{:g}",
                          c.x, c.y, h->diameter, g.diameter)));
      return std::nullopt;
    }
    if (h->full_depth < op.depth - 1e-6) {
      cx.diags.report(pilot_error(
          op, fmt::format("the D{:g} pilot hole at X{:g} Y{:g} is full width to {:.3g} mm deep "
                          "(a drill's point ends it); the bore goes {:g} mm: the bar's end would "
                          "cut solid below it. Drill deeper, or bore {:.3g} mm at most",
                          h->diameter, c.x, c.y, h->full_depth, op.depth, h->full_depth)));
      return std::nullopt;
    }
    narrowest = std::min(narrowest, h->diameter);
  }
  return narrowest;
}

// The named boring tool, checked against the bore and the pilot hole, or the
// one boring_tool chooses; null after an error.
const Tool* bore_tool(Context& cx, const Operation& op, double diameter, double pilot,
                      std::string& chosen) {
  if (!op.tool) {
    const ToolChoice c = boring_tool(cx.j.tools, diameter, op.depth, pilot);
    if (c.tool == nullptr)
      cx.diags.report({core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc, c.why});
    chosen = c.why;
    return c.tool;
  }
  const Tool* tool = named_tool(cx.j, op, cx.diags);
  if (tool == nullptr) return nullptr;
  std::string why;
  if (!bores(*tool, diameter)) {
    why = tool->max_bore > 0
              ? fmt::format("T{} bores D{:g} to D{:g}; the holes of layer \"{}\" are D{:g}",
                            tool->number, tool->diameter, tool->max_bore, op.layer, diameter)
              : fmt::format("T{} is a boring bar set to D{:g}; the holes of layer \"{}\" are D{:g}",
                            tool->number, tool->diameter, op.layer, diameter);
  } else if (tool->max_bore > 0 && pilot > 0 && tool->diameter > pilot + 0.005) {
    why = fmt::format(
        "T{}'s bar is for holes of D{:g} or more: it does not enter the D{:g} "
        "pilot hole",
        tool->number, tool->diameter, pilot);
  }
  if (!why.empty()) {
    cx.diags.report({core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc, why});
    return nullptr;
  }
  return tool;
}

// A boring head is set to one diameter at the machine; the job writes no
// stop to set it again, so a second diameter needs another head or a bar.
bool set_head(Context& cx, const Operation& op, const Tool& tool, double diameter) {
  if (tool.max_bore <= 0) return true;
  for (const auto& [number, set] : cx.head_settings) {
    if (number != tool.number) continue;
    if (std::abs(set - diameter) <= 0.005) return true;
    cx.diags.report({core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc,
                     fmt::format("the boring head T{} is set to D{:g} for earlier holes; the job "
                                 "writes no stop to set it again to D{:g}: bore D{:g} with "
                                 "another head or a bar set to it",
                                 tool.number, set, diameter, diameter)});
    return false;
  }
  cx.head_settings.emplace_back(tool.number, diameter);
  return true;
}

canon::HoleCycle hole_cycle(BoreCycle c) {
  switch (c) {
  case BoreCycle::DwellFeedOut: return canon::HoleCycle::BoreDwell;
  case BoreCycle::StopRapidOut: return canon::HoleCycle::BoreStop;
  case BoreCycle::FeedOut: break;
  }
  return canon::HoleCycle::Bore;
}

}  // namespace

bool run_bore(Context& cx, const Operation& op, const std::string& title) {
  const auto found = layer_holes(cx, op);
  if (!found) return false;
  const Stock& stock = cx.j.job.stock;
  std::vector<cam::Vec2> centres;
  for (const HoleGroup& g : *found)
    centres.insert(centres.end(), g.centers.begin(), g.centers.end());
  if (!check_hole_centres(stock, op, centres, cx.diags)) return false;
  check_hole_edges(stock, op, *found, cx.diags);
  for (const HoleGroup& g : *found) {
    const auto pilot = op.predrilled ? std::optional<double>(0.0) : pilot_of(cx, op, g);
    if (!pilot) return false;
    std::string chosen;
    const Tool* tool = bore_tool(cx, op, g.diameter, *pilot, chosen);
    if (tool == nullptr || !set_head(cx, op, *tool, g.diameter) ||
        !check_hole_depth(stock, op, *tool, cx.diags))
      return false;
    // The tool as it cuts: at the hole's diameter (its speed is the bore's).
    Tool set = *tool;
    set.diameter = g.diameter;
    set.max_bore = 0;
    cam::DrillOptions o;
    if (!prepare(cx, op, set, false, chosen, o.cut,
                 fmt::format("{}: {} holes D{:g}", title, g.centers.size(), g.diameter)))
      return false;
    if (tool->max_bore > 0)
      cx.sink.comment(fmt::format("set the boring head T{} (D{:g}-{:g}) to D{:.3f}", tool->number,
                                  tool->diameter, tool->max_bore, g.diameter));
    cx.sink.comment(op.predrilled ? std::string("the holes are there before the job "
                                                "(predrilled = true)")
                                  : fmt::format("pilot holes D{:g}, drilled before", *pilot));
    if (cx.sheet != nullptr) cx.sheet->steps.back().holes = g.centers;
    o.form = cam::HoleForm::Features;  // G85 (G89, G86) where the control has it
    o.bore = true;
    o.bore_cycle = hole_cycle(op.bore_cycle);
    o.dwell = op.dwell;
    o.depth = op.depth;
    o.retract = op.retract;
    AtOperation at(cx.diags, op.loc, title);
    if (!cam::generate_drill(g.centers, o, cx.sink, at)) return false;
    for (const cam::Vec2& c : g.centers)
      cx.holes.push_back({c, g.diameter, op.depth});
  }
  return true;
}

}  // namespace usina::job
