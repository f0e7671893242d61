#include "job/make.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "cam/chain.hpp"
#include "cam/drill.hpp"
#include "cam/pocket.hpp"
#include "cam/profile.hpp"
#include "job/geometry.hpp"
#include "job/make_support.hpp"
#include "job/stock_check.hpp"

namespace usina::job {
namespace {

constexpr double kNoCorner = std::numeric_limits<double>::infinity();

// A drill of the holes' diameter, a spot drill at least as wide (its 90°
// point chamfers the hole's edge as it centres it), or the tap whose tap
// drill the holes are; null after an error.
const Tool* hole_tool(Context& cx, const Operation& op, double diameter, std::string& chosen) {
  const bool spot = op.type == OpType::Spot;
  const bool tap = op.type == OpType::Tap;
  if (op.tool) {
    const Tool* tool = named_tool(cx.j, op, cx.diags);
    if (tool != nullptr && tap && tool->pitch <= 0) {
      cx.diags.report({core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc,
                       fmt::format("T{} has no pitch in the library {}: a tap operation needs "
                                   "it (pitch = mm)",
                                   tool->number, cx.j.job.tools)});
      return nullptr;
    }
    const double size = tool == nullptr ? 0 : tap ? tool->diameter - tool->pitch : tool->diameter;
    const bool fits = tool == nullptr || (spot  ? size >= diameter - 0.005
                                          : tap ? std::abs(size - diameter) <= 0.1
                                                : std::abs(size - diameter) <= 0.005);
    if (!fits) {
      cx.diags.report(
          {core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc,
           fmt::format("T{} is D{:g}; the holes of layer \"{}\" are D{:g}{}", tool->number,
                       tool->diameter, op.layer, diameter,
                       spot  ? ": a spot drill narrower than a hole cannot centre it"
                       : tap ? ": they are not the tap drill of its thread (nominal less pitch)"
                             : "")});
      return nullptr;
    }
    return tool;
  }
  const ToolChoice c = spot  ? spot_drill(cx.j.tools, diameter, op.depth)
                       : tap ? tap_for(cx.j.tools, diameter, op.depth)
                             : drill_of(cx.j.tools, diameter, op.depth + op.retract);
  if (c.tool == nullptr)
    cx.diags.report({core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc, c.why});
  chosen = c.why;
  return c.tool;
}

std::vector<cam::Vec2> centres_of(const std::vector<HoleGroup>& groups) {
  std::vector<cam::Vec2> centres;
  for (const HoleGroup& g : groups)
    centres.insert(centres.end(), g.centers.begin(), g.centers.end());
  return centres;
}

// The depth below Z0 where a drilled hole's full diameter ends: its 118°
// point above the drill's depth, or none when that is through the stock.
double full_depth(const Stock& stock, const Operation& op, double diameter) {
  const double full = op.depth - point_length(diameter, kDrillPointAngle);
  return full >= stock_top(stock).height - 1e-6 ? kNoCorner : full;
}

bool run_drill(Context& cx, const Operation& op, const std::string& title) {
  const auto found = layer_holes(cx, op);
  if (!found) return false;
  const std::vector<HoleGroup>& groups = *found;
  const Stock& stock = cx.j.job.stock;
  if (!check_hole_centres(stock, op, centres_of(groups), cx.diags)) return false;
  check_hole_edges(stock, op, groups, cx.diags);
  for (const HoleGroup& g : groups) {
    std::string chosen;
    const Tool* tool = hole_tool(cx, op, g.diameter, chosen);
    cam::DrillOptions o;
    if (tool == nullptr || !check_hole_depth(stock, op, *tool, cx.diags) ||
        !prepare(cx, op, *tool, false, chosen, o.cut,
                 fmt::format("{}: {} holes D{:g}", title, g.centers.size(), g.diameter))) {
      return false;
    }
    // Drilled holes as canned cycles where the control has them (G81/G83:
    // shorter, editable at the machine, drawn as circles), as their moves
    // where it has not (the post's choice, docs/post.md "Holes"); tapping
    // is written as moves (no rigid tapping cycle is assumed).
    if (cx.sheet != nullptr) cx.sheet->steps.back().holes = g.centers;
    o.form = op.type == OpType::Tap ? cam::HoleForm::Moves : cam::HoleForm::Features;
    o.depth = op.depth;
    o.retract = op.retract;
    o.peck = op.peck;
    if (op.type == OpType::Tap) o.pitch = tool->pitch;
    AtOperation at(cx.diags, op.loc, title);
    if (!cam::generate_drill(g.centers, o, cx.sink, at)) return false;
    // A spot drill's cone and a tap's thread are no pilot hole for a bore.
    if (op.type == OpType::Drill) {
      for (const cam::Vec2& c : g.centers)
        cx.holes.push_back({c, g.diameter, full_depth(stock, op, g.diameter)});
    }
  }
  return true;
}

bool run_pocket(Context& cx, const Operation& op, const std::string& title) {
  const auto paths = layer_paths(cx.j, op, cx.diags);
  if (!paths) return false;
  AtOperation at(cx.diags, op.loc, title);
  const auto shape = cam::pocket_shape(cam::chain(*paths), at);
  if (!shape || !check_pocket(cx.j.job.stock, op, shape->outline, cx.diags)) return false;
  std::string chosen;
  const Tool* tool = mill_for(cx, op, pocket_corner(*shape), chosen);
  if (tool == nullptr) return false;
  cam::PocketOptions o;
  o.depth = op.depth;
  o.step_down = op.step_down.value_or(tool->diameter / 2);
  o.stepover = op.stepover.value_or(tool->diameter / 2);
  const bool slotting = o.stepover >= tool->diameter;
  return prepare(cx, op, *tool, slotting, chosen, o.cut, title) &&
         cam::generate_pocket(*shape, o, cx.sink, at);
}

// The smallest corner the tool meets on the contours' sides (auto: inside
// the holes of the part, outside its outline).
double profile_corner(const std::vector<cam::Path>& contours, const Operation& op) {
  double corner = kNoCorner;
  const std::vector<int> depth = cam::nesting_depths(contours, 0.001);
  for (std::size_t i = 0; i < contours.size(); ++i) {
    if (!contours[i].closed) continue;
    const bool inside = op.side == "inside" || (op.side == "auto" && depth[i] % 2 == 1);
    if (op.side == "inside" || op.side == "outside" || op.side == "auto") {
      corner = std::min(corner, smallest_inside_radius(contours[i], inside));
    }
  }
  return corner;
}

bool run_profile(Context& cx, const Operation& op, const std::string& title) {
  const auto paths = layer_paths(cx.j, op, cx.diags);
  if (!paths) return false;
  const std::vector<cam::Path> contours = cam::chain(*paths);
  if (!check_profile(cx.j.job.stock, op, contours, cx.diags)) return false;
  std::string chosen;
  const Tool* tool = mill_for(cx, op, profile_corner(contours, op), chosen);
  if (tool == nullptr) return false;
  cam::ProfileOptions o;
  o.depth = op.depth;
  o.step_down = op.step_down.value_or(tool->diameter / 2);
  o.side = cam::profile_side(op.side).value_or(cam::ProfileSide::Outside);
  o.lead_radius = op.lead_radius;
  o.tabs = {op.tabs, op.tab_width, op.tab_height};
  AtOperation at(cx.diags, op.loc, title);
  // A profile cuts its full width into the stock: a slot.
  return prepare(cx, op, *tool, true, chosen, o.cut, title) &&
         cam::generate_profile(contours, o, cx.sink, at);
}

void job_header(Context& cx) {
  const Job& job = cx.j.job;
  const Stock& s = job.stock;
  cx.sink.comment(fmt::format("job {}", job.name.empty() ? "(unnamed)" : job.name));
  cx.sink.comment(
      s.shape == "box"
          ? fmt::format("stock box {:g} x {:g} x {:g} mm, corner at X{:g} Y{:g}, top Z0", s.size[0],
                        s.size[1], s.size[2], s.origin[0], s.origin[1])
          : fmt::format("stock cylinder D{:g} x {:g} mm, centre at X{:g} Y{:g}, top Z0", s.size[0],
                        s.size[1], s.origin[0], s.origin[1]));
  const Material& m = cx.j.materials[cx.j.material];
  cx.sink.comment(
      fmt::format("material {}{}", m.name, m.description.empty() ? "" : ": " + m.description));
}

}  // namespace

bool make_job(const LoadedJob& j, canon::Sink& sink, core::DiagnosticSink& diags, SheetLog* sheet) {
  ProgramSink program(sink);
  Context cx{j, program, diags, sheet, {}, {}};
  job_header(cx);
  for (std::size_t i = 0; i < j.job.operations.size(); ++i) {
    const Operation& op = j.job.operations[i];
    const std::string title = fmt::format("operation {} {}{}", i + 1, op_type_name(op.type),
                                          op.layer.empty() ? "" : " layer " + op.layer);
    bool ok = false;
    switch (op.type) {
    case OpType::Drill:
    case OpType::Spot:
    case OpType::Tap: ok = run_drill(cx, op, title); break;
    case OpType::Bore: ok = run_bore(cx, op, title); break;
    case OpType::Pocket: ok = run_pocket(cx, op, title); break;
    case OpType::Profile: ok = run_profile(cx, op, title); break;
    case OpType::EllipsePocket: ok = run_ellipse(cx, op, title); break;
    case OpType::Face: ok = run_face(cx, op, title); break;
    case OpType::Engrave: ok = run_engrave(cx, op, title); break;
    case OpType::Chamfer: ok = run_chamfer(cx, op, title); break;
    }
    if (!ok) return false;
  }
  sink.on(canon::Op{canon::ProgramEnd{}, {}, canon::Origin::Program});
  return true;
}

}  // namespace usina::job
