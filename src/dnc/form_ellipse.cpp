// The elliptical pocket's form (seed 002): usina gen ellipse-pocket's fields.
#include "cam/ellipse_pocket.hpp"
#include "dnc/form_reading.hpp"

namespace usina::dnc {
namespace {

// The DDA increment: from 0.1 µm (ellipse_pocket.cpp's own range).
constexpr cam::Range kResolution{0.0001, cam::kMaxCoordinate, true, "mm"};

}  // namespace

Reading read_ellipse(FormFields& f, post::PostOptions&) {
  cam::EllipsePocket p;
  p.center = read_point(f, "center_x", "center_y", "the centre");
  p.rx = f.number("rx", "the radius along X", cam::kLength, std::nullopt);
  p.ry = f.number("ry", "the radius along Y", cam::kLength, std::nullopt);
  p.depth = f.number("depth", "the depth", cam::kLength, std::nullopt);
  p.ae = f.number("stepover", "the stepover", cam::kLength, std::nullopt);
  p.ap = f.number("step_down", "the step down", cam::kLength, 1.0);
  p.ae_finish = f.number("finish_allowance", "the finish allowance", cam::kLengthOrZero, 0.2);
  p.ap_finish = f.number("floor_allowance", "the floor allowance", cam::kLengthOrZero, 0.0);
  p.resolution = f.number("resolution", "the resolution", kResolution, 0.1);
  p.cut = read_cutting(f);
  return {[p](canon::Sink& sink, core::DiagnosticSink& diags) {
            return cam::generate_ellipse_pocket(p, sink, diags);
          },
          {{"resolution", "resolution"},
           {"stepover", "stepover"},
           {"finish allowance", "finish_allowance"},
           {"floor allowance", "floor_allowance"},
           {"passes", "step_down"}},
          "resolution"};
}

}  // namespace usina::dnc
