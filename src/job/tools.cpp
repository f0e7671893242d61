#include "job/tools.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "job/toml_reader.hpp"

namespace usina::job {
namespace {

constexpr std::array kTypes = {
    std::pair{ToolType::Flat, "flat"}, std::pair{ToolType::Ball, "ball"},
    std::pair{ToolType::Bull, "bull"}, std::pair{ToolType::Drill, "drill"},
    std::pair{ToolType::Spot, "spot"}, std::pair{ToolType::Chamfer, "chamfer"},
    std::pair{ToolType::Tap, "tap"},   std::pair{ToolType::Engraver, "engraver"},
    std::pair{ToolType::Face, "face"}, std::pair{ToolType::Bore, "bore"},
};
constexpr std::array kMaterials = {
    std::pair{ToolMaterial::Hss, "hss"},
    std::pair{ToolMaterial::Carbide, "carbide"},
    std::pair{ToolMaterial::Coated, "coated"},
};
constexpr std::string_view kToolKeys[] = {
    "number",        "type",           "name",           "diameter",
    "flutes",        "cutting_length", "overall_length", "holder_diameter",
    "holder_length", "material",       "pitch",          "angle",
    "tip_diameter",  "diameter_range"};

constexpr Range kNumber{1, 9999, ""};
constexpr Range kDiameter{0.01, 500, "mm"};
constexpr Range kFlutes{1, 50, "flutes"};
constexpr Range kLength{0.01, 1000, "mm"};
constexpr Range kPitch{0.05, 10, "mm"};
// 0 and 180 themselves are no cone: a needle and a flat end.
constexpr Range kAngle{0.001, 179.999, "degrees"};
constexpr Range kTip{0, 500, "mm"};

template <typename E, std::size_t N>
std::optional<E> by_name(const std::array<std::pair<E, const char*>, N>& names,
                         std::string_view s) {
  for (const auto& [e, n] : names) {
    if (s == n) return e;
  }
  return std::nullopt;
}

template <typename E, std::size_t N>
std::string list(const std::array<std::pair<E, const char*>, N>& names) {
  std::string out;
  for (const auto& [e, n] : names)
    out += fmt::format("{}\"{}\"", out.empty() ? "" : ", ", n);
  return out;
}

// A chamfer mill's or an engraver's cone: only they have an angle and a
// tip flat, and a chamfer mill needs its angle. Chamfer mills are made at
// 60, 82, 90, 100 and 120 degrees; an angle taken for granted would
// silently put the tip at another depth and the path at another offset, a
// chamfer of the wrong width and angle (the reason an unknown key is an
// error too). An engraver's angle is only recorded: it cuts with its tip.
bool check_cone(TomlReader& r, const toml::table& t, const std::string& what, const Tool& tool) {
  const bool cone = tool.type == ToolType::Chamfer || tool.type == ToolType::Engraver;
  for (const char* key : {"angle", "tip_diameter"}) {
    if (!cone && t.get(key) != nullptr) {
      r.fail(t.get(key)->source(),
             fmt::format("{}: only a chamfer mill or an engraver has {}", what, key));
      return false;
    }
  }
  if (tool.type == ToolType::Chamfer && t.get("angle") == nullptr) {
    r.fail(t.source(), fmt::format("{}: a chamfer mill needs its included angle (angle = 90 for "
                                   "a 45-degree chamfer): the chamfer's depth and path follow "
                                   "from it",
                                   what));
    return false;
  }
  if (tool.tip_diameter >= tool.diameter && t.get("tip_diameter") != nullptr) {
    r.fail(t.get("tip_diameter")->source(),
           fmt::format("{}: tip_diameter {:g} is not below the diameter {:g}: the tip's flat is "
                       "the narrow end of the cone",
                       what, tool.tip_diameter, tool.diameter));
    return false;
  }
  return true;
}

// A boring tool is a bar set to one `diameter`, or a head with its
// `diameter_range = [smallest, largest]`: one or the other, never both (a
// head's set diameter changes at the machine, the job sets it per hole).
// Only a boring tool has a range. The diameter is then the range's start:
// the smallest hole its bar enters.
bool read_bore_size(TomlReader& r, const toml::table& t, const std::string& what, Tool& tool,
                    bool has_diameter) {
  const toml::node* range = t.get("diameter_range");
  if (tool.type != ToolType::Bore) {
    if (range != nullptr) {
      r.fail(range->source(), fmt::format("{}: only a boring tool has a diameter_range", what));
      return false;
    }
    return has_diameter;
  }
  if (range != nullptr && has_diameter) {
    r.fail(range->source(),
           fmt::format("{}: give diameter (a bar set to one size) or diameter_range (a boring "
                       "head's smallest and largest bore), not both",
                       what));
    return false;
  }
  if (range == nullptr) {
    if (!has_diameter)
      r.fail(t.source(), fmt::format("{}: a boring tool needs diameter (a bar set to one size) "
                                     "or diameter_range = [smallest, largest] (a boring head)",
                                     what));
    return has_diameter;
  }
  const auto d = r.numbers(t, what, "diameter_range", 2, kDiameter, true);
  if (!d) return false;
  if ((*d)[1] <= (*d)[0]) {
    r.fail(range->source(),
           fmt::format("{}: diameter_range [{:g}, {:g}] is not [smallest, largest]", what, (*d)[0],
                       (*d)[1]));
    return false;
  }
  tool.diameter = (*d)[0];
  tool.max_bore = (*d)[1];
  return true;
}

// One [[tool]] entry; nullopt after an error.
std::optional<Tool> read_tool(TomlReader& r, const toml::table& t) {
  r.known_keys(t, "[[tool]]", kToolKeys);
  Tool tool;
  const auto number = r.number(t, "[[tool]]", "number", kNumber, true);
  const std::string what = number ? fmt::format("tool {:g}", *number) : "[[tool]]";
  const auto type = r.text(t, what, "type", true);
  const bool bore = t.get("type") != nullptr && t.get("type")->value_or<std::string>("") == "bore";
  const auto diameter = r.number(t, what, "diameter", kDiameter, !bore);
  const auto flutes = r.number(t, what, "flutes", kFlutes, false);
  const auto cutting = r.number(t, what, "cutting_length", kLength, true);
  const auto material = r.text(t, what, "material", true);
  tool.overall_length = r.number(t, what, "overall_length", kLength, false).value_or(0.0);
  tool.holder_diameter = r.number(t, what, "holder_diameter", kLength, false).value_or(0.0);
  tool.holder_length = r.number(t, what, "holder_length", kLength, false).value_or(0.0);
  tool.name = r.text(t, what, "name", false).value_or("");
  tool.pitch = r.number(t, what, "pitch", kPitch, false).value_or(0.0);
  tool.angle = r.number(t, what, "angle", kAngle, false).value_or(0.0);
  tool.tip_diameter = r.number(t, what, "tip_diameter", kTip, false).value_or(0.0);
  if (number && *number != std::floor(*number)) {
    r.fail(t.get("number")->source(), fmt::format("{}: the number must be whole", what));
    return std::nullopt;
  }
  const auto ty = type ? by_name(kTypes, *type) : std::nullopt;
  if (type && !ty) {
    r.fail(t.get("type")->source(), fmt::format("{}: type \"{}\" is not one usina knows: give {}",
                                                what, *type, list(kTypes)));
  }
  const auto ma = material ? by_name(kMaterials, *material) : std::nullopt;
  if (material && !ma) {
    r.fail(t.get("material")->source(),
           fmt::format("{}: material \"{}\" is not one usina knows: give {}", what, *material,
                       list(kMaterials)));
  }
  if (!number || !ty || !cutting || !ma) return std::nullopt;
  tool.number = static_cast<int>(*number);
  tool.type = *ty;
  tool.diameter = diameter.value_or(0.0);
  if (!read_bore_size(r, t, what, tool, diameter.has_value())) return std::nullopt;
  tool.flutes = static_cast<int>(flutes.value_or(2.0));
  tool.cutting_length = *cutting;
  tool.material = *ma;
  if (tool.type != ToolType::Tap && tool.pitch > 0) {
    r.fail(t.get("pitch")->source(), fmt::format("{}: only a tap has a pitch", what));
    return std::nullopt;
  }
  if (!check_cone(r, t, what, tool)) return std::nullopt;
  return tool;
}

}  // namespace

std::string_view tool_type_name(ToolType t) {
  for (const auto& [e, n] : kTypes) {
    if (e == t) return n;
  }
  return "?";
}

std::string_view tool_material_name(ToolMaterial m) {
  for (const auto& [e, n] : kMaterials) {
    if (e == m) return n;
  }
  return "?";
}

std::optional<std::vector<Tool>> read_tool_library(std::string_view toml_text, std::uint32_t file,
                                                   core::DiagnosticSink& diags) {
  TomlReader r(toml_text, file, core::Code::BadToolLibrary, diags);
  const auto root = r.parse();
  if (!root) return std::nullopt;
  const toml::array* entries = r.entries(*root, "tool", "the tool library");
  if (entries == nullptr) return std::nullopt;
  std::vector<Tool> tools;
  std::set<int> numbers;  // a search of `tools` for each tool is quadratic
  for (const toml::node& e : *entries) {
    const auto tool = read_tool(r, *e.as_table());
    if (!tool) continue;
    if (!numbers.insert(tool->number).second) {
      r.fail(e.source(), fmt::format("tool {} is in the library twice", tool->number));
      continue;
    }
    tools.push_back(*tool);
  }
  if (!r.ok()) return std::nullopt;
  return tools;
}

const Tool* find_tool(const std::vector<Tool>& tools, int number) {
  for (const Tool& t : tools) {
    if (t.number == number) return &t;
  }
  return nullptr;
}

ToolChoice largest_end_mill(const std::vector<Tool>& tools, double max_radius, double depth) {
  ToolChoice c;
  const Tool* refused = nullptr;  // the largest flat end mill refused, to say why
  for (const Tool& t : tools) {
    if (t.type != ToolType::Flat) continue;
    const bool fits = t.diameter / 2 <= max_radius + 1e-9 && t.cutting_length >= depth;
    if (fits && (c.tool == nullptr || t.diameter > c.tool->diameter)) c.tool = &t;
    if (!fits && (refused == nullptr || t.diameter > refused->diameter)) refused = &t;
  }
  const std::string corner = std::isinf(max_radius)
                                 ? std::string("no inside corner to fit")
                                 : fmt::format("a smallest inside corner of R{:g}", max_radius);
  if (c.tool != nullptr) {
    c.why = fmt::format(
        "T{}: the largest flat end mill for {} with a cutting length of {:g} mm "
        "or more",
        c.tool->number, corner, depth);
  } else if (refused == nullptr) {
    c.why = "the library has no flat end mill";
  } else {
    c.why = fmt::format(
        "no flat end mill fits {} at a depth of {:g} mm: the largest, T{}, is "
        "R{:g} with a cutting length of {:g} mm",
        corner, depth, refused->number, refused->diameter / 2, refused->cutting_length);
  }
  return c;
}

namespace {

// The tool of `type` reaching `depth` that `better` prefers, or null.
template <class Better>
const Tool* best_of(const std::vector<Tool>& tools, ToolType type, double depth, Better better) {
  const Tool* best = nullptr;
  for (const Tool& t : tools) {
    if (t.type == type && t.cutting_length >= depth && (best == nullptr || better(t, *best)))
      best = &t;
  }
  return best;
}

bool larger(const Tool& a, const Tool& b) {
  return a.diameter > b.diameter;
}

}  // namespace

ToolChoice face_mill(const std::vector<Tool>& tools, double step) {
  ToolChoice c;
  if ((c.tool = best_of(tools, ToolType::Face, step, larger))) {
    c.why = fmt::format("T{}: the largest face mill with a cutting length of {:g} mm or more",
                        c.tool->number, step);
  } else if ((c.tool = best_of(tools, ToolType::Flat, step, larger))) {
    c.why =
        fmt::format("T{}: no face mill reaches {:g} mm a pass; the largest flat end mill that does",
                    c.tool->number, step);
  } else {
    c.why = fmt::format("no face mill or flat end mill has a cutting length of {:g} mm", step);
  }
  return c;
}

ToolChoice engraver(const std::vector<Tool>& tools, double depth) {
  ToolChoice c;
  c.tool = best_of(tools, ToolType::Engraver, depth,
                   [](const Tool& a, const Tool& b) { return a.diameter < b.diameter; });
  c.why = c.tool != nullptr
              ? fmt::format("T{}: the smallest engraver with a cutting length of {:g} mm or more",
                            c.tool->number, depth)
              : fmt::format("the library has no engraver with a cutting length of {:g} mm", depth);
  return c;
}

ToolChoice spot_drill(const std::vector<Tool>& tools, double diameter, double depth) {
  ToolChoice c;
  for (const Tool& t : tools) {
    if (t.type == ToolType::Spot && t.diameter >= diameter - 0.005 && t.cutting_length >= depth &&
        (c.tool == nullptr || t.diameter < c.tool->diameter))
      c.tool = &t;
  }
  c.why = c.tool != nullptr
              ? fmt::format("T{}: the smallest spot drill of D{:g} or more reaching {:g} mm",
                            c.tool->number, diameter, depth)
              : fmt::format("no spot drill of D{:g} or more reaches {:g} mm", diameter, depth);
  return c;
}

ToolChoice tap_for(const std::vector<Tool>& tools, double diameter, double depth) {
  ToolChoice c;
  for (const Tool& t : tools) {
    if (t.type != ToolType::Tap || t.pitch <= 0 || std::abs(t.diameter - t.pitch - diameter) > 0.1)
      continue;
    if (t.cutting_length >= depth) {
      c.tool = &t;
      c.why = fmt::format("T{}: the M{:g} x {:g} tap, whose tap drill is D{:g}", t.number,
                          t.diameter, t.pitch, diameter);
      return c;
    }
    c.why = fmt::format("the M{:g} tap T{} cuts {:g} mm deep at most; the holes need {:g}",
                        t.diameter, t.number, t.cutting_length, depth);
  }
  if (c.why.empty())
    c.why = fmt::format(
        "no tap with its pitch in the library has D{:g} as its tap drill (nominal "
        "diameter less pitch, within 0.1 mm)",
        diameter);
  return c;
}

ChamferCut chamfer_cut(const Tool& tool, double width, double tip_offset) {
  const double tan_a = std::tan(tool.angle / 2 * std::numbers::pi / 180);
  ChamferCut c;
  c.depth = width / tan_a + tip_offset;
  c.offset = tool.tip_diameter / 2 + tip_offset * tan_a;
  return c;
}

double chamfer_reach(const Tool& tool, double tip_offset) {
  const double tan_a = std::tan(tool.angle / 2 * std::numbers::pi / 180);
  const double rt = tool.tip_diameter / 2;
  const double top = std::min(tool.diameter / 2, rt + tool.cutting_length * tan_a);
  return top - rt - tip_offset * tan_a;
}

ToolChoice chamfer_mill(const std::vector<Tool>& tools, double width, double tip_offset) {
  ToolChoice c;
  const Tool* widest = nullptr;  // the one that comes nearest, to say why none fits
  for (const Tool& t : tools) {
    if (t.type != ToolType::Chamfer) continue;
    const double reach = chamfer_reach(t, tip_offset);
    if (widest == nullptr || reach > chamfer_reach(*widest, tip_offset)) widest = &t;
    if (reach >= width - 1e-9 && (c.tool == nullptr || t.diameter < c.tool->diameter)) c.tool = &t;
  }
  if (c.tool != nullptr) {
    c.why = fmt::format("T{}: the smallest chamfer mill whose edge reaches a {:g} mm chamfer",
                        c.tool->number, width);
  } else if (widest == nullptr) {
    c.why = "the library has no chamfer mill";
  } else {
    c.why = fmt::format(
        "no chamfer mill's edge reaches a {:g} mm chamfer with a tip offset of {:g} mm: the "
        "widest, T{}, makes {:.3g} mm",
        width, tip_offset, widest->number, chamfer_reach(*widest, tip_offset));
  }
  return c;
}

bool bores(const Tool& tool, double diameter) {
  if (tool.type != ToolType::Bore) return false;
  if (tool.max_bore <= 0) return std::abs(tool.diameter - diameter) <= 0.005;
  return diameter >= tool.diameter - 0.005 && diameter <= tool.max_bore + 0.005;
}

namespace {

std::string bore_size(const Tool& t) {
  return t.max_bore > 0 ? fmt::format("D{:g}-{:g}", t.diameter, t.max_bore)
                        : fmt::format("D{:g}", t.diameter);
}

// A set bar before any head; among heads, the largest smallest bore.
bool better_bore(const Tool& a, const Tool& b) {
  if ((a.max_bore <= 0) != (b.max_bore <= 0)) return a.max_bore <= 0;
  return a.diameter > b.diameter;
}

}  // namespace

ToolChoice boring_tool(const std::vector<Tool>& tools, double diameter, double depth,
                       double pilot) {
  ToolChoice c;
  const Tool* refused = nullptr;  // one that bores the size but is refused, to say why
  for (const Tool& t : tools) {
    if (!bores(t, diameter)) continue;
    const bool enters = pilot <= 0 || t.max_bore <= 0 || t.diameter <= pilot + 0.005;
    if (t.cutting_length >= depth && enters) {
      if (c.tool == nullptr || better_bore(t, *c.tool)) c.tool = &t;
    } else {
      refused = &t;
    }
  }
  if (c.tool != nullptr) {
    c.why = fmt::format("T{}: {} {} for a D{:g} bore {:g} mm deep{}", c.tool->number,
                        c.tool->max_bore > 0 ? "the boring head" : "the boring bar",
                        bore_size(*c.tool), diameter, depth,
                        c.tool->max_bore > 0 && pilot > 0
                            ? fmt::format(" whose bar enters the D{:g} pilot hole", pilot)
                            : std::string());
  } else if (refused != nullptr) {
    c.why = refused->cutting_length < depth
                ? fmt::format(
                      "the boring tool T{} ({}) cuts {:g} mm deep at most; the bore is "
                      "{:g} mm deep",
                      refused->number, bore_size(*refused), refused->cutting_length, depth)
                : fmt::format(
                      "the boring head T{} ({}) has a bar for holes of D{:g} or more: it "
                      "does not enter the D{:g} pilot hole",
                      refused->number, bore_size(*refused), refused->diameter, pilot);
  } else {
    c.why = fmt::format(
        "the library has no boring tool for D{:g} (a bar set to it, or a head "
        "whose diameter_range holds it)",
        diameter);
  }
  return c;
}

ToolChoice drill_of(const std::vector<Tool>& tools, double diameter, double depth) {
  ToolChoice c;
  const Tool* too_short = nullptr;
  for (const Tool& t : tools) {
    if (t.type != ToolType::Drill || std::abs(t.diameter - diameter) > 0.005) continue;
    if (t.cutting_length >= depth) {
      c.tool = &t;
      c.why =
          fmt::format("T{}: a {:g} mm drill whose flutes reach {:g} mm", t.number, diameter, depth);
      return c;
    }
    too_short = &t;
  }
  c.why = too_short != nullptr
              ? fmt::format(
                    "the {:g} mm drill T{} cuts {:g} mm deep at most; the holes are "
                    "{:g} mm deep",
                    diameter, too_short->number, too_short->cutting_length, depth)
              : fmt::format("the library has no {:g} mm drill", diameter);
  return c;
}

}  // namespace usina::job
