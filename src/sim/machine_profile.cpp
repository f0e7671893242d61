#include "sim/machine_profile.hpp"

#include <cmath>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "core/units.hpp"

namespace usina::sim {
namespace {

constexpr const char* kAxisNames[] = {"x", "y", "z", "a", "b", "c"};

class Reader {
 public:
  Reader(std::uint32_t file, core::DiagnosticSink& diags) : file_(file), diags_(diags) {}

  void fail(const toml::source_region& where, std::string message) {
    ok_ = false;
    core::SourceLoc loc{file_, static_cast<std::uint32_t>(where.begin.line),
                        static_cast<std::uint32_t>(where.begin.column), 1, 0};
    diags_.report({core::Code::BadMachineProfile, core::Severity::Error, loc, std::move(message)});
  }

  // A number at `path` (integers accepted), required or with a default.
  double number(const toml::table& t, const char* section, const char* key,
                std::optional<double> fallback, bool non_negative = true) {
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
    if (non_negative && *v < 0.0) {
      fail(n->source(), fmt::format("[{}] {} = {} must not be negative", section, key, *v));
    }
    return *v;
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

  bool ok() const { return ok_; }

 private:
  std::uint32_t file_;
  core::DiagnosticSink& diags_;
  bool ok_ = true;
};

void read_machine(Reader& r, const toml::table& root, MachineProfile& p) {
  const toml::table* m = r.section(root, "machine", true);
  if (m == nullptr) return;
  p.name = m->get("name") != nullptr ? m->get("name")->value_or<std::string>("") : "";
  const toml::node* units = m->get("units");
  const std::string u = units != nullptr ? units->value_or<std::string>("") : "mm";
  if (u != "mm" && u != "inch") {
    r.fail(units != nullptr ? units->source() : m->source(),
           fmt::format("[machine] units = \"{}\": must be \"mm\" or \"inch\"", u));
  }
  p.file_in_inch = u == "inch";
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
  AxisLimits& a = p.axes[static_cast<std::size_t>(i)];
  a.present = true;
  a.min = r.number(t, section.c_str(), "min", std::nullopt, false) * scale;
  a.max = r.number(t, section.c_str(), "max", std::nullopt, false) * scale;
  a.rapid = r.number(t, section.c_str(), "rapid", std::nullopt) * scale;
  a.max_feed = r.number(t, section.c_str(), "max_feed", std::nullopt) * scale;
  a.accel = r.number(t, section.c_str(), "accel", std::nullopt) * scale;
  a.jerk = r.number(t, section.c_str(), "jerk", 0.0) * scale;
  if (a.min > a.max) r.fail(t.source(), fmt::format("[{}] min is above max", section));
  if (a.rapid == 0.0 || a.accel == 0.0) {
    r.fail(t.source(), fmt::format("[{}] rapid and accel must be above zero", section));
  }
}

}  // namespace

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
  MachineProfile p;
  read_machine(r, root, p);
  if (const toml::table* axes = r.section(root, "axes", true)) {
    for (int i = 0; i < 6; ++i)
      read_axis(r, *axes, i, p);
  }
  if (const toml::table* s = r.section(root, "spindle", false)) {
    p.spindle_max_rpm = r.number(*s, "spindle", "max_rpm", 0.0);
    p.spindle_accel_time = r.number(*s, "spindle", "accel_time", 0.0);
  }
  if (const toml::table* t = r.section(root, "times", false)) {
    p.tool_change_time = r.number(*t, "times", "tool_change", 0.0);
    p.block_time = r.number(*t, "times", "block", 0.0);
  }
  if (const toml::table* c = r.section(root, "cost", false)) {
    p.cost_per_hour = r.number(*c, "cost", "per_hour", 0.0);
  }
  if (const toml::table* pl = r.section(root, "planner", false)) {
    const double scale = p.file_in_inch ? core::kMmPerInch : 1.0;
    p.junction_deviation = r.number(*pl, "planner", "junction_deviation", 0.01 / scale) * scale;
  }
  if (!r.ok()) return std::nullopt;
  return p;
}

}  // namespace usina::sim
