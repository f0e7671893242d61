#include "sim/machine_profile.hpp"

#include <algorithm>
#include <cmath>
#include <span>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "core/units.hpp"
#include "sim/profile_keys.hpp"

namespace usina::sim {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z", "a", "b", "c"};

// The values a key may take, in the file's units ({L}: mm or inch; a rotary
// axis's lengths are degrees). Wide enough for any real machine, narrow
// enough that no time computed from them is absurd (docs/stats.md, "Profile
// keys"). `zero_too` admits 0 below `min` (0 meaning "none").
struct KeyRange {
  double min;
  double max;
  const char* unit;
  bool zero_too = false;
};

constexpr KeyRange kTravel{-1e6, 1e6, "{L}"};
constexpr KeyRange kRate{1.0, 1e6, "{L}/min"};
constexpr KeyRange kAccel{1.0, 1e6, "{L}/s²"};
constexpr KeyRange kJerk{1.0, 1e9, "{L}/s³", true};
constexpr KeyRange kRpm{1.0, 1e6, "rev/min"};
constexpr KeyRange kSpindleTime{0.0, 3600.0, "s"};
constexpr KeyRange kToolChange{0.0, 86400.0, "s"};
constexpr KeyRange kBlockTime{0.0, 60.0, "s"};
constexpr KeyRange kCost{0.0, 1e9, "an hour"};
constexpr KeyRange kDeviation{0.0, 10.0, "{L}"};
constexpr KeyRange kServoPeriod{1e-5, 0.1, "s"};
constexpr KeyRange kPathRate{1.0, 1e6, "{L}/min", true};
constexpr KeyRange kKinkRatio{0.0, 0.9, ""};
constexpr KeyRange kGapCycles{0.0, 1000.0, "cycles"};
constexpr KeyRange kFeedScale{0.1, 10.0, ""};
constexpr KeyRange kDepth{2.0, 10000.0, "segments"};
constexpr KeyRange kArcTolerance{0.0001, 1.0, "{L}"};

std::string unit_text(const char* unit, std::string_view length) {
  std::string u = unit;
  if (const auto at = u.find("{L}"); at != std::string::npos) u.replace(at, 3, length);
  return u;
}

class Reader {
 public:
  Reader(std::uint32_t file, core::DiagnosticSink& diags) : file_(file), diags_(diags) {}

  void report(core::Code code, core::Severity severity, const toml::source_region& where,
              std::string message) {
    core::SourceLoc loc{file_, static_cast<std::uint32_t>(where.begin.line),
                        static_cast<std::uint32_t>(where.begin.column), 1, 0};
    diags_.report({code, severity, loc, std::move(message)});
  }

  void fail(const toml::source_region& where, std::string message) {
    ok_ = false;
    report(core::Code::BadMachineProfile, core::Severity::Error, where, std::move(message));
  }

  // The number at `key` of section `t`, within `range`, required or with a
  // default (a missing key is not checked).
  double number(const toml::table& t, const std::string& section, const char* key,
                std::optional<double> fallback, const KeyRange& range) {
    const toml::node* n = t.get(key);
    if (n == nullptr) {
      if (!fallback) fail(t.source(), fmt::format("[{}] needs the key '{}'", section, key));
      return fallback.value_or(0.0);
    }
    auto v = n->value<double>();
    if (!v || !std::isfinite(*v)) {
      fail(n->source(), fmt::format("[{}] {} must be a number", section, key));
      return 0.0;
    }
    const bool in = (*v >= range.min && *v <= range.max) || (range.zero_too && *v == 0.0);
    if (!in) {
      const std::string unit = unit_text(range.unit, length_unit_);
      fail(n->source(),
           fmt::format("[{}] {} = {:g} is out of range: give {}from {:g} to {:g} {}", section, key,
                       *v, range.zero_too ? "0 or a number " : "", range.min, range.max, unit));
    }
    return *v;
  }

  // number(), for a count: 2.5 segments was taken for 2.
  double whole_number(const toml::table& t, const std::string& section, const char* key,
                      double fallback, const KeyRange& range) {
    const double v = number(t, section, key, fallback, range);
    if (v != std::floor(v)) {
      fail(t.get(key)->source(),
           fmt::format("[{}] {} = {:g} must be a whole number", section, key, v));
      return fallback;
    }
    return v;
  }

  const toml::table* section(const toml::table& root, const char* name, bool required) {
    const toml::node* n = root.get(name);
    if (n == nullptr) {
      if (required) fail(root.source(), fmt::format("the profile needs a [{}] section", name));
      return nullptr;
    }
    if (!n->is_table()) {
      fail(n->source(), fmt::format("{} must be a section ([{}])", name, name));
      return nullptr;
    }
    return n->as_table();
  }

  // A warning for each key of `t` usina does not read, with the nearest
  // valid one; nested sections are walked.
  void unknown_keys(const toml::table& t, const std::string& section) {
    const auto keys = profile_keys(section);
    for (auto&& [key, node] : t) {
      const std::string_view name = key.str();
      if (std::find(keys.begin(), keys.end(), name) == keys.end()) {
        unknown_key(key, section, keys);
        continue;
      }
      // The top level and [axes] hold sections; the others hold values.
      const toml::table* sub = node.as_table();
      if (sub != nullptr && (section.empty() || section == "axes")) {
        unknown_keys(*sub, section.empty() ? std::string(name) : section + "." + std::string(name));
      }
    }
  }

  void set_length_unit(std::string_view unit) { length_unit_ = unit; }

  bool ok() const { return ok_; }

 private:
  void unknown_key(const toml::key& key, const std::string& section,
                   std::span<const std::string_view> keys) {
    const std::string_view name = key.str();
    const std::string where =
        section.empty() ? "at the top of the profile" : fmt::format("in [{}]", section);
    const std::string_view near = nearest_key(name, keys);
    std::string known;
    for (const std::string_view k : keys)
      known += fmt::format("{}{}", known.empty() ? "" : ", ", k);
    const std::string hint = near.empty() ? fmt::format("the keys here are {}", known)
                                          : fmt::format("did you mean `{}`?", near);
    report(core::Code::UnknownProfileKey, core::Severity::Warning, key.source(),
           fmt::format("unknown key `{}` {} is not read; {}", name, where, hint));
  }

  std::uint32_t file_;
  core::DiagnosticSink& diags_;
  std::string length_unit_ = "mm";
  bool ok_ = true;
};

void read_machine(Reader& r, const toml::table& root, MachineProfile& p) {
  const toml::table* m = r.section(root, "machine", true);
  if (m == nullptr) return;
  if (const toml::node* name = m->get("name")) {
    // A name that is no string was read as none.
    if (name->is_string()) {
      p.name = name->value_or<std::string>("");
    } else {
      r.fail(name->source(), "[machine] name must be a string, e.g. name = \"Mill 1\"");
    }
  }
  const toml::node* units = m->get("units");
  const std::string u = units != nullptr ? units->value_or<std::string>("") : "mm";
  if (units != nullptr && !units->is_string()) {
    r.fail(units->source(), "[machine] units must be the string \"mm\" or \"inch\"");
  } else if (u != "mm" && u != "inch") {
    r.fail(units != nullptr ? units->source() : m->source(),
           fmt::format("[machine] units = \"{}\": must be \"mm\" or \"inch\"", u));
  }
  p.file_in_inch = u == "inch";
  r.set_length_unit(p.file_in_inch ? "inch" : "mm");
}

void read_axis(Reader& r, const toml::table& axes, int i, MachineProfile& p) {
  const char* name = kAxisNames[i];
  const toml::node* n = axes.get(name);
  if (n == nullptr) {
    if (i < 3) r.fail(axes.source(), fmt::format("the profile needs [axes.{}]", name));
    return;
  }
  if (!n->is_table()) {
    r.fail(n->source(), fmt::format("axes.{} must be a section", name));
    return;
  }
  const toml::table& t = *n->as_table();
  const std::string section = fmt::format("axes.{}", name);
  // Linear axes scale with the file's units; rotary axes are in degrees.
  const double scale = (i < 3 && p.file_in_inch) ? core::kMmPerInch : 1.0;
  r.set_length_unit(i >= 3 ? "deg" : (p.file_in_inch ? "inch" : "mm"));
  AxisLimits& a = p.axes[static_cast<std::size_t>(i)];
  a.present = true;
  a.min = r.number(t, section, "min", std::nullopt, kTravel) * scale;
  a.max = r.number(t, section, "max", std::nullopt, kTravel) * scale;
  a.rapid = r.number(t, section, "rapid", std::nullopt, kRate) * scale;
  a.max_feed = r.number(t, section, "max_feed", std::nullopt, kRate) * scale;
  a.accel = r.number(t, section, "accel", std::nullopt, kAccel) * scale;
  a.jerk = r.number(t, section, "jerk", 0.0, kJerk) * scale;
  if (a.min > a.max) r.fail(t.source(), fmt::format("[{}] min is above max", section));
  r.set_length_unit(p.file_in_inch ? "inch" : "mm");
}

// [planner] model = "textbook" | "linuxcnc" | "grbl", and the models' settings.
void read_model(Reader& r, const toml::table& pl, MachineProfile& p) {
  const toml::node* n = pl.get("model");
  if (n == nullptr) return;
  const std::optional<std::string> name = n->value<std::string>();
  for (const PlannerModel m :
       {PlannerModel::Textbook, PlannerModel::Linuxcnc, PlannerModel::Grbl}) {
    if (name && *name == planner_model_name(m)) {
      p.model = m;
      return;
    }
  }
  r.fail(n->source(),
         fmt::format("[planner] model = {}: give \"textbook\" (the default), \"linuxcnc\" "
                     "(LinuxCNC 2.9's planner) or \"grbl\"",
                     name ? fmt::format("\"{}\"", *name) : std::string("a value that is no text")));
}

void read_planner(Reader& r, const toml::table& pl, MachineProfile& p) {
  const double scale = p.file_in_inch ? core::kMmPerInch : 1.0;
  p.junction_deviation =
      r.number(pl, "planner", "junction_deviation", 0.01 / scale, kDeviation) * scale;
  read_model(r, pl, p);
  p.arc_tolerance = r.number(pl, "planner", "arc_tolerance", 0.002 / scale, kArcTolerance) * scale;
  LinuxcncPlannerSettings& lc = p.linuxcnc;
  lc.servo_period = r.number(pl, "planner", "servo_period", lc.servo_period, kServoPeriod);
  lc.max_velocity = r.number(pl, "planner", "max_velocity", 0.0, kPathRate) * scale / 60.0;
  lc.kink_ratio = r.number(pl, "planner", "kink_ratio", lc.kink_ratio, kKinkRatio);
  lc.gap_cycles = r.number(pl, "planner", "gap_cycles", lc.gap_cycles, kGapCycles);
  lc.max_feed_scale = r.number(pl, "planner", "max_feed_scale", lc.max_feed_scale, kFeedScale);
  lc.optimization_depth = static_cast<std::size_t>(r.whole_number(
      pl, "planner", "optimization_depth", static_cast<double>(lc.optimization_depth), kDepth));
  if (const toml::node* b = pl.get("arc_blend")) {
    if (b->is_boolean()) {
      lc.arc_blend = b->value_or(true);
    } else {
      r.fail(b->source(), "[planner] arc_blend must be true or false");
    }
  }
}

// [spindle], [times], [cost], [planner]: optional, their keys too.
void read_optional(Reader& r, const toml::table& root, MachineProfile& p) {
  if (const toml::table* s = r.section(root, "spindle", false)) {
    // No max_rpm: a change of speed always takes accel_time (stats.cpp).
    p.spindle_max_rpm =
        s->get("max_rpm") != nullptr ? r.number(*s, "spindle", "max_rpm", std::nullopt, kRpm) : 0.0;
    p.spindle_accel_time = r.number(*s, "spindle", "accel_time", 0.0, kSpindleTime);
  }
  if (const toml::table* t = r.section(root, "times", false)) {
    p.tool_change_time = r.number(*t, "times", "tool_change", 0.0, kToolChange);
    p.block_time = r.number(*t, "times", "block", 0.0, kBlockTime);
  }
  if (const toml::table* c = r.section(root, "cost", false)) {
    p.cost_per_hour = r.number(*c, "cost", "per_hour", 0.0, kCost);
  }
  if (const toml::table* pl = r.section(root, "planner", false)) read_planner(r, *pl, p);
}

}  // namespace

const char* planner_model_name(PlannerModel m) {
  switch (m) {
  case PlannerModel::Textbook: return "textbook";
  case PlannerModel::Linuxcnc: return "linuxcnc";
  case PlannerModel::Grbl: return "grbl";
  }
  return "textbook";
}

std::optional<MachineProfile> read_machine_profile(std::string_view toml_text,
                                                   std::uint32_t file_id,
                                                   core::DiagnosticSink& diags) {
  Reader r(file_id, diags);
  toml::table root;
  try {
    root = toml::parse(toml_text);
  } catch (const toml::parse_error& e) {
    r.fail(e.source(), fmt::format("not valid TOML: {}", e.description()));
    return std::nullopt;
  }
  r.unknown_keys(root, "");
  MachineProfile p;
  read_machine(r, root, p);
  if (const toml::table* axes = r.section(root, "axes", true)) {
    for (int i = 0; i < 6; ++i)
      read_axis(r, *axes, i, p);
  }
  read_optional(r, root, p);
  if (!r.ok()) return std::nullopt;
  return p;
}

}  // namespace usina::sim
