// The shop's tool library (examples/tools/shop.toml; docs/job.md, "Tool
// library"): what the crib holds (seed 004, 7.6.3), and the choice of a tool
// for an operation that asks for one rather than naming it.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"

namespace usina::job {

enum class ToolType { Flat, Ball, Bull, Drill, Spot, Chamfer, Tap, Engraver, Face };
enum class ToolMaterial { Hss, Carbide, Coated };

std::string_view tool_type_name(ToolType t);
std::string_view tool_material_name(ToolMaterial m);

struct Tool {
  int number = 0;
  ToolType type = ToolType::Flat;
  std::string name;
  double diameter = 0;         // mm
  int flutes = 2;              // z
  double cutting_length = 0;   // mm of flute: the deepest it cuts
  double overall_length = 0;   // mm
  double holder_diameter = 0;  // mm, 0: not given
  double holder_length = 0;    // mm, 0: not given
  double pitch = 0;            // a tap's thread pitch, mm; 0: not given
  ToolMaterial material = ToolMaterial::Hss;
};

// Reads a library; every problem an error (E_BAD_TOOL_LIBRARY,
// E_UNKNOWN_JOB_KEY) at its line. Nullopt when it is unusable.
std::optional<std::vector<Tool>> read_tool_library(std::string_view toml_text, std::uint32_t file,
                                                   core::DiagnosticSink& diags);

const Tool* find_tool(const std::vector<Tool>& tools, int number);

// A choice, or why none: the reason names the nearest candidate refused.
struct ToolChoice {
  const Tool* tool = nullptr;
  std::string why;  // what was chosen and by which rule, or why none fits
};

// The largest flat end mill whose radius is at most `max_radius` (the
// smallest inside corner radius, seed 004's "the largest end mill that fits
// the corners") and whose cutting length reaches `depth`.
ToolChoice largest_end_mill(const std::vector<Tool>& tools, double max_radius, double depth);

// The largest face mill whose cutting length reaches `step` (a facing
// pass): the fewest rows. Without one, the largest flat end mill that does.
ToolChoice face_mill(const std::vector<Tool>& tools, double step);

// The smallest engraver whose cutting length reaches `depth`: the finest line.
ToolChoice engraver(const std::vector<Tool>& tools, double depth);

// The smallest spot drill at least `diameter` wide whose cutting length
// reaches `depth`.
ToolChoice spot_drill(const std::vector<Tool>& tools, double diameter, double depth);

// The tap for holes of `diameter` (its tap drill): the tap whose nominal
// diameter less its pitch is within 0.1 mm of it (ISO 2306's tap drills
// for coarse metric threads: M8 x 1.25 in 6.8), reaching `depth`.
ToolChoice tap_for(const std::vector<Tool>& tools, double diameter, double depth);

// A drill of `diameter` (within 0.005 mm) whose cutting length reaches `depth`.
ToolChoice drill_of(const std::vector<Tool>& tools, double diameter, double depth);

}  // namespace usina::job
