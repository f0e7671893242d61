// usina stats FILE: cycle time by a motion planner on a machine profile,
// totals and per-tool figures, and the program checks (docs/stats.md; the
// JSON schema is there).
//
// Exit status: 0; 1 when the program has an error (the figures of what ran
// before it are still printed, "complete": false); 2 for bad input (an
// unreadable program or profile, a profile with an error, a bad option).
#include "sim/stats.hpp"

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/machine_option.hpp"
#include "cli/run.hpp"
#include "cli/verbs.hpp"
#include "core/source.hpp"

namespace usina::cli {
namespace {

using nlohmann::json;

struct StatsOptions {
  RunOptions run;
  std::string machine;
  std::string format = "text";
  std::optional<double> stock_top;
  std::vector<double> work_zero;
};

// A diagnostic as the JSON lists it.
struct Reported {
  core::Diagnostic d;
  std::string file;
};

// Prints the checks' diagnostics like the program's (stderr) and keeps them for JSON.
class CheckDiagnostics final : public core::DiagnosticSink {
 public:
  void set_sources(const core::SourceManager* s) { sources_ = s; }

  void report(core::Diagnostic d) override {
    std::string file = "<input>";
    if (sources_ != nullptr) {
      const std::string text = core::render(d, *sources_);
      std::fwrite(text.data(), 1, text.size(), stderr);
      if (const core::SourceFile* f = sources_->get(d.loc.file)) file = f->name();
    }
    all_.push_back({std::move(d), std::move(file)});
  }

  const std::vector<Reported>& all() const { return all_; }

  // The program's own diagnostics, already printed by run_program: kept only.
  class Keeper final : public core::DiagnosticSink {
   public:
    explicit Keeper(CheckDiagnostics& owner) : owner_(owner) {}

    void report(core::Diagnostic d) override { owner_.keep(std::move(d)); }

   private:
    CheckDiagnostics& owner_;
  };

 private:
  void keep(core::Diagnostic d) {
    std::string file = "<input>";
    if (sources_ != nullptr) {
      if (const core::SourceFile* f = sources_->get(d.loc.file)) file = f->name();
    }
    all_.push_back({std::move(d), std::move(file)});
  }

  const core::SourceManager* sources_ = nullptr;
  std::vector<Reported> all_;
};

// 754.5 s → "0:12:34.5".
std::string clock(double s) {
  const double tenths = std::round(s * 10.0);
  const auto t = static_cast<long long>(tenths);
  return fmt::format("{}:{:02}:{:02}.{}", t / 36000, (t / 600) % 60, (t / 10) % 60, t % 10);
}

json range_json(const sim::Range& r) {
  return r.empty() ? json(nullptr) : json{{"min", r.min}, {"max", r.max}};
}

json box_json(const sim::Box& b) {
  if (b.empty()) return nullptr;
  return {{"min", {b.lo.x, b.lo.y, b.lo.z}}, {"max", {b.hi.x, b.hi.y, b.hi.z}}};
}

json counts_json(const sim::Counts& c) {
  return {{"moves", c.moves()},   {"rapids", c.rapids},
          {"feeds", c.feeds},     {"arcs", c.arcs},
          {"splines", c.splines}, {"probes", c.probes},
          {"holes", c.holes},     {"tool_changes", c.tool_changes},
          {"dwells", c.dwells}};
}

// motion_s: the time the axes move (cutting and rapid; probing is "other"),
// LinuxCNC's own "motion" figure; total_s adds dwells, tool changes and
// spindle waits.
json time_json(const sim::ToolStats& t) {
  return {{"total_s", t.total_s()},   {"motion_s", t.cutting_s + t.rapid_s},
          {"cutting_s", t.cutting_s}, {"rapid_s", t.rapid_s},
          {"other_s", t.other_s},     {"exact_stop_s", t.exact_stop_s}};
}

json distance_json(const sim::ToolStats& t) {
  return {{"cutting_mm", t.cutting_mm}, {"rapid_mm", t.rapid_mm}};
}

json diagnostics_json(const std::vector<Reported>& all) {
  json out = json::array();
  for (const Reported& r : all) {
    out.push_back({{"code", core::code_name(r.d.code)},
                   {"severity", core::severity_name(r.d.severity)},
                   {"file", r.file},
                   {"line", r.d.loc.line},
                   {"column", r.d.loc.col},
                   {"message", r.d.message}});
  }
  return out;
}

void print_json(const StatsOptions& o, const sim::MachineProfile& m, const sim::StatsReport& r,
                bool complete, const std::vector<Reported>& diags) {
  json tools = json::array();
  for (const sim::ToolStats& t : r.tools) {
    tools.push_back({{"tool", t.tool},
                     {"time", time_json(t)},
                     {"distance", distance_json(t)},
                     {"counts", counts_json(t.counts)},
                     {"bounds", box_json(t.bounds)},
                     {"feed_mm_per_min", range_json(t.feed)},
                     {"rpm", range_json(t.rpm)}});
  }
  json checks = json::object();
  for (const auto& [code, n] : r.checks)
    checks[std::string(core::code_name(code))] = n;
  const json out = {
      {"program", o.run.file},
      {"machine",
       {{"name", m.name},
        {"profile", o.machine.empty() ? json(nullptr) : json(o.machine)},
        {"junction_deviation_mm", m.junction_deviation}}},
      {"complete", complete},
      {"planner", {{"model", sim::planner_model_name(m.model)}}},
      {"time", time_json(r.total)},
      {"distance", distance_json(r.total)},
      {"counts", counts_json(r.total.counts)},
      {"feed_mm_per_min", range_json(r.total.feed)},
      {"rpm", range_json(r.total.rpm)},
      {"cost", {{"per_hour", m.cost_per_hour}, {"total", r.cost}}},
      {"tools", std::move(tools)},
      {"bounds", box_json(r.total.bounds)},
      {"checks", std::move(checks)},
      {"diagnostics", diagnostics_json(diags)},
  };
  fmt::print("{}\n", out.dump(2));
}

std::string range_text(const sim::Range& r, const char* unit) {
  if (r.empty()) return "-";
  if (r.min == r.max) return fmt::format("{:g} {}", r.min, unit);
  return fmt::format("{:g} to {:g} {}", r.min, r.max, unit);
}

void print_times(const sim::ToolStats& t, double cost, double per_hour) {
  const double total = t.total_s();
  const auto share = [total](double s) { return total > 0.0 ? 100.0 * s / total : 0.0; };
  fmt::print("cycle time       {:>11}  ({:.1f} s)\n", clock(total), total);
  fmt::print("  cutting        {:>11}  {:5.1f} %\n", clock(t.cutting_s), share(t.cutting_s));
  fmt::print("  rapid          {:>11}  {:5.1f} %\n", clock(t.rapid_s), share(t.rapid_s));
  fmt::print(
      "  other          {:>11}  {:5.1f} %  (tool changes, dwells, spindle start-up, "
      "probing)\n",
      clock(t.other_s), share(t.other_s));
  fmt::print("exact stop (G61) {:>11}  ({:.1f} s, {:+.1f} % against look-ahead)\n",
             clock(t.exact_stop_s), t.exact_stop_s,
             total > 0.0 ? 100.0 * (t.exact_stop_s / total - 1.0) : 0.0);
  if (per_hour > 0.0) fmt::print("cost             {:>11.2f}  at {:.2f} an hour\n", cost, per_hour);
}

void print_text(const StatsOptions& o, const sim::MachineProfile& m, const sim::StatsReport& r,
                bool complete) {
  const sim::ToolStats& t = r.total;
  fmt::print("program          {}{}\n", o.run.file,
             complete ? "" : "  (stopped at an error: figures up to it)");
  fmt::print("machine          {}{}\n", m.name,
             o.machine.empty() ? " (no --machine given)" : fmt::format(" ({})", o.machine));
  if (m.model != sim::PlannerModel::Textbook) {
    fmt::print("planner          {} model\n", sim::planner_model_name(m.model));
  }
  print_times(t, r.cost, m.cost_per_hour);
  fmt::print("distance         cutting {:.3f} mm, rapid {:.3f} mm\n", t.cutting_mm, t.rapid_mm);
  const sim::Counts& c = t.counts;
  fmt::print("moves            {} (rapid {}, feed {}, arc {}, spline {}, probe {})\n", c.moves(),
             c.rapids, c.feeds, c.arcs, c.splines, c.probes);
  fmt::print("                 holes {}, tool changes {}, dwells {}\n", c.holes, c.tool_changes,
             c.dwells);
  fmt::print("feed             {}\n", range_text(t.feed, "mm/min"));
  fmt::print("spindle          {}\n", range_text(t.rpm, "rpm"));
  if (!t.bounds.empty()) {
    fmt::print("extent           X {:.3f} to {:.3f}, Y {:.3f} to {:.3f}, Z {:.3f} to {:.3f} mm\n",
               t.bounds.lo.x, t.bounds.hi.x, t.bounds.lo.y, t.bounds.hi.y, t.bounds.lo.z,
               t.bounds.hi.z);
  }
  if (!r.tools.empty()) {
    fmt::print("\n{:<6} {:>11} {:>11} {:>11} {:>11} {:>12} {:>7} {:>6}  {}\n", "tool", "cutting",
               "rapid", "other", "total", "cutting mm", "moves", "holes", "feed / spindle");
  }
  for (const sim::ToolStats& s : r.tools) {
    fmt::print("{:<6} {:>11} {:>11} {:>11} {:>11} {:>12.3f} {:>7} {:>6}  {}; {}\n",
               s.tool == 0 ? std::string("(T0)") : fmt::format("T{}", s.tool), clock(s.cutting_s),
               clock(s.rapid_s), clock(s.other_s), clock(s.total_s()), s.cutting_mm,
               s.counts.moves(), s.counts.holes, range_text(s.feed, "mm/min"),
               range_text(s.rpm, "rpm"));
  }
  if (!r.checks.empty()) {
    fmt::print("\nchecks (ops flagged; the first of each run is shown on standard error):\n");
    for (const auto& [code, n] : r.checks)
      fmt::print("  {:<24} {}\n", core::code_name(code), n);
  }
}

void run_stats(const StatsOptions& o) {
  const auto profile = load_machine_profile(o.machine);
  if (!profile) return set_exit_status(2);
  CheckDiagnostics diags;
  sim::StatsOptions so;
  so.stock_top = o.stock_top;
  // A parameter file places the program (its G54.. offsets are in the trace).
  if (!o.work_zero.empty()) {
    so.work_zero = core::Vec3{o.work_zero[0], o.work_zero[1], o.work_zero[2]};
  } else if (!o.run.var_file.empty()) {
    so.work_zero = core::Vec3{};
  }
  sim::StatsSink sink(*profile, so, diags);
  CheckDiagnostics::Keeper program_diags(diags);
  const int status = run_program(
      o.run, sink, [&diags](const core::SourceManager& sources) { diags.set_sources(&sources); },
      &program_diags);
  if (status == 2) return set_exit_status(2);
  sink.finish();
  const sim::StatsReport report = sink.report();
  if (o.format == "json") {
    print_json(o, *profile, report, status == 0, diags.all());
  } else {
    print_text(o, *profile, report, status == 0);
  }
  set_exit_status(status);
}

}  // namespace

void add_stats(CLI::App& app) {
  auto opts = std::make_shared<StatsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stats", "cycle time on a machine profile, per-tool figures and program checks");
  add_run_options(*cmd, opts->run);
  cmd->add_option("--machine", opts->machine,
                  "machine profile (TOML, see examples/machines/); without it a generic mill");
  cmd->add_option("--format", opts->format, "text, or json (docs/stats.md)")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  cmd->add_option("--stock-top", opts->stock_top,
                  "Z of the top of the stock, mm: rapids below it are reported");
  cmd->add_option("--work-zero", opts->work_zero,
                  "X,Y,Z: machine coordinates of program zero (mm), to check the travel "
                  "limits; without it (or --var-file) the program's extent is checked")
      ->delimiter(',')
      ->expected(3);
  cmd->callback([opts] { run_stats(*opts); });
}

}  // namespace usina::cli
