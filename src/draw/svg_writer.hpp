// SVG of a drawing, hand-written XML. The y axis points up: y is written
// negated, so that SVG's downward y shows the drawing as a CAD program does.
// 1 user unit = 1 mm (width and height in mm), the viewBox is view_box() of
// the drawing's bounds, one <g id="LAYER"> per layer, arcs as path A
// commands, circles as <circle>, dashed layers with stroke-dasharray.
#pragma once

#include <ostream>
#include <string>

#include "draw/drawing.hpp"
#include "draw/write_result.hpp"

namespace usina::draw {

// Nothing, or why the drawing could not all be read (Drawing::read_error);
// a failed stream is the caller's to see.
WriteResult write_svg(const Drawing& drawing, std::ostream& out);

// Through core::OutputFile; `inputs` may not be the output.
WriteResult write_svg_file(const Drawing& drawing, const std::string& path,
                           const std::vector<std::string>& inputs = {});

// A number as the SVG and tests see it: at most 4 decimals, no trailing
// zeros, no "-0".
std::string svg_number(double v);

}  // namespace usina::draw
