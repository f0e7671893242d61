#include "job/make_support.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cam/dxf_import.hpp"

namespace usina::job {

void ProgramSink::on(const canon::Op& op) {
  if (std::holds_alternative<canon::ProgramEnd>(op.kind)) return;
  if (const auto* t = std::get_if<canon::ToolChange>(&op.kind)) {
    if (tool_ == t->tool) return;
    tool_ = t->tool;
  }
  next_.on(op);
}

void ProgramSink::comment(std::string text) {
  next_.on(canon::Op{canon::Comment{std::move(text)}, {}, canon::Origin::Program});
}

void AtOperation::report(core::Diagnostic d) {
  if (d.loc.line == 0) {
    d.loc = loc_;
    d.message = fmt::format("{}: {}", what_, d.message);
  }
  next_.report(std::move(d));
}

std::optional<std::vector<cam::Path>> layer_paths(const LoadedJob& j, const Operation& op,
                                                  core::DiagnosticSink& diags) {
  if (j.job.drawing.empty()) {
    diags.report({core::Code::BadJob, core::Severity::Error, op.layer_loc,
                  "the layer is of a drawing: give [job] drawing = \"FILE.dxf\""});
    return std::nullopt;
  }
  cam::DxfOptions o;
  o.layer = op.layer;
  core::DiagnosticList local;
  auto paths = cam::read_dxf(j.job.drawing, o, local);
  for (core::Diagnostic d : local.all()) {
    if (d.code == core::Code::DxfNoEntities) {
      d = {core::Code::JobMissingLayer, core::Severity::Error, op.layer_loc,
           fmt::format("the drawing {} has nothing to cut on layer \"{}\" (absent, empty, or "
                       "only text and blocks): check the layer's name",
                       j.job.drawing, op.layer)};
    } else if (d.loc.line == 0) {
      d.loc = op.layer_loc;
    }
    diags.report(std::move(d));
  }
  return paths;
}

std::optional<std::vector<HoleGroup>> layer_holes(Context& cx, const Operation& op) {
  const auto paths = layer_paths(cx.j, op, cx.diags);
  if (!paths) return std::nullopt;
  std::size_t others = 0;
  std::vector<HoleGroup> groups = holes_of(*paths, others);
  if (op.diameter) {
    std::erase_if(groups,
                  [&](const HoleGroup& g) { return std::abs(g.diameter - *op.diameter) > 1e-3; });
  }
  if (groups.empty() || others > 0) {
    cx.diags.report({core::Code::BadJob, core::Severity::Error, op.layer_loc,
                     fmt::format("layer \"{}\" has {} circles{} and {} other entities: a {} "
                                 "layer holds the holes' circles only",
                                 op.layer, groups.size(), op.diameter ? " of that diameter" : "",
                                 others, op_type_name(op.type))});
    return std::nullopt;
  }
  return groups;
}

namespace {

bool is_end_mill(ToolType t) {
  return t == ToolType::Flat || t == ToolType::Ball || t == ToolType::Bull;
}

// Whether an operation of `op` runs a tool of type `t`, and what it takes.
bool takes_tool(OpType op, ToolType t) {
  switch (op) {
  case OpType::Drill: return t == ToolType::Drill;
  case OpType::Spot: return t == ToolType::Spot;
  case OpType::Tap: return t == ToolType::Tap;
  case OpType::Bore: return t == ToolType::Bore;
  case OpType::Face: return t == ToolType::Face || t == ToolType::Flat || t == ToolType::Bull;
  case OpType::Engrave:
    return t == ToolType::Engraver || t == ToolType::Flat || t == ToolType::Ball;
  case OpType::Chamfer: return t == ToolType::Chamfer;
  default: return is_end_mill(t);
  }
}

std::string_view tools_taken(OpType op) {
  switch (op) {
  case OpType::Drill: return "a drill";
  case OpType::Spot: return "a spot drill";
  case OpType::Tap: return "a tap";
  case OpType::Bore: return "a boring bar or head";
  case OpType::Face: return "a face mill, or a flat or bull end mill";
  case OpType::Engrave: return "an engraver, or a flat or ball end mill";
  case OpType::Chamfer: return "a chamfer mill";
  default: return "a flat, ball or bull end mill";
  }
}

}  // namespace

const Tool* named_tool(const LoadedJob& j, const Operation& op, core::DiagnosticSink& diags) {
  const Tool* t = find_tool(j.tools, *op.tool);
  if (t == nullptr) {
    diags.report({core::Code::JobUnknownTool, core::Severity::Error, op.tool_loc,
                  fmt::format("tool {} is not in the library {}", *op.tool, j.job.tools)});
    return nullptr;
  }
  // A drill drills and an end mill mills: the cutting data and the moves
  // are each kind's own.
  const std::string_view takes = tools_taken(op.type);
  if (!takes_tool(op.type, t->type)) {
    diags.report({core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc,
                  fmt::format("T{} is a {} tool; a {} operation takes {}", t->number,
                              tool_type_name(t->type), op_type_name(op.type), takes)});
    return nullptr;
  }
  // A facing cuts its depth in passes: the tool reaches one.
  const double reach = op.type == OpType::Face ? op.step_down.value_or(op.depth) : op.depth;
  if (t->cutting_length < reach) {
    diags.report({core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc,
                  fmt::format("T{} cuts {:g} mm deep at most (its cutting length); the "
                              "operation goes {:g} mm deep{}",
                              t->number, t->cutting_length, reach,
                              op.type == OpType::Face ? " a pass" : "")});
    return nullptr;
  }
  return t;
}

namespace {

// The machine's limits: its spindle's top speed, the slower of X and Y.
MachineLimits limits_of(const LoadedJob& j) {
  MachineLimits m;
  if (!j.machine) return m;
  m.max_rpm = j.machine->spindle_max_rpm;
  m.max_feed = std::min(j.machine->axes[0].max_feed, j.machine->axes[1].max_feed);
  return m;
}

// The milling rows are end mills' charts, read at the cutter's diameter; a
// chamfer mill cuts at every diameter from its tip to the chamfer's top at
// once, and no cited table gives its speeds.
bool no_chamfer_data(const LoadedJob& j, const Operation& op, const Tool& tool,
                     core::DiagnosticSink& diags) {
  diags.report({core::Code::JobNoCuttingData, core::Severity::Error, op.loc,
                fmt::format("the cutting data have no rows for a chamfer mill (T{}; the end mill "
                            "charts are read at a cutter's full diameter, and a chamfer mill "
                            "cuts at every diameter of its cone): give rpm and feed in the "
                            "operation, or add the row to {}",
                            tool.number, j.job.materials)});
  return false;
}

bool from_cutting_data(const LoadedJob& j, const Operation& op, const Tool& tool, bool slotting,
                       CuttingConditions& c, core::DiagnosticSink& diags) {
  if (tool.type == ToolType::Chamfer) return no_chamfer_data(j, op, tool, diags);
  const Material& m = j.materials[j.material];
  // A spot drill drills: the tables' drilling rows (none for carbide).
  const bool drills = tool.type == ToolType::Drill || tool.type == ToolType::Spot;
  const CutKind kind = drills                        ? CutKind::Drill
                       : tool.type == ToolType::Bore ? CutKind::Bore
                                                     : CutKind::Mill;
  const CuttingRow* row = cutting_row(m, tool, kind);
  const auto conditions =
      row ? cutting_conditions(*row, tool, slotting, limits_of(j)) : std::nullopt;
  if (!conditions) {
    diags.report({core::Code::JobNoCuttingData, core::Severity::Error, op.loc,
                  fmt::format("{} has no {} data for a {} tool of D{:g} (T{}): give rpm and "
                              "feed in the operation, or add the row to {}",
                              m.name,
                              kind == CutKind::Drill  ? "drilling"
                              : kind == CutKind::Bore ? "boring"
                                                      : "milling",
                              tool_material_name(tool.material), tool.diameter, tool.number,
                              j.job.materials)});
    return false;
  }
  c = *conditions;
  if (c.limited) {
    diags.report({core::Code::JobCuttingLimited, core::Severity::Note, op.loc,
                  fmt::format("T{}: the machine's limits lower the speed or feed: {}", tool.number,
                              fmt::join(c.why, "; "))});
  }
  return true;
}

}  // namespace

bool cutting_values(const LoadedJob& j, const Operation& op, const Tool& tool, bool slotting,
                    cam::Cutting& cut, std::vector<std::string>& why, core::DiagnosticSink& diags) {
  cut.tool = tool.number;
  cut.tool_diameter = tool.diameter;
  cut.safe_z = j.job.safe_z;
  CuttingConditions c;
  if (op.type == OpType::Tap && op.rpm) {
    c.rpm = *op.rpm;
    c.feed = c.plunge_feed = tool.pitch * c.rpm;
    c.why.push_back(fmt::format("n {:g} as the job gives it; vf = pitch {:g} x n = {:g}", c.rpm,
                                tool.pitch, c.feed));
  } else if (op.rpm && op.feed) {
    c.rpm = *op.rpm;
    c.feed = *op.feed;
    const bool axial = tool.type == ToolType::Drill || tool.type == ToolType::Spot ||
                       tool.type == ToolType::Bore;  // the whole cut is along Z
    c.plunge_feed = axial ? c.feed : c.feed / 2;
    c.why.push_back(fmt::format("n {:g} and vf {:g} as the job gives them", c.rpm, c.feed));
  } else if (!from_cutting_data(j, op, tool, slotting, c, diags)) {
    return false;
  }
  if (op.plunge_feed) {
    c.plunge_feed = *op.plunge_feed;
    c.why.push_back(fmt::format("plunge feed {:g} as the job gives it", c.plunge_feed));
  }
  cut.rpm = c.rpm;
  cut.feed = c.feed;
  cut.plunge_feed = c.plunge_feed;
  why = std::move(c.why);
  return true;
}

// The tool of `op`: named, or the largest end mill the corners allow.
const Tool* mill_for(Context& cx, const Operation& op, double corner, std::string& chosen) {
  if (op.tool) return named_tool(cx.j, op, cx.diags);
  const ToolChoice c = largest_end_mill(cx.j.tools, corner, op.depth);
  if (c.tool == nullptr) {
    cx.diags.report({core::Code::JobNoToolFits, core::Severity::Error, op.tool_loc, c.why});
  }
  chosen = c.why;
  return c.tool;
}

// The operation's comments, its tool and cutting values; false after an error.
bool prepare(Context& cx, const Operation& op, const Tool& tool, bool slotting,
             const std::string& chosen, cam::Cutting& cut, const std::string& title) {
  std::vector<std::string> why;
  if (!cutting_values(cx.j, op, tool, slotting, cut, why, cx.diags)) return false;
  if (cx.sheet != nullptr)
    cx.sheet->begin({title,
                     tool,
                     op.depth,
                     cut.rpm,
                     cut.feed,
                     cut.plunge_feed,
                     chosen,
                     why,
                     {},
                     {},
                     static_cast<std::size_t>(&op - cx.j.job.operations.data())});
  cx.sink.comment(title);
  cx.sink.comment(fmt::format("T{} {} D{:g} {} z{}, cutting length {:g}", tool.number,
                              tool_type_name(tool.type), tool.diameter,
                              tool_material_name(tool.material), tool.flutes, tool.cutting_length));
  if (!chosen.empty()) cx.sink.comment("chosen: " + chosen);
  for (const std::string& w : why)
    cx.sink.comment(w);
  return true;
}

}  // namespace usina::job
