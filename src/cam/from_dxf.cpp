#include "cam/from_dxf.hpp"

#include <fmt/format.h>

#include "cam/offset.hpp"

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

bool generate_from_paths(const std::vector<Path>& paths, const FromDxfOptions& o, canon::Sink& sink,
                         core::DiagnosticSink& diags) {
  bool ok = check_cutting(o.cut, diags);
  ok = check_positive("the depth", o.depth, "mm", diags) && ok;
  ok = check_positive("the tolerance", o.tolerance, "mm", diags) && ok;
  if (!ok || !check_extent(paths, diags)) return false;
  std::vector<Path> cut;
  if (!tool_paths(paths, o.side, o.cut.tool_diameter / 2.0, o.tolerance, cut, diags)) return false;
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
