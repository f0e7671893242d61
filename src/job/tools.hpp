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

enum class ToolType { Flat, Ball, Bull, Drill, Spot, Chamfer, Tap, Engraver, Face, Bore };
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
  double angle = 0;            // a chamfer mill's or engraver's included angle, deg; 0: not given
  double tip_diameter = 0;     // the flat at a chamfer mill's or engraver's tip, mm
  // A boring head's largest setting, mm: it bores any diameter from
  // `diameter` (the smallest, which its bar enters) to this. 0: a boring
  // bar set to one diameter, `diameter`.
  double max_bore = 0;
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

// Where a chamfer mill of half-angle a = angle/2 and tip radius rt cuts a
// chamfer `width` wide on the top edge (docs/job.md, "Chamfering"): its tip
// goes to depth z = width/tan(a) + tip_offset, below the chamfer's foot on
// the wall, so the tip's corner does not run on the edge; its radius at the
// top face is then r(z) = rt + z tan(a), and its centre runs r(z) - width =
// rt + tip_offset tan(a) off the edge (Autodesk Fusion's 2D chamfer: "chamfer
// width" and "chamfer tip offset").
struct ChamferCut {
  double depth = 0;   // the tip's depth below Z0
  double offset = 0;  // the tool centre's distance from the edge, to the waste side
};

ChamferCut chamfer_cut(const Tool& tool, double width, double tip_offset);

// The widest chamfer the tool's cutting edge makes with that tip offset: the
// edge runs from the tip out to the diameter, or to the cutting length up the
// cone when that ends first; 0 or less when none.
double chamfer_reach(const Tool& tool, double tip_offset);

// The smallest chamfer mill whose cutting edge reaches `width` (the one
// that reaches into the tightest places).
ToolChoice chamfer_mill(const std::vector<Tool>& tools, double width, double tip_offset);

// Whether a boring tool bores `diameter`: a bar set to it (within 0.005 mm),
// or a head whose range holds it.
bool bores(const Tool& tool, double diameter);

// The boring tool for holes of `diameter` bored `depth` deep, whose bar
// enters a pre-drilled hole of `pilot` mm (0: not known): a bar set to the
// diameter first (nothing to set at the machine), else the head whose
// smallest bore is the largest that enters the pilot hole (the thickest,
// stiffest bar).
ToolChoice boring_tool(const std::vector<Tool>& tools, double diameter, double depth, double pilot);

// A drill of `diameter` (within 0.005 mm) whose cutting length reaches `depth`.
ToolChoice drill_of(const std::vector<Tool>& tools, double diameter, double depth);

}  // namespace usina::job
