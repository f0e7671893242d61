// Facing: the stock's top milled flat to a depth, row by row across it
// (seed 004 table 7.6's first operation on a sawn blank). Each row runs in
// X from clear of the stock to clear of it, the rows `stepover` apart in Y,
// their direction alternating (zig-zag); the step between rows is made off
// the stock, so the tool only ever enters the work from the side.
#pragma once

#include "cam/program.hpp"

namespace usina::cam {

struct FaceOptions {
  Cutting cut;
  Vec2 lo, hi;           // the area faced: the stock's corners in XY
  double depth = 0.5;    // mm below the top
  double step_down = 0;  // mm a pass; 0: the whole depth in one
  double stepover = 0;   // mm between rows; 0: 70 % of the tool's diameter
  double clearance = 2;  // mm between the tool and the stock where a row starts and ends
};

// A face mill engages 2/3 to 4/5 of its diameter at its best (Sandvik
// Coromant, "Face milling": a cutter 20-50 % larger than the width of cut):
// the default width of cut.
inline constexpr double kFaceStepoverShare = 0.7;

// Checks, then the passes; false, with nothing emitted, after an error (a
// stepover wider than the tool would leave ribs standing).
bool generate_face(const FaceOptions& o, canon::Sink& sink, core::DiagnosticSink& diags);

}  // namespace usina::cam
