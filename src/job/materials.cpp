#include "job/materials.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "job/toml_reader.hpp"

namespace usina::job {
namespace {

constexpr std::string_view kMaterialKeys[] = {"name", "description", "cutting"};
constexpr std::string_view kRowKeys[] = {"tool", "cut", "vc", "fz", "fn", "source"};
constexpr Range kVc{1, 5000, "m/min"};

// fz = [[D, f], ...]: points of increasing diameter, positive feeds.
bool read_feeds(TomlReader& r, const toml::node& n, const std::string& what, CuttingRow& row) {
  const toml::array* a = n.as_array();
  bool ok = a != nullptr && !a->empty();
  double last = -1;
  for (std::size_t i = 0; ok && i < a->size(); ++i) {
    const toml::array* p = a->get(i)->as_array();
    const auto d = p && p->size() == 2 ? p->get(0)->value<double>() : std::nullopt;
    const auto f = p && p->size() == 2 ? p->get(1)->value<double>() : std::nullopt;
    ok = d && f && std::isfinite(*d) && std::isfinite(*f) && *d > last && *f >= 0 && *f < 10;
    if (ok) row.feed.emplace_back(*d, *f);
    last = d.value_or(last);
  }
  if (!ok) {
    r.fail(n.source(),
           fmt::format("{}: the feed is [[diameter, feed], ...] in mm, diameters "
                       "increasing, feeds from 0 (no data from there on) to below 10 mm",
                       what));
  }
  return ok;
}

std::optional<CuttingRow> read_row(TomlReader& r, const toml::table& t, const std::string& name) {
  const std::string what = fmt::format("material {}'s [[material.cutting]]", name);
  r.known_keys(t, what, kRowKeys);
  CuttingRow row;
  const auto tool = r.text(t, what, "tool", true);
  const auto cut = r.text(t, what, "cut", true);
  const auto vc = r.number(t, what, "vc", kVc, true);
  const auto source = r.text(t, what, "source", true);
  if (cut && *cut != "mill" && *cut != "drill" && *cut != "bore") {
    r.fail(t.get("cut")->source(),
           fmt::format("{}: cut must be \"mill\", \"drill\" or \"bore\"", what));
    return std::nullopt;
  }
  // Drills and boring bars feed per revolution, mills per tooth.
  const bool per_rev = cut && *cut != "mill";
  const char* feed_key = per_rev ? "fn" : "fz";
  const toml::node* feed = t.get(feed_key);
  if (feed == nullptr) {
    r.fail(t.source(),
           fmt::format("{}: a {} row needs {} (feed per {})", what, cut.value_or("mill"), feed_key,
                       per_rev ? "revolution" : "tooth"));
    return std::nullopt;
  }
  // The other feed would be silently unread.
  if (const toml::node* other = t.get(per_rev ? "fz" : "fn")) {
    r.fail(other->source(), fmt::format("{}: a {} row's feed is {}, not {}", what,
                                        cut.value_or("mill"), feed_key, per_rev ? "fz" : "fn"));
    return std::nullopt;
  }
  if (!tool || !cut || !vc || !source || !read_feeds(r, *feed, what, row)) return std::nullopt;
  row.tool_material = *tool;
  row.cut = *cut == "drill" ? CutKind::Drill : *cut == "bore" ? CutKind::Bore : CutKind::Mill;
  row.vc = *vc;
  row.source = *source;
  return row;
}

std::optional<Material> read_material(TomlReader& r, const toml::table& t) {
  r.known_keys(t, "[[material]]", kMaterialKeys);
  Material m;
  const auto name = r.text(t, "[[material]]", "name", true);
  if (!name) return std::nullopt;
  m.name = *name;
  m.description = r.text(t, m.name, "description", false).value_or("");
  const toml::node* rows = t.get("cutting");
  if (rows == nullptr || !rows->is_array_of_tables()) {
    r.fail(t.source(), fmt::format("material {} needs [[material.cutting]] rows", m.name));
    return std::nullopt;
  }
  for (const toml::node& e : *rows->as_array()) {
    if (auto row = read_row(r, *e.as_table(), m.name)) m.rows.push_back(std::move(*row));
  }
  return m;
}

double feed_at(const CuttingRow& row, double diameter) {
  double f = 0;
  for (const auto& [d, v] : row.feed) {
    if (d <= diameter + 1e-9) f = v;
  }
  return f;
}

}  // namespace

std::optional<std::vector<Material>> read_materials(std::string_view toml_text, std::uint32_t file,
                                                    core::DiagnosticSink& diags) {
  TomlReader r(toml_text, file, core::Code::BadMaterials, diags);
  const auto root = r.parse();
  if (!root) return std::nullopt;
  const toml::array* list = r.entries(*root, "material", "the materials file");
  if (list == nullptr) return std::nullopt;
  std::vector<Material> ms;
  for (const toml::node& e : *list) {
    if (auto m = read_material(r, *e.as_table())) ms.push_back(std::move(*m));
  }
  if (!r.ok()) return std::nullopt;
  return ms;
}

const Material* find_material(const std::vector<Material>& ms, std::string_view name) {
  const auto it =
      std::find_if(ms.begin(), ms.end(), [&](const Material& m) { return m.name == name; });
  return it == ms.end() ? nullptr : &*it;
}

const CuttingRow* cutting_row(const Material& m, const Tool& t, CutKind cut) {
  const auto find = [&](std::string_view tool_material) -> const CuttingRow* {
    for (const CuttingRow& r : m.rows) {
      if (r.cut == cut && r.tool_material == tool_material) return &r;
    }
    return nullptr;
  };
  const CuttingRow* row = find(tool_material_name(t.material));
  if (row == nullptr && t.material == ToolMaterial::Coated) row = find("carbide");
  return row;
}

std::optional<CuttingConditions> cutting_conditions(const CuttingRow& row, const Tool& tool,
                                                    bool slotting, const MachineLimits& limits) {
  const double f = feed_at(row, tool.diameter);
  if (f <= 0) return std::nullopt;
  CuttingConditions c;
  const bool drill = row.cut != CutKind::Mill;  // a drill's or a boring bar's feed a revolution
  const double vc = slotting ? row.vc * 0.8 : row.vc;
  c.rpm = vc * 1000.0 / (std::numbers::pi * tool.diameter);
  c.why.push_back(fmt::format(
      "n = vc*1000/[pi*D] = {:g}*1000/[pi*{:g}] = {:.0f} rev/min{}", vc, tool.diameter, c.rpm,
      slotting ? fmt::format(", vc {:g} less 20 % for slotting", row.vc) : std::string()));
  if (limits.max_rpm > 0 && c.rpm > limits.max_rpm) {
    c.why.push_back(fmt::format("the spindle's max_rpm {:g} caps n", limits.max_rpm));
    c.rpm = limits.max_rpm;
    c.limited = true;
  }
  // A drill's feed is per revolution; a mill's per tooth, times its teeth.
  const double per_rev = drill ? f : f * tool.flutes;
  c.feed = per_rev * c.rpm;
  c.why.push_back(drill ? fmt::format("vf = fn*n = {:g}*{:.0f} = {:.0f} mm/min", f, c.rpm, c.feed)
                        : fmt::format("vf = fz*z*n = {:g}*{}*{:.0f} = {:.0f} mm/min", f,
                                      tool.flutes, c.rpm, c.feed));
  if (limits.max_feed > 0 && c.feed > limits.max_feed) {
    c.why.push_back(fmt::format("the axes' max_feed {:g} caps vf", limits.max_feed));
    c.feed = limits.max_feed;
    c.limited = true;
  }
  // Drills and boring bars feed along Z at vf; an end mill goes in at half
  // its feed (the job's rule, docs/job.md).
  c.plunge_feed = drill ? c.feed : c.feed / 2;
  c.why.push_back(fmt::format("vc {:g} m/min, f {:g} mm: {}", row.vc, f, row.source));
  return c;
}

}  // namespace usina::job
