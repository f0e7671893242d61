#include "cli/simulate_job.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "cam/chain.hpp"
#include "cam/dxf_import.hpp"
#include "cam/offset.hpp"
#include "cam/path.hpp"

namespace usina::cli {
namespace {

namespace stock = sim::stock;
using core::Vec2;
using Rings = std::vector<std::vector<Vec2>>;

// DXF diagnostics as `usina: SEVERITY[CODE]: message` (they name the file).
class DxfDiagnostics final : public core::DiagnosticSink {
 public:
  void report(core::Diagnostic d) override {
    if (d.severity == core::Severity::Error) ++errors_;
    fmt::print(stderr, "usina: {}[{}]: {}\n", core::severity_name(d.severity),
               core::code_name(d.code), d.message);
  }

  int errors() const { return errors_; }

 private:
  int errors_ = 0;
};

// The library's words for one tool, as --tool-shape writes them.
std::string shape_words(const job::Tool& t) {
  const auto angle = [&t](double fallback) { return t.angle > 0.0 ? t.angle : fallback; };
  switch (t.type) {
  case job::ToolType::Ball: return "ball";
  case job::ToolType::Drill: return fmt::format("drill:{:g}", angle(118.0));
  case job::ToolType::Spot:
  case job::ToolType::Chamfer:
  case job::ToolType::Engraver: return fmt::format("vee:{:g}", angle(90.0));
  case job::ToolType::Tap: return "drill";
  case job::ToolType::Bull:
  case job::ToolType::Flat:
  case job::ToolType::Face:
  case job::ToolType::Bore: break;  // a boring bar's end is square
  }
  return "flat";
}

// Outline counter-clockwise, islands clockwise: the largest ring is the outline.
std::vector<cam::Ring> oriented(const Rings& rings) {
  std::size_t outline = 0;
  for (std::size_t k = 1; k < rings.size(); ++k) {
    if (std::fabs(cam::signed_area2(rings[k])) > std::fabs(cam::signed_area2(rings[outline])))
      outline = k;
  }
  std::vector<cam::Ring> out;
  for (std::size_t k = 0; k < rings.size(); ++k) {
    cam::Ring r = rings[k];
    if ((cam::signed_area2(r) > 0.0) != (k == outline)) std::reverse(r.begin(), r.end());
    out.push_back(std::move(r));
  }
  return out;
}

// What a tool of `radius` reaches of an area: eroded by its radius, grown back.
Rings reachable(const Rings& area, double radius) {
  const std::vector<cam::Ring> in = cam::offset_rings(oriented(area), -radius, kTargetChord);
  return cam::offset_rings(in, radius, kTargetChord);
}

Rings ellipse_ring(const job::Operation& op) {
  // Chords within kTargetChord of the ellipse: its largest radius sets the step.
  const double r = std::max({op.rx, op.ry, kTargetChord});  // acos stays defined
  const auto n = static_cast<std::size_t>(
      std::clamp(std::ceil(std::numbers::pi / std::acos(1.0 - kTargetChord / r)), 64.0, 100000.0));
  std::vector<Vec2> ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    ring.push_back({op.center[0] + op.rx * std::cos(t), op.center[1] + op.ry * std::sin(t)});
  }
  return {ring};
}

const job::SheetStep* step_of(const job::SheetLog& log, std::size_t operation) {
  for (const job::SheetStep& s : log.steps) {
    if (s.operation == operation) return &s;
  }
  return nullptr;
}

// One operation's target, or none for the operations that clear no area.
tl::expected<std::optional<stock::TargetLayer>, std::string> target_of(const job::LoadedJob& j,
                                                                       const job::SheetLog& log,
                                                                       std::size_t i) {
  const job::Operation& op = j.job.operations[i];
  const job::SheetStep* step = step_of(log, i);
  if (step == nullptr) return std::nullopt;  // the job stopped before it
  stock::TargetLayer t;
  t.z = -op.depth;
  t.operation = static_cast<int>(i) + 1;
  t.reachable = true;
  const double radius = step->tool.diameter / 2.0;
  switch (op.type) {
  case job::OpType::Pocket: {
    auto rings = closed_rings(j.job.drawing, op.layer, kTargetChord);
    if (!rings) return tl::unexpected(rings.error());
    t.layer = op.layer;
    t.rings = reachable(*rings, radius);
    t.title = fmt::format("operation {} (pocket, layer {})", i + 1, op.layer);
    break;
  }
  case job::OpType::EllipsePocket:
    t.layer = "ellipse";
    t.rings = reachable(ellipse_ring(op), radius);
    t.title = fmt::format("operation {} (elliptical pocket)", i + 1);
    break;
  case job::OpType::Face: {
    const auto& s = j.job.stock;
    const double x0 = s.origin[0], y0 = s.origin[1];
    t.layer = "face";
    t.rings = {
        {{x0, y0}, {x0 + s.size[0], y0}, {x0 + s.size[0], y0 + s.size[1]}, {x0, y0 + s.size[1]}}};
    t.title = fmt::format("operation {} (facing)", i + 1);
    break;
  }
  default: return std::nullopt;
  }
  return t;
}

}  // namespace

bool is_job_file(std::string_view path) {
  return path.size() > 5 && path.substr(path.size() - 5) == ".toml";
}

tl::expected<Rings, std::string> closed_rings(const std::string& dxf, const std::string& layer,
                                              double chord) {
  cam::DxfOptions options;
  options.layer = layer;
  DxfDiagnostics diags;
  auto entities = cam::read_dxf(dxf, options, diags);
  if (!entities || diags.errors() > 0)
    return tl::unexpected(fmt::format("{} cannot be read (above)", dxf));
  Rings rings;
  for (const cam::Path& p : cam::chain(std::move(*entities))) {
    if (!p.closed) continue;
    auto ring = cam::linearize(p, chord);
    if (ring.size() > 1 && core::distance(ring.front(), ring.back()) < 1e-9) ring.pop_back();
    if (ring.size() >= 3) rings.push_back(std::move(ring));
  }
  if (rings.empty())
    return tl::unexpected(fmt::format("layer {} of {} has no closed contour", layer, dxf));
  return rings;
}

tl::expected<stock::StockBox, std::string> job_stock(const job::Job& j) {
  if (j.stock.shape != "box") {
    return tl::unexpected(
        fmt::format("the job's stock is a {}: the simulation's height map is a box; give --stock "
                    "box:WxLxH and --origin X,Y,Z for the box around it",
                    j.stock.shape));
  }
  stock::StockBox box;
  box.width = j.stock.size[0];
  box.length = j.stock.size[1];
  box.height = j.stock.size[2];
  box.origin = {j.stock.origin[0], j.stock.origin[1], 0.0};
  return box;
}

tl::expected<std::map<int, stock::ToolShape>, std::string> job_tool_shapes(
    const std::vector<job::Tool>& tools) {
  std::map<int, stock::ToolShape> shapes;
  for (const job::Tool& t : tools) {
    // A tap cuts its thread round the hole its drill made: its core.
    const double d =
        t.type == job::ToolType::Tap && t.pitch > 0.0 ? t.diameter - t.pitch : t.diameter;
    std::string spec = fmt::format("{}={}/{:g}", t.number, shape_words(t), d);
    if (t.cutting_length > 0.0) spec += fmt::format(",flutes:{:g}", t.cutting_length);
    auto tool = stock::parse_tool_spec(spec, shapes);
    if (!tool && t.cutting_length > 0.0) {
      // Flutes shorter than the tool's end (a library's short spot drill):
      // the shape without them rather than no shape.
      tool = stock::parse_tool_spec(fmt::format("{}={}/{:g}", t.number, shape_words(t), d), shapes);
    }
    if (!tool)
      return tl::unexpected(fmt::format("tool {} of the library: {}", t.number, tool.error()));
    // A boring head cuts at the diameter the job sets it to, which its tool
    // change carries (make_bore.cpp); its library diameter is only the
    // smallest it sets to. Without one here the simulator takes the stream's.
    if (t.max_bore > 0.0) tool->second.diameter = 0.0;
    shapes[tool->first] = tool->second;
  }
  return shapes;
}

tl::expected<std::vector<stock::TargetLayer>, std::string> job_targets(const job::LoadedJob& j,
                                                                       const job::SheetLog& log) {
  std::vector<stock::TargetLayer> targets;
  for (std::size_t i = 0; i < j.job.operations.size(); ++i) {
    auto t = target_of(j, log, i);
    if (!t) return tl::unexpected(t.error());
    if (*t && !(*t)->rings.empty()) targets.push_back(std::move(**t));
  }
  return targets;
}

}  // namespace usina::cli
