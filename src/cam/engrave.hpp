// Engraving text (seed 004, table 7.5, "inscrição"): the strokes of a
// single-stroke Hershey font, each cut as a line at the engraving depth.
#pragma once

#include <string>
#include <vector>

#include "cam/hershey.hpp"
#include "cam/path.hpp"
#include "cam/program.hpp"

namespace usina::cam {

struct EngraveOptions {
  Cutting cut;
  std::string text;
  double height = 10.0;  // mm, the height of a capital letter (the font's "H")
  Vec2 at;               // where the first letter's baseline starts
  double depth = 0.2;    // mm below the top
};

// The text's strokes in mm, each an open polyline; false after
// E_TEXT_NOT_IN_FONT (a character the font has no glyph for) or a bad height.
bool layout_text(const HersheyFont& font, const EngraveOptions& o,
                 std::vector<std::vector<Vec2>>& strokes, core::DiagnosticSink& diags);

// Checks, lays out the text, then for each stroke: over its first point,
// down to −depth, along it. False, with nothing emitted, after an error.
bool generate_engrave(const HersheyFont& font, const EngraveOptions& o, canon::Sink& sink,
                      core::DiagnosticSink& diags);

}  // namespace usina::cam
