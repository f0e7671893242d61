#include "job/job_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <span>

#include <fmt/format.h>

#include "cam/drill.hpp"
#include "cam/profile.hpp"
#include "job/toml_reader.hpp"

namespace usina::job {
namespace {

constexpr Range kDepth{0.001, 1000, "mm"};
constexpr Range kSmall{0.001, 1000, "mm"};
constexpr Range kZeroUp{0, 1000, "mm"};
constexpr Range kCoord{-1e5, 1e5, "mm"};
constexpr Range kSize{0.001, 1e5, "mm"};
constexpr Range kTool{1, 9999, ""};
constexpr Range kRpm{1, 1e6, "rev/min"};
constexpr Range kFeed{0.001, 1e6, "mm/min"};
constexpr Range kTabs{0, 100, "tabs"};
constexpr Range kDwell{0.001, cam::kMaxBoreDwell, "s"};

constexpr std::string_view kTop[] = {"job", "stock", "operation"};
constexpr std::string_view kJobKeys[] = {"name",    "machine", "tools",      "materials",
                                         "drawing", "safe_z",  "setup_note", "tool_table_units"};
constexpr std::string_view kStockKeys[] = {"shape",  "size",     "diameter",
                                           "height", "material", "origin"};
// The keys every operation has, then each type's own.
#define USINA_JOB_COMMON "type", "tool", "depth", "rpm", "feed", "plunge_feed"
constexpr std::string_view kDrillKeys[] = {USINA_JOB_COMMON, "layer", "diameter", "peck",
                                           "retract"};
constexpr std::string_view kSpotKeys[] = {USINA_JOB_COMMON, "layer", "diameter", "retract"};
constexpr std::string_view kBoreKeys[] = {USINA_JOB_COMMON, "layer", "diameter", "retract",
                                          "predrilled",     "cycle", "dwell"};
constexpr std::string_view kPocketKeys[] = {USINA_JOB_COMMON, "layer", "step_down", "stepover"};
constexpr std::string_view kProfileKeys[] = {USINA_JOB_COMMON, "layer", "step_down", "side",
                                             "lead_radius",    "tabs",  "tab_width", "tab_height"};
constexpr std::string_view kEllipseKeys[] = {USINA_JOB_COMMON, "center",  "rx", "ry",
                                             "step_down",      "stepover"};
constexpr std::string_view kFaceKeys[] = {USINA_JOB_COMMON, "step_down", "stepover"};
constexpr std::string_view kEngraveKeys[] = {USINA_JOB_COMMON, "text", "font", "height", "at"};
// `depth` is read to be refused with the reason (read_chamfer_keys).
constexpr std::string_view kChamferKeys[] = {USINA_JOB_COMMON, "layer", "side", "width",
                                             "tip_offset"};
#undef USINA_JOB_COMMON

struct TypeName {
  OpType type;
  const char* name;
  std::span<const std::string_view> keys;
};

constexpr TypeName kTypes[] = {
    {OpType::Drill, "drill", kDrillKeys},
    {OpType::Spot, "spot", kSpotKeys},
    {OpType::Tap, "tap", kSpotKeys},
    {OpType::Bore, "bore", kBoreKeys},
    {OpType::Pocket, "pocket", kPocketKeys},
    {OpType::Profile, "profile", kProfileKeys},
    {OpType::EllipsePocket, "ellipse_pocket", kEllipseKeys},
    {OpType::Face, "face", kFaceKeys},
    {OpType::Engrave, "engrave", kEngraveKeys},
    {OpType::Chamfer, "chamfer", kChamferKeys},
};

std::string relative_to(const std::string& folder, const std::string& path) {
  if (path.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(folder) / path).lexically_normal().string();
}

// A LinuxCNC tool table's lengths are in its machine's units and the file
// does not say which (LinuxCNC docs, "Tool Table Format"): the job says it,
// for a table and only for one.
void read_tool_table_units(TomlReader& r, const toml::table& t, Job& job) {
  const bool table = job.tools.ends_with(".tbl");
  const auto units = r.text(t, "[job]", "tool_table_units", false);
  const toml::node* n = t.get("tool_table_units");
  if (n != nullptr) job.tool_table_units_loc = r.loc(n->source());
  if (units && !table) {
    r.fail(n->source(),
           "[job] tool_table_units is for a LinuxCNC tool table (tools = "
           "\"FILE.tbl\"); a TOML library's lengths are in mm");
  } else if (units && *units != "mm" && *units != "inch") {
    r.fail(n->source(),
           fmt::format("[job] tool_table_units = \"{}\": give \"mm\" or \"inch\"", *units));
  } else if (table && !units && n == nullptr) {
    r.fail(t.get("tools")->source(),
           "[job] tools is a LinuxCNC tool table, whose lengths are in its machine's units: give "
           "tool_table_units = \"mm\" or \"inch\"");
  } else if (units) {
    job.tool_table_mm = *units == "inch" ? 25.4 : 1.0;
  }
}

void read_header(TomlReader& r, const toml::table& root, const std::string& folder, Job& job) {
  const toml::table* section = r.section(root, "job", "the job");
  if (section == nullptr) return;
  const toml::table& t = *section;
  r.known_keys(t, "[job]", kJobKeys);
  job.name = r.text(t, "[job]", "name", false).value_or("");
  const auto path = [&](const char* key, bool required, core::SourceLoc& loc) {
    if (const toml::node* k = t.get(key)) loc = r.loc(k->source());
    return relative_to(folder, r.text(t, "[job]", key, required).value_or(""));
  };
  job.machine = path("machine", false, job.machine_loc);
  job.tools = path("tools", true, job.tools_loc);
  job.materials = path("materials", true, job.materials_loc);
  job.drawing = path("drawing", false, job.drawing_loc);
  job.safe_z = r.number(t, "[job]", "safe_z", kSmall, false).value_or(5.0);
  job.setup_note = r.text(t, "[job]", "setup_note", false).value_or("");
  read_tool_table_units(r, t, job);
}

void read_stock(TomlReader& r, const toml::table& root, Stock& s) {
  const toml::table* section = r.section(root, "stock", "the job");
  if (section == nullptr) return;
  const toml::table& t = *section;
  r.known_keys(t, "[stock]", kStockKeys);
  s.shape = r.text(t, "[stock]", "shape", true).value_or("box");
  // The other shape's keys would be silently unread.
  for (const char* key : {"size", "diameter", "height"}) {
    const bool box_key = std::string_view(key) == "size";
    if (t.get(key) != nullptr && (s.shape == "box") != box_key) {
      r.fail(t.get(key)->source(),
             fmt::format("[stock] {} is not a {}'s: a box has size = [x, y, z], a cylinder "
                         "diameter and height",
                         key, s.shape));
    }
  }
  if (s.shape == "box") {
    const auto size = r.numbers(t, "[stock]", "size", 3, kSize, true);
    if (size) s.size = {(*size)[0], (*size)[1], (*size)[2]};
  } else if (s.shape == "cylinder") {
    s.size[0] = r.number(t, "[stock]", "diameter", kSize, true).value_or(0);
    s.size[1] = r.number(t, "[stock]", "height", kSize, true).value_or(0);
  } else {
    r.fail(t.get("shape")->source(),
           fmt::format("[stock] shape = \"{}\": give \"box\" or \"cylinder\"", s.shape));
  }
  if (const auto o = r.numbers(t, "[stock]", "origin", 2, kCoord, false)) {
    s.origin = {(*o)[0], (*o)[1]};
  }
  s.material = r.text(t, "[stock]", "material", true).value_or("");
  if (const toml::node* m = t.get("material")) s.material_loc = r.loc(m->source());
}

// tool = N or "auto".
void read_tool(TomlReader& r, const toml::table& t, const std::string& what, Operation& op) {
  const toml::node* n = t.get("tool");
  if (n == nullptr) {
    r.fail(t.source(), fmt::format("{} needs the key 'tool' (a number, or \"auto\")", what));
    return;
  }
  op.tool_loc = r.loc(n->source());
  if (n->is_string() && n->value_or<std::string>("") == "auto") return;
  if (const auto v = r.number(t, what, "tool", kTool, true); v && *v == std::floor(*v)) {
    op.tool = static_cast<int>(*v);
  } else if (v) {
    r.fail(n->source(), fmt::format("{} tool = {:g}: give a whole number or \"auto\"", what, *v));
  }
}

void read_engrave_keys(TomlReader& r, const toml::table& t, const std::string& w, Operation& op) {
  op.text = r.text(t, w, "text", true).value_or("");
  if (const toml::node* n = t.get("text"); n != nullptr && op.text.empty())
    r.fail(n->source(), fmt::format("{} text is empty: there is nothing to engrave", w));
  op.font = r.text(t, w, "font", false).value_or("rowmans");
  op.height = r.number(t, w, "height", kSmall, false).value_or(5.0);
  if (const auto a = r.numbers(t, w, "at", 2, kCoord, true)) op.at = {(*a)[0], (*a)[1]};
  if (const toml::node* n = t.get("at")) op.place_loc = r.loc(n->source());
}

// A chamfer's depth is not the author's: the tip goes where the width, the
// tool's angle and the tip offset put it (job/tools.hpp, chamfer_cut). The
// side "on" would cut a V-groove along the line, not a chamfer.
void read_chamfer_keys(TomlReader& r, const toml::table& t, const std::string& w, Operation& op) {
  op.width = r.number(t, w, "width", kSmall, true).value_or(0);
  if (const toml::node* n = t.get("width")) op.width_loc = r.loc(n->source());
  op.tip_offset = r.number(t, w, "tip_offset", kZeroUp, false).value_or(0.5);
  if (const toml::node* n = t.get("depth")) {
    r.fail(n->source(), fmt::format("{} gives depth: a chamfer's depth follows from its width, "
                                    "the tool's angle and tip_offset; give width",
                                    w));
  }
  if (op.side == "on") {
    r.fail(t.get("side")->source(),
           fmt::format("{} side = \"on\" would cut a groove along the line, not a chamfer: give "
                       "outside, inside, left, right or auto",
                       w));
  }
}

// A bore's cycle (G85 unless given) and G89's dwell, which only it has.
void read_bore_keys(TomlReader& r, const toml::table& t, const std::string& w, Operation& op) {
  const auto cycle = r.text(t, w, "cycle", false);
  const toml::node* c = t.get("cycle");
  if (cycle == "G89") {
    op.bore_cycle = BoreCycle::DwellFeedOut;
  } else if (cycle == "G86") {
    op.bore_cycle = BoreCycle::StopRapidOut;
  } else if (cycle && *cycle != "G85") {
    r.fail(c->source(),
           fmt::format("{} cycle = \"{}\": give \"G85\" (fed out, the default), \"G89\" (a dwell "
                       "at the bottom, then fed out) or \"G86\" (the spindle stopped at the "
                       "bottom, out at rapid)",
                       w, *cycle));
  }
  op.dwell = r.number(t, w, "dwell", kDwell, false).value_or(0.0);
  const toml::node* d = t.get("dwell");
  if (op.bore_cycle == BoreCycle::DwellFeedOut && d == nullptr) {
    r.fail(c->source(), fmt::format("{} cycle = \"G89\" dwells at the bottom: give dwell = the "
                                    "seconds (e.g. 0.5)",
                                    w));
  } else if (op.bore_cycle != BoreCycle::DwellFeedOut && d != nullptr) {
    r.fail(d->source(), fmt::format("{} gives dwell: only G89 dwells at the bottom; give cycle = "
                                    "\"G89\" or no dwell",
                                    w));
  }
}

void read_type_keys(TomlReader& r, const toml::table& t, const std::string& w, Operation& op) {
  const bool layered = op.type == OpType::Drill || op.type == OpType::Spot ||
                       op.type == OpType::Tap || op.type == OpType::Bore ||
                       op.type == OpType::Pocket || op.type == OpType::Profile ||
                       op.type == OpType::Chamfer;
  if (layered) {
    op.layer = r.text(t, w, "layer", true).value_or("");
    if (const toml::node* l = t.get("layer")) op.layer_loc = r.loc(l->source());
  }
  op.step_down = r.number(t, w, "step_down", kSmall, false);
  op.stepover = r.number(t, w, "stepover", kSmall, false);
  op.diameter = r.number(t, w, "diameter", kSmall, false);
  op.peck = r.number(t, w, "peck", kZeroUp, false).value_or(0.0);
  op.retract = r.number(t, w, "retract", kSmall, false).value_or(1.0);
  op.predrilled = r.flag(t, w, "predrilled").value_or(false);
  op.side = r.text(t, w, "side", false).value_or("outside");
  op.lead_radius = r.number(t, w, "lead_radius", kZeroUp, false).value_or(0.0);
  op.tabs = static_cast<int>(r.number(t, w, "tabs", kTabs, false).value_or(0.0));
  op.tab_width = r.number(t, w, "tab_width", kSmall, false).value_or(3.0);
  op.tab_height = r.number(t, w, "tab_height", kSmall, false).value_or(1.0);
  if (op.type == OpType::EllipsePocket) {
    const auto c = r.numbers(t, w, "center", 2, kCoord, true);
    if (c) op.center = {(*c)[0], (*c)[1]};
    if (const toml::node* n = t.get("center")) op.place_loc = r.loc(n->source());
    op.rx = r.number(t, w, "rx", kSize, true).value_or(0);
    op.ry = r.number(t, w, "ry", kSize, true).value_or(0);
  }
  if (op.type == OpType::Engrave) read_engrave_keys(r, t, w, op);
  if (op.type == OpType::Chamfer) read_chamfer_keys(r, t, w, op);
  if (op.type == OpType::Bore) read_bore_keys(r, t, w, op);
  if (!cam::profile_side(op.side)) {
    r.fail(
        t.get("side")->source(),
        fmt::format("{} side = \"{}\": give outside, inside, left, right, on or auto", w, op.side));
  }
}

void read_operation(TomlReader& r, const toml::table& t, std::size_t index, Job& job) {
  Operation op;
  op.loc = r.loc(t.source());
  std::string what = fmt::format("operation {}", index + 1);
  const auto type = r.text(t, what, "type", true);
  if (!type) return;
  const TypeName* found = nullptr;
  for (const TypeName& tn : kTypes) {
    if (*type == tn.name) found = &tn;
  }
  if (found == nullptr) {
    r.fail(core::Code::JobUnknownOperation, t.get("type")->source(),
           fmt::format("{}: type \"{}\" is not an operation usina makes: give drill, spot, "
                       "tap, bore, pocket, profile, ellipse_pocket, face, engrave or chamfer",
                       what, *type));
    return;
  }
  op.type = found->type;
  what = fmt::format("operation {} ({})", index + 1, found->name);
  r.known_keys(t, what, found->keys);
  read_tool(r, t, what, op);
  if (op.type != OpType::Chamfer) op.depth = r.number(t, what, "depth", kDepth, true).value_or(0);
  if (const toml::node* n = t.get("depth")) op.depth_loc = r.loc(n->source());
  op.rpm = r.number(t, what, "rpm", kRpm, false);
  op.feed = r.number(t, what, "feed", kFeed, false);
  op.plunge_feed = r.number(t, what, "plunge_feed", kFeed, false);
  // A tap's feed is its pitch a revolution, and no table has tapping speeds.
  if (op.type == OpType::Tap) {
    if (!op.rpm)
      r.fail(t.source(), fmt::format("{} needs rpm: the tables have no tapping speeds", what));
    if (op.feed)
      r.fail(t.get("feed")->source(),
             fmt::format("{} gives feed: a tap feeds its pitch a revolution (feed = pitch x rpm)",
                         what));
  } else if (op.rpm.has_value() != op.feed.has_value()) {
    // One without the other would mix the job's figure with the data's.
    const char* given = op.rpm ? "rpm" : "feed";
    r.fail(t.get(given)->source(),
           fmt::format("{} gives {} alone: give both rpm and feed, or neither (the cutting "
                       "data then set them)",
                       what, given));
  }
  read_type_keys(r, t, what, op);
  job.operations.push_back(std::move(op));
}

}  // namespace

std::string_view op_type_name(OpType t) {
  for (const TypeName& tn : kTypes) {
    if (tn.type == t) return tn.name;
  }
  return "?";
}

std::optional<Job> read_job(std::string_view toml_text, std::uint32_t file,
                            const std::string& folder, core::DiagnosticSink& diags) {
  TomlReader r(toml_text, file, core::Code::BadJob, diags);
  const auto root = r.parse();
  if (!root) return std::nullopt;
  r.known_keys(*root, "the job", kTop);
  Job job;
  read_header(r, *root, folder, job);
  read_stock(r, *root, job.stock);
  const toml::node* ops = root->get("operation");
  if (ops == nullptr || !ops->is_array_of_tables() || ops->as_array()->empty()) {
    r.fail(ops != nullptr ? ops->source() : root->source(),
           "the job needs its operations: [[operation]] entries, in the order they are cut");
    return std::nullopt;
  }
  const toml::array& list = *ops->as_array();
  for (std::size_t i = 0; i < list.size(); ++i)
    read_operation(r, *list.get(i)->as_table(), i, job);
  if (!r.ok()) return std::nullopt;
  return job;
}

}  // namespace usina::job
