// What a generator accepts and how much it may do (issue 11): the documented
// range of every parameter (docs/gen.md, "Ranges") and a bound on the work,
// the moves a generator will emit, estimated before it starts, so that no
// input makes it run out of memory, run for hours, or write a program of
// gigabytes (DESIGN.md, "Errors and bad input").
#pragma once

#include <string_view>
#include <vector>

#include "cam/path.hpp"
#include "core/diagnostic.hpp"

namespace usina::cam {

// The values a parameter may take: from `min` (included or not) to `max`
// (included), in `unit`.
struct Range {
  double min;
  double max;
  bool min_included;
  std::string_view unit;
};

inline constexpr double kMaxCoordinate = 1e5;  // mm from the origin: 100 m
inline constexpr int kMaxPasses = 10000;       // depth passes, rings, tabs, holes / 10

// Sizes, depths, steps, widths and heights: above 0, at most 100 m.
inline constexpr Range kLength{0.0, kMaxCoordinate, false, "mm"};
// Allowances, retract height, lead radius, peck, corner radius: 0 is "none".
inline constexpr Range kLengthOrZero{0.0, kMaxCoordinate, true, "mm"};
// 1 µm, the resolution of a control, to 1 m (a fly cutter).
inline constexpr Range kToolDiameter{0.001, 1000.0, true, "mm"};
inline constexpr Range kFeed{0.0, 1e6, false, "mm/min"};  // up to 1 km/min
inline constexpr Range kSpindle{0.0, 1e6, false, "rev/min"};
// Chords of splines and arcs, the ellipse's DDA increment: below 0.1 µm
// Clipper's integers (offset.hpp) no longer see the difference.
inline constexpr Range kTolerance{0.0001, 10.0, true, "mm"};
inline constexpr Range kAngle{-360.0, 360.0, true, "°"};
inline constexpr Range kToolNumber{0.0, 99999.0, true, ""};

// E_GEN_BAD_VALUE unless `value` is a finite number within `range`; the
// message names `what`, the value and the range. Returns whether it was good.
bool check_range(std::string_view what, double value, const Range& range,
                 core::DiagnosticSink& diags);

// E_GEN_BAD_VALUE unless every point of `paths` is within ±kMaxCoordinate.
bool check_extent(const std::vector<Path>& paths, core::DiagnosticSink& diags);
bool check_point(std::string_view what, Vec2 p, core::DiagnosticSink& diags);

// E_GEN_BAD_VALUE when depth / step makes more than kMaxPasses passes.
bool check_passes(double depth, double step, core::DiagnosticSink& diags);

// The work bound: a generator's moves (canon ops), counted or estimated from
// above before they are made. 20 million moves is about 360 MB of G-code,
// twice the biggest documented job (docs/gen.md, "Speed"); --max-moves raises it.
inline constexpr double kDefaultMaxMoves = 20e6;
inline constexpr Range kMaxMovesRange{1.0, 1e10, true, "moves"};
// Bytes of G-code a move takes, for the message (the rs274ngc post: 117 MB
// for 6.65 million moves).
inline constexpr double kBytesPerMove = 18.0;

// E_GEN_TOO_MUCH_WORK when `moves` is above `max_moves`: the message gives the
// estimate, the output size it means, the limit and `remedy` (what to change).
bool check_work(std::string_view what, double moves, double max_moves, std::string_view remedy,
                core::DiagnosticSink& diags);

// The moves of cutting `paths` once each: a move a segment, and the rapid
// over, the plunge and the retract of each path.
double path_moves(const std::vector<Path>& paths);

// A count for a message: 20,000,000 (thousands separated), or 3.2e+15.
std::string count_text(double n);

}  // namespace usina::cam
