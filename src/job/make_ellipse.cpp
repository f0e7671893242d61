#include <string>

#include "cam/ellipse_pocket.hpp"
#include "job/geometry.hpp"
#include "job/make_support.hpp"
#include "job/stock_check.hpp"

namespace usina::job {

bool run_ellipse(Context& cx, const Operation& op, const std::string& title) {
  if (!check_ellipse_pocket(cx.j.job.stock, op, cx.diags)) return false;
  std::string chosen;
  const Tool* tool = mill_for(cx, op, ellipse_smallest_radius(op.rx, op.ry), chosen);
  if (tool == nullptr) return false;
  cam::EllipsePocket p;
  p.center = {op.center[0], op.center[1]};
  p.rx = op.rx;
  p.ry = op.ry;
  p.depth = op.depth;
  p.ae = op.stepover.value_or(tool->diameter / 2);
  p.ap = op.step_down.value_or(tool->diameter / 2);
  AtOperation at(cx.diags, op.loc, title);
  return prepare(cx, op, *tool, p.ae >= tool->diameter, chosen, p.cut, title) &&
         cam::generate_ellipse_pocket(p, cx.sink, at);
}

}  // namespace usina::job
