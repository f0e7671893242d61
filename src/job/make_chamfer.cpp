// Chamfering along a contour (docs/job.md, "Chamfering"): a chamfer mill
// run along the layer's contours by the profile generator, in one pass at
// the depth and offset that its angle, its tip and the chamfer's width give
// (job/tools.hpp, chamfer_cut).
#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cam/chain.hpp"
#include "cam/profile.hpp"
#include "job/make_support.hpp"
#include "job/stock_check.hpp"

namespace usina::job {
namespace {

// Where the chamfer mill's refusal is told: at the width, which is what it
// cannot make, unless the library has no chamfer mill at all.
core::SourceLoc refusal_at(const LoadedJob& j, const Operation& op) {
  const bool any = std::any_of(j.tools.begin(), j.tools.end(),
                               [](const Tool& t) { return t.type == ToolType::Chamfer; });
  return any ? op.width_loc : op.tool_loc;
}

// The named chamfer mill, or the smallest whose edge reaches the width;
// null after an error.
const Tool* chamfer_tool(Context& cx, const Operation& op, std::string& chosen) {
  if (!op.tool) {
    const ToolChoice c = chamfer_mill(cx.j.tools, op.width, op.tip_offset);
    if (c.tool == nullptr) {
      cx.diags.report(
          {core::Code::JobNoToolFits, core::Severity::Error, refusal_at(cx.j, op), c.why});
    }
    chosen = c.why;
    return c.tool;
  }
  const Tool* tool = named_tool(cx.j, op, cx.diags);
  if (tool == nullptr) return nullptr;
  const double reach = chamfer_reach(*tool, op.tip_offset);
  if (reach >= op.width - 1e-9) return tool;
  cx.diags.report(
      {core::Code::JobNoToolFits, core::Severity::Error, op.width_loc,
       fmt::format("width {:g} mm: the edge of T{} (D{:g}, {:g} degrees, tip D{:g}) makes a "
                   "chamfer {:.3g} mm wide at most with the tip {:g} mm below it; give a smaller "
                   "width or tip_offset, or a larger chamfer mill",
                   op.width, tool->number, tool->diameter, tool->angle, tool->tip_diameter,
                   std::max(reach, 0.0), op.tip_offset)});
  return nullptr;
}

}  // namespace

bool run_chamfer(Context& cx, const Operation& op, const std::string& title) {
  const auto paths = layer_paths(cx.j, op, cx.diags);
  if (!paths) return false;
  const std::vector<cam::Path> contours = cam::chain(*paths);
  std::string chosen;
  const Tool* tool = chamfer_tool(cx, op, chosen);
  if (tool == nullptr) return false;
  const ChamferCut c = chamfer_cut(*tool, op.width, op.tip_offset);
  // The tip's depth follows from the width: the stock's check and the
  // setup sheet take it, and point at the width.
  Operation at_depth = op;
  at_depth.depth = c.depth;
  at_depth.depth_loc = op.width_loc;
  if (!check_profile(cx.j.job.stock, at_depth, contours, cx.diags)) return false;
  cam::ProfileOptions o;
  o.depth = c.depth;
  o.step_down = c.depth;  // one pass: the cone cuts the whole chamfer at once
  o.side = cam::profile_side(op.side).value_or(cam::ProfileSide::Outside);
  o.offset = c.offset;
  if (!prepare(cx, at_depth, *tool, false, chosen, o.cut, title)) return false;
  const double half = tool->angle / 2;
  cx.sink.comment(fmt::format(
      "chamfer {:g} mm wide at {:g} deg to the wall: tip at Z-{:.4f} = width/tan[{:g}] + tip "
      "offset {:g}; centre {:.4f} mm off the edge = tip radius {:g} + tip offset*tan[{:g}]",
      op.width, half, c.depth, half, op.tip_offset, c.offset, tool->tip_diameter / 2, half));
  AtOperation at(cx.diags, op.loc, title);
  return cam::generate_profile(contours, o, cx.sink, at);
}

}  // namespace usina::job
