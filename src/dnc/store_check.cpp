#include "dnc/store_check.hpp"

#include <nlohmann/json.hpp>

#include "canon/sink.hpp"
#include "core/source.hpp"
#include "gcode/dialect.hpp"
#include "sim/stats.hpp"

namespace usina::dnc {
namespace {

using nlohmann::json;

// Keeps the first diagnostics and counts them all.
class Collector final : public core::DiagnosticSink {
 public:
  explicit Collector(CheckResults& r) : r_(r) {}

  void report(core::Diagnostic d) override {
    if (d.severity == core::Severity::Error) ++r_.errors;
    if (d.severity == core::Severity::Warning) ++r_.warnings;
    if (d.code == core::Code::OverTravel) ++r_.overtravel;
    if (r_.diagnostics.size() >= CheckResults::kMaxKeptDiagnostics) return;
    r_.diagnostics.push_back({std::string(core::code_name(d.code)),
                              std::string(core::severity_name(d.severity)), d.loc.line, d.loc.col,
                              std::move(d.message)});
  }

 private:
  CheckResults& r_;
};

void take_report(const sim::StatsReport& report, CheckResults& r) {
  r.cycle_time_s = report.total.total_s();
  r.cutting_s = report.total.cutting_s;
  r.rapid_s = report.total.rapid_s;
  const sim::Box& b = report.total.bounds;
  if (!b.empty()) r.bounds = std::array<double, 6>{b.lo.x, b.lo.y, b.lo.z, b.hi.x, b.hi.y, b.hi.z};
  for (const auto& [code, n] : report.checks)
    r.checks[std::string(core::code_name(code))] = n;
  r.has_tools = true;
  for (const sim::ToolStats& t : report.tools)
    r.tools.push_back({t.tool, t.cutting_s, t.total_s()});
}

}  // namespace

CheckResults check_program(std::string_view text, const CheckSettings& settings) {
  CheckResults r;
  r.dialect = settings.dialect;
  Collector diags(r);
  const gcode::Dialect* dialect = gcode::find_dialect(settings.dialect);
  if (dialect == nullptr) {
    diags.report({core::Code::Unsupported,
                  core::Severity::Error,
                  {},
                  "unknown dialect " + settings.dialect});
    return r;
  }
  const sim::MachineProfile profile =
      settings.profile != nullptr ? *settings.profile : sim::default_machine_profile();
  r.machine = profile.name;
  core::SourceManager sources;
  const std::uint32_t id =
      sources.add(core::SourceFile::from_string("<revision>", std::string(text)));
  gcode::OptionValues options = gcode::default_options(*dialect);
  sim::StatsSink stats(profile, sim::StatsOptions{}, diags);
  canon::OpBudget budget(stats, settings.max_ops, diags);
  auto runner = dialect->make_runner(
      gcode::RunContext{sources, gcode::InterpOptions{}, std::move(options), budget, diags});
  const bool ok = runner->run(id);
  stats.finish();
  r.complete = ok && r.errors == 0;
  take_report(stats.report(), r);
  return r;
}

std::string CheckResults::to_json() const {
  json d = json::array();
  for (const CheckDiagnostic& c : diagnostics) {
    d.push_back({{"code", c.code},
                 {"severity", c.severity},
                 {"line", c.line},
                 {"column", c.column},
                 {"message", c.message}});
  }
  json tool_list = json::array();
  for (const CheckTool& t : tools)
    tool_list.push_back({{"tool", t.tool}, {"cutting_s", t.cutting_s}, {"total_s", t.total_s}});
  json out = {
      {"dialect", dialect},
      {"machine", machine},
      {"complete", complete},
      {"errors", errors},
      {"warnings", warnings},
      {"overtravel", overtravel},
      {"diagnostics", std::move(d)},
      {"cycle_time_s", cycle_time_s},
      {"cutting_s", cutting_s},
      {"rapid_s", rapid_s},
      {"bounds", bounds ? json{{"min", {(*bounds)[0], (*bounds)[1], (*bounds)[2]}},
                               {"max", {(*bounds)[3], (*bounds)[4], (*bounds)[5]}}}
                        : json(nullptr)},
      {"checks", checks},
  };
  if (has_tools) out["tools"] = std::move(tool_list);
  // A message may quote a program's bytes that are not UTF-8.
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

namespace {

CheckResults from_object(const json& j) {
  CheckResults r;
  r.dialect = j.value("dialect", "");
  r.machine = j.value("machine", "");
  r.complete = j.value("complete", false);
  r.errors = j.value("errors", std::uint64_t{0});
  r.warnings = j.value("warnings", std::uint64_t{0});
  r.overtravel = j.value("overtravel", std::uint64_t{0});
  r.cycle_time_s = j.value("cycle_time_s", 0.0);
  r.cutting_s = j.value("cutting_s", 0.0);
  r.rapid_s = j.value("rapid_s", 0.0);
  if (const auto it = j.find("diagnostics"); it != j.end() && it->is_array()) {
    for (const json& d : *it) {
      r.diagnostics.push_back({d.value("code", ""), d.value("severity", ""),
                               d.value("line", std::uint32_t{0}),
                               d.value("column", std::uint32_t{0}), d.value("message", "")});
    }
  }
  if (const auto it = j.find("bounds"); it != j.end() && it->is_object()) {
    const json& lo = it->at("min");
    const json& hi = it->at("max");
    r.bounds = std::array<double, 6>{lo.at(0).get<double>(), lo.at(1).get<double>(),
                                     lo.at(2).get<double>(), hi.at(0).get<double>(),
                                     hi.at(1).get<double>(), hi.at(2).get<double>()};
  }
  if (const auto it = j.find("checks"); it != j.end() && it->is_object())
    r.checks = it->get<std::map<std::string, std::uint64_t>>();
  if (const auto it = j.find("tools"); it != j.end() && it->is_array()) {
    r.has_tools = true;
    for (const json& t : *it)
      r.tools.push_back({t.value("tool", 0), t.value("cutting_s", 0.0), t.value("total_s", 0.0)});
  }
  return r;
}

}  // namespace

std::optional<CheckResults> CheckResults::from_json(std::string_view text) {
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  try {
    return from_object(j);
  } catch (const json::exception&) {  // a field of the wrong type: not our JSON
    return std::nullopt;
  }
}

}  // namespace usina::dnc
