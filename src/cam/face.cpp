#include "cam/face.hpp"

#include <cmath>

#include <fmt/format.h>

namespace usina::cam {
namespace {

// The Y of each row's tool centre: the first takes `ae` off the front
// edge, the last leaves the tool's edge at or past the back edge.
std::vector<double> row_ys(double lo, double hi, double radius, double ae) {
  std::vector<double> ys;
  for (double y = lo - radius + ae;; y += ae) {
    ys.push_back(y);
    if (y + radius >= hi) break;
  }
  return ys;
}

bool check_face(const FaceOptions& o, double ae, core::DiagnosticSink& diags) {
  bool ok = check_cutting(o.cut, diags);
  ok = check_range("the facing depth", o.depth, kLength, diags) && ok;
  ok = check_range("the step down", o.step_down, kLengthOrZero, diags) && ok;
  ok = check_range("the stepover", ae, kLength, diags) && ok;
  ok = check_range("the clearance", o.clearance, kLengthOrZero, diags) && ok;
  ok = check_point("the area's first corner", o.lo, diags) && ok;
  ok = check_point("the area's second corner", o.hi, diags) && ok;
  if (!ok) return false;
  if (!(o.hi.x > o.lo.x && o.hi.y > o.lo.y)) {
    return fail(diags, core::Code::GenBadValue, "the area to face is empty");
  }
  if (ae > o.cut.tool_diameter) {
    return fail(diags, core::Code::GenBadValue,
                fmt::format("a stepover of {:g} mm is wider than the D{:g} tool: ribs would "
                            "stand between the rows",
                            ae, o.cut.tool_diameter));
  }
  const double step = o.step_down > 0 ? o.step_down : o.depth;
  if (!check_passes(o.depth, step, diags)) return false;
  const double rows = std::ceil((o.hi.y - o.lo.y) / ae) + 1;
  const double moves = std::ceil(o.depth / step) * (2 * rows + 3) + 10;
  return check_work("the facing", moves, o.cut.max_moves, "give a wider stepover", diags);
}

}  // namespace

bool generate_face(const FaceOptions& o, canon::Sink& sink, core::DiagnosticSink& diags) {
  const double ae = o.stepover > 0 ? o.stepover : kFaceStepoverShare * o.cut.tool_diameter;
  if (!check_face(o, ae, diags)) return false;
  const double r = o.cut.tool_diameter / 2;
  const double x0 = o.lo.x - r - o.clearance;
  const double x1 = o.hi.x + r + o.clearance;
  const std::vector<double> ys = row_ys(o.lo.y, o.hi.y, r, ae);
  ProgramWriter w(sink, o.cut);
  w.begin(fmt::format("usina facing: {:g} mm in {} rows of {:g} mm", o.depth, ys.size(), ae));
  for (const double z : depth_levels(o.depth, o.step_down > 0 ? o.step_down : o.depth)) {
    // Down beside the stock, never onto it.
    w.rapid_over({x0, ys.front()});
    w.plunge(z);
    bool forward = true;
    for (std::size_t i = 0; i < ys.size(); ++i) {
      if (i > 0) w.feed({forward ? x0 : x1, ys[i], z});  // off the stock
      w.feed({forward ? x1 : x0, ys[i], z});
      forward = !forward;
    }
    w.retract();
  }
  w.end();
  return true;
}

}  // namespace usina::cam
