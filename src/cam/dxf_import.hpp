// Reading a DXF drawing's geometry (dxflib): LINE, ARC, CIRCLE, LWPOLYLINE
// and POLYLINE with bulges, SPLINE approximated to a tolerance, each entity a
// Path in drawing order. What cannot be machined as a contour (text, hatches,
// block references, ellipses) is a warning and is left out.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cam/path.hpp"
#include "core/diagnostic.hpp"

namespace usina::cam {

// Coordinates beyond this (mm) are not a part a machine holds: such an
// entity is a warning and left out.
inline constexpr double kMaxDrawingCoordinate = 1e5;

// SPLINE tolerances below this are raised to it (a finer one only makes
// more chords than a control can follow).
inline constexpr double kMinSplineTolerance = 1e-4;

// What the splines of one drawing may cost. Their decomposition into Bézier
// pieces takes time in the square of control points × degree, so the sum of
// those squares is bounded (one spline of degree 3 may have 2,100 control
// points); so is the number of points they make. A SPLINE beyond either, or
// with weights further apart than kMaxSplineWeightRatio, is a warning and is
// left out. The chordal tolerance is at least kSplineRelativeTolerance of the
// spline's extent (1 µm for a 1 m curve).
inline constexpr double kMaxSplineWork = 4e7;
inline constexpr std::size_t kMaxSplinePoints = 10'000'000;
inline constexpr double kMaxSplineWeightRatio = 1e6;
inline constexpr double kSplineRelativeTolerance = 1e-6;

struct DxfOptions {
  std::optional<std::string> layer;  // only this layer (DXF layer names are case-insensitive)
  double spline_tolerance = 0.01;    // mm between a SPLINE and its chords
};

// The largest drawing read; a larger file (or an endless one: a device, a
// pipe that does not end) is an error, E_DXF_UNREADABLE.
inline constexpr std::size_t kMaxDxfBytes = std::size_t{64} << 20;

// The entities of `file` in drawing order, or nullopt after an error
// (E_DXF_UNREADABLE, E_DXF_MALFORMED, E_DXF_NO_ENTITIES). Entities of block
// definitions are not part of the drawing's model space and are skipped.
// Every input ends: the lines are checked before dxflib reads them
// (cam/dxf_groups.hpp).
std::optional<std::vector<Path>> read_dxf(const std::string& file, const DxfOptions& options,
                                          core::DiagnosticSink& diags);

// The same from a stream; `name` names it in messages.
std::optional<std::vector<Path>> read_dxf(std::istream& in, const std::string& name,
                                          const DxfOptions& options, core::DiagnosticSink& diags);

// The same from the file's bytes (at most kMaxDxfBytes are expected).
std::optional<std::vector<Path>> read_dxf_text(std::string_view text, const std::string& name,
                                               const DxfOptions& options,
                                               core::DiagnosticSink& diags);

}  // namespace usina::cam
