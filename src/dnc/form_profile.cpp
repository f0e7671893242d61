// The profile's form, usina gen profile --dxf with the drawing's text in
// the body, and the reading of a form's drawing (the pocket's too).
#include "cam/chain.hpp"
#include "cam/dxf_import.hpp"
#include "cam/profile.hpp"
#include "dnc/form_reading.hpp"

namespace usina::dnc {
namespace {

constexpr int kMaxTabs = 10000;

}  // namespace

FormDrawing read_drawing(FormFields& f) {
  FormDrawing d;
  d.text = f.text("dxf", "the drawing", cam::kMaxDxfBytes, std::nullopt);
  const std::string layer = f.text("layer", "the layer", 255, std::string());
  if (!layer.empty()) d.options.layer = layer;
  d.options.spline_tolerance =
      f.number("spline_tolerance", "the spline tolerance", cam::kTolerance, 0.01);
  return d;
}

std::optional<std::vector<cam::Path>> FormDrawing::contours(core::DiagnosticSink& diags) const {
  auto entities = cam::read_dxf_text(text, "the drawing", options, diags);
  if (!entities) return std::nullopt;
  return cam::chain(std::move(*entities));
}

Reading read_profile_dxf(FormFields& f, post::PostOptions&) {
  const FormDrawing drawing = read_drawing(f);
  cam::ProfileOptions o;
  const std::string side =
      f.choice("side", "the side", {"outside", "inside", "auto", "left", "right", "on"}, "outside");
  o.depth = f.number("depth", "the depth", cam::kLength, std::nullopt);
  o.step_down = f.number("step_down", "the step down", cam::kLength, 1.0);
  o.lead_radius = f.number("lead_radius", "the lead radius", cam::kLengthOrZero, 0.0);
  o.tabs.count = f.whole("tabs", "the tab count", 0, kMaxTabs, 0);
  o.tabs.width = f.number("tab_width", "the tab width", cam::kLength, 3.0);
  o.tabs.height = f.number("tab_height", "the tab height", cam::kLength, 1.0);
  o.cut = read_cutting(f);
  if (const auto s = cam::profile_side(side)) o.side = *s;
  return {[drawing, o](canon::Sink& sink, core::DiagnosticSink& diags) {
            const auto contours = drawing.contours(diags);
            return contours && cam::generate_profile(*contours, o, sink, diags);
          },
          {{"tab height", "tab_height"},
           {"tabs", "tabs"},
           {"lead", "lead_radius"},
           {"open", "side"},
           {"step down", "step_down"},
           {"passes", "step_down"},
           {"spline", "spline_tolerance"}},
          "dxf",
          "dxf"};
}

}  // namespace usina::dnc
