// The pockets' forms: usina gen pocket's fields with --rect W,H (and
// --corner-radius), --circle R, or --dxf (a drawing's closed outline with
// its islands, the drawing's text in the body as the profile's form has it).
#include <algorithm>

#include <fmt/format.h>

#include "cam/pocket.hpp"
#include "dnc/form_reading.hpp"

namespace usina::dnc {
namespace {

// What the pockets share: depth, stepover, step down, finish allowance.
cam::PocketOptions read_pocket_options(FormFields& f) {
  cam::PocketOptions o;
  o.depth = f.number("depth", "the depth", cam::kLength, std::nullopt);
  o.stepover = f.number("stepover", "the stepover", cam::kLength, std::nullopt);
  o.step_down = f.number("step_down", "the step down", cam::kLength, 1.0);
  o.finish_allowance =
      f.number("finish_allowance", "the finish allowance", cam::kLengthOrZero, 0.2);
  o.cut = read_cutting(f);
  return o;
}

// The phrases of the pocket generator's messages, and the field each is about.
std::vector<Phrase> pocket_phrases() {
  return {{"stepover", "stepover"},
          {"finish allowance", "finish_allowance"},
          {"step down", "step_down"},
          {"passes", "step_down"},
          {"contour's point", "center_x"}};
}

Reading pocket_reading(cam::PocketShape shape, cam::PocketOptions o) {
  return {[shape = std::move(shape), o](canon::Sink& sink, core::DiagnosticSink& diags) {
            return cam::generate_pocket(shape, o, sink, diags);
          },
          pocket_phrases(), "stepover"};
}

}  // namespace

Reading read_rect_pocket(FormFields& f, post::PostOptions&) {
  const double w = f.number("width", "the rectangle's width", cam::kLength, std::nullopt);
  const double h = f.number("height", "the rectangle's height", cam::kLength, std::nullopt);
  const double r = f.number("corner_radius", "the corner radius", cam::kLengthOrZero, 0.0);
  const cam::Vec2 c = read_point(f, "center_x", "center_y", "the centre");
  cam::PocketOptions o = read_pocket_options(f);
  // As usina gen pocket --rect checks it (gen_cam_options.cpp).
  if (f.ok() && 2 * r > std::min(w, h)) {
    f.fail("corner_radius",
           fmt::format("the corner radius {:g} mm is more than half the rectangle's side {:g} mm",
                       r, std::min(w, h)));
  }
  return pocket_reading({cam::rectangle(c, w, h, r), {}}, o);
}

Reading read_circle_pocket(FormFields& f, post::PostOptions&) {
  const double r = f.number("radius", "the circle's radius", cam::kLength, std::nullopt);
  const cam::Vec2 c = read_point(f, "center_x", "center_y", "the centre");
  return pocket_reading({cam::circle(c, r), {}}, read_pocket_options(f));
}

// The outline and islands of a drawing: the closed contours of its layer
// (all layers when none is named), the outermost the pocket's wall.
Reading read_pocket_dxf(FormFields& f, post::PostOptions&) {
  const FormDrawing drawing = read_drawing(f);
  const cam::PocketOptions o = read_pocket_options(f);
  auto phrases = pocket_phrases();
  phrases.back() = {"spline", "spline_tolerance"};  // a drawing has no centre field
  return {[drawing, o](canon::Sink& sink, core::DiagnosticSink& diags) {
            const auto contours = drawing.contours(diags);
            if (!contours) return false;
            const auto shape = cam::pocket_shape(*contours, diags);
            return shape && cam::generate_pocket(*shape, o, sink, diags);
          },
          std::move(phrases), "stepover", "dxf"};
}

}  // namespace usina::dnc
