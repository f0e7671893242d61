// The operations on the stock's top face that need no drawing: facing the
// blank flat, and engraving text (docs/job.md, "Operations").
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cam/engrave.hpp"
#include "cam/face.hpp"
#include "cam/hershey.hpp"
#include "job/make_support.hpp"
#include "job/stock_check.hpp"

namespace usina::job {
namespace {

// The stock's extent in XY: a box from its corner, a cylinder's square
// about its centre (the rows past the round edge cut air).
void stock_area(const Stock& s, cam::Vec2& lo, cam::Vec2& hi) {
  if (s.shape == "box") {
    lo = {s.origin[0], s.origin[1]};
    hi = {s.origin[0] + s.size[0], s.origin[1] + s.size[1]};
  } else {
    const double r = s.size[0] / 2;
    lo = {s.origin[0] - r, s.origin[1] - r};
    hi = {s.origin[0] + r, s.origin[1] + r};
  }
}

// The named tool, or the one `choose` picks; null after an error.
template <class Choose>
const Tool* tool_for(Context& cx, const Operation& op, std::string& chosen, Choose choose) {
  if (op.tool) return named_tool(cx.j, op, cx.diags);
  const ToolChoice c = choose();
  if (c.tool == nullptr)
    cx.diags.report({core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc, c.why});
  chosen = c.why;
  return c.tool;
}

}  // namespace

bool run_face(Context& cx, const Operation& op, const std::string& title) {
  // The whole top is faced: only the depth is checked.
  if (!check_face(cx.j.job.stock, op, cx.diags)) return false;
  std::string chosen;
  const double pass = op.step_down.value_or(op.depth);
  const Tool* tool = tool_for(cx, op, chosen, [&] { return face_mill(cx.j.tools, pass); });
  if (tool == nullptr) return false;
  cam::FaceOptions o;
  stock_area(cx.j.job.stock, o.lo, o.hi);
  o.depth = op.depth;
  o.step_down = pass;
  o.stepover = op.stepover.value_or(cam::kFaceStepoverShare * tool->diameter);
  AtOperation at(cx.diags, op.loc, title);
  return prepare(cx, op, *tool, o.stepover >= tool->diameter, chosen, o.cut, title) &&
         cam::generate_face(o, cx.sink, at);
}

bool run_engrave(Context& cx, const Operation& op, const std::string& title) {
  std::string chosen;
  const Tool* tool = tool_for(cx, op, chosen, [&] { return engraver(cx.j.tools, op.depth); });
  if (tool == nullptr) return false;
  AtOperation at(cx.diags, op.loc, title);
  const auto font = cam::read_hershey(cam::hershey_file(op.font), at);
  if (!font) return false;
  cam::EngraveOptions o;
  o.text = op.text;
  o.height = op.height;
  o.at = {op.at[0], op.at[1]};
  o.depth = op.depth;
  // The strokes laid out once here to be checked on the stock; the
  // generator lays them out again as it cuts them.
  std::vector<std::vector<cam::Vec2>> strokes;
  if (!cam::layout_text(*font, o, strokes, at) ||
      !check_engraving(cx.j.job.stock, op, strokes, cx.diags)) {
    return false;
  }
  // An engraver cuts its whole width: a slot.
  return prepare(cx, op, *tool, true, chosen, o.cut, title) &&
         cam::generate_engrave(*font, o, cx.sink, at);
}

}  // namespace usina::job
