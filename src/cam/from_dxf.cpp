#include "cam/from_dxf.hpp"

#include <numbers>

#include <fmt/format.h>

#include "cam/offset.hpp"
#include "core/arc.hpp"

namespace usina::cam {

bool tool_paths(const std::vector<Path>& paths, Side side, double radius, double tolerance,
                std::vector<Path>& out, core::DiagnosticSink& diags) {
  if (side == Side::On) {
    out = paths;
    return true;
  }
  const bool left = side == Side::Left;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const Path& p = paths[i];
    if (p.closed) {
      std::vector<Path> offsets = offset_closed(p, radius, left, tolerance);
      if (offsets.empty()) {
        return fail(diags, core::Code::GenToolTooBig,
                    fmt::format("contour {} (from ({:g}, {:g})) is too small for a tool of "
                                "radius {:g} mm on its {} side; use a smaller tool",
                                i + 1, p.start.x, p.start.y, radius, left ? "left" : "right"));
      }
      out.insert(out.end(), offsets.begin(), offsets.end());
    } else if (auto o = offset_open(p, radius, left, tolerance)) {
      out.push_back(std::move(*o));
    } else {
      return fail(diags, core::Code::GenToolTooBig,
                  fmt::format("open contour {} (from ({:g}, {:g})) leaves no {} side for a tool "
                              "of radius {:g} mm",
                              i + 1, p.start.x, p.start.y, left ? "left" : "right", radius));
    }
  }
  return true;
}

namespace {

constexpr std::string_view kLessWork = "cut fewer contours at a time";

// The moves from above before the offsets are made: every contour's points
// (arcs in chords when offset) and a full round corner about each.
double estimate_moves(const std::vector<Path>& paths, const FromDxfOptions& o) {
  if (o.side == Side::On) return path_moves(paths) + 10;
  const double corner =
      core::segments_for_tolerance(o.cut.tool_diameter / 2.0, 2 * std::numbers::pi, o.tolerance);
  double n = 10;
  for (const Path& p : paths)
    n += linearized_points(p, o.tolerance) + corner + 3;
  return n;
}

bool check_from_paths(const std::vector<Path>& paths, const FromDxfOptions& o,
                      core::DiagnosticSink& diags) {
  bool ok = check_cutting(o.cut, diags);
  ok = check_range("the depth (--depth)", o.depth, kLength, diags) && ok;
  ok = check_range("the tolerance", o.tolerance, kTolerance, diags) && ok;
  return ok && check_extent(paths, diags) &&
         check_work("the program", estimate_moves(paths, o), o.cut.max_moves, kLessWork, diags);
}

}  // namespace

bool generate_from_paths(const std::vector<Path>& paths, const FromDxfOptions& o, canon::Sink& sink,
                         core::DiagnosticSink& diags) {
  if (!check_from_paths(paths, o, diags)) return false;
  std::vector<Path> cut;
  if (!tool_paths(paths, o.side, o.cut.tool_diameter / 2.0, o.tolerance, cut, diags)) return false;
  if (!check_work("the program", path_moves(cut) + 10, o.cut.max_moves, kLessWork, diags)) {
    return false;
  }
  ProgramWriter w(sink, o.cut);
  w.begin(fmt::format("usina gen from-dxf: {} contours, depth {:g} mm", cut.size(), o.depth));
  for (const Path& p : cut) {
    w.rapid_over(p.start);
    w.plunge(-o.depth);
    w.path(p, -o.depth);
  }
  w.end();
  return true;
}

}  // namespace usina::cam
