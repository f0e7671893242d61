// Work materials and their cutting data (data/materials.toml; docs/job.md,
// "Materials"): for each material group, tool material and kind of cut, a
// cutting speed and a feed per tooth (or per revolution, for drills) by tool
// diameter, each row with its published source. From them the spindle speed
// and feed of an operation, by seed 004's formulas (usina calc cutting):
// n = vc·1000/(π·D), vf = fz·z·n, then reduced for slotting and for the
// machine's limits, each step said.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"
#include "job/tools.hpp"

namespace usina::job {

// Bore: finishing a pre-drilled hole with a single-point boring bar; its
// feed is per revolution, as a drill's.
enum class CutKind { Mill, Drill, Bore };

// One row: a material cut by a tool material, in one kind of cut.
struct CuttingRow {
  std::string tool_material;  // "hss", "carbide"
  CutKind cut = CutKind::Mill;
  double vc = 0;  // m/min
  // [diameter mm, feed mm] points: the feed of the largest point at or
  // below the tool's diameter (a chart read by its column); per tooth for
  // milling, per revolution for drilling.
  std::vector<std::pair<double, double>> feed;
  std::string source;
};

struct Material {
  std::string name;
  std::string description;
  std::vector<CuttingRow> rows;
};

std::optional<std::vector<Material>> read_materials(std::string_view toml_text, std::uint32_t file,
                                                    core::DiagnosticSink& diags);

const Material* find_material(const std::vector<Material>& ms, std::string_view name);

// The row for a tool: its own material's, a coated tool taking the carbide
// row when there is no "coated" one (coatings raise the speed; carbide's is
// the lower, safe figure). Null when there is none.
const CuttingRow* cutting_row(const Material& m, const Tool& t, CutKind cut);

struct MachineLimits {
  double max_rpm = 0;   // 0: none
  double max_feed = 0;  // mm/min in the plane, 0: none
};

// The spindle speed and feed of one operation, and why each is what it is.
struct CuttingConditions {
  double rpm = 0;
  double feed = 0;               // mm/min
  double plunge_feed = 0;        // mm/min
  std::vector<std::string> why;  // one line each, for the program's comments
  bool limited = false;          // the machine's limits lowered a figure
};

// Slotting (the tool cutting its full width in solid stock) takes 20 % off
// the cutting speed ("Slotting: reduce 20 percent", the News on Tool end
// mill chart, newsontool.com; docs/job.md). Nullopt when
// the row has no feed at the tool's diameter (below its smallest).
std::optional<CuttingConditions> cutting_conditions(const CuttingRow& row, const Tool& tool,
                                                    bool slotting, const MachineLimits& limits);

}  // namespace usina::job
