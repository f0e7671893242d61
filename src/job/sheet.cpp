#include "job/sheet.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

namespace usina::job {
namespace {

// `a` less `b`: the figures between two marks of the same run.
sim::ToolStats between(const sim::ToolStats& a, const sim::ToolStats& b) {
  sim::ToolStats d;
  d.cutting_s = a.cutting_s - b.cutting_s;
  d.rapid_s = a.rapid_s - b.rapid_s;
  d.other_s = a.other_s - b.other_s;
  d.cutting_mm = a.cutting_mm - b.cutting_mm;
  d.rapid_mm = a.rapid_mm - b.rapid_mm;
  return d;
}

// 75 s as "1 min 15 s", 4000 s as "1 h 6 min 40 s".
std::string duration(double s) {
  const long total = std::lround(std::max(0.0, s));
  const long h = total / 3600;
  const long m = total / 60 % 60;
  const long sec = total % 60;
  if (h > 0) return fmt::format("{} h {} min {} s", h, m, sec);
  if (m > 0) return fmt::format("{} min {} s", m, sec);
  return fmt::format("{:.1f} s", std::max(0.0, s));
}

std::string stock_text(const Stock& s) {
  return s.shape == "box"
             ? fmt::format("box {:g} × {:g} × {:g} mm, corner at X{:g} Y{:g} of the drawing",
                           s.size[0], s.size[1], s.size[2], s.origin[0], s.origin[1])
             : fmt::format("cylinder Ø{:g} × {:g} mm, centre at X{:g} Y{:g} of the drawing",
                           s.size[0], s.size[1], s.origin[0], s.origin[1]);
}

void part_section(core::Document& d, const LoadedJob& j, std::string_view program) {
  const Job& job = j.job;
  const Material& m = j.materials[j.material];
  d.heading("Part and stock");
  core::DocBlock facts{core::DocBlock::Kind::Facts};
  const auto row = [&facts](std::string name, std::string value) {
    facts.rows.push_back({std::move(name), std::move(value)});
  };
  row("Program", std::string(program));
  row("Stock", stock_text(job.stock));
  row("Material", m.name + (m.description.empty() ? "" : " — " + m.description));
  row("Work zero", "the drawing's X0 Y0 on the stock's top face (Z0); depths are below it");
  row("Safe Z", fmt::format("{:g} mm above Z0 for every rapid", job.safe_z));
  row("Machine", j.machine ? j.machine->name : "none given: no limits, generic times");
  row("Setup", job.setup_note.empty() ? "(no setup_note in the job file)" : job.setup_note);
  d.blocks.push_back(std::move(facts));
}

// Each tool once, in the order of first use, with the stick-out its
// deepest step needs.
void tool_section(core::Document& d, const SheetLog& log) {
  std::vector<const SheetStep*> first;
  std::map<int, double> deepest;
  for (const SheetStep& s : log.steps) {
    auto [it, added] = deepest.emplace(s.tool.number, s.depth);
    if (added) first.push_back(&s);
    it->second = std::max(it->second, s.depth);
  }
  d.heading("Tools");
  core::DocBlock table{core::DocBlock::Kind::Table};
  table.header = {"T",
                  "Tool",
                  "Ø mm",
                  "Flutes",
                  "Cutting length mm",
                  "Deepest cut mm",
                  "Stick-out at least mm"};
  for (const SheetStep* s : first) {
    const Tool& t = s->tool;
    const double stick = deepest[t.number] + kHolderClearance;
    const bool too_long = t.overall_length > 0 && stick > t.overall_length;
    table.rows.push_back(
        {fmt::format("T{}", t.number),
         fmt::format("{} ({}, {})", t.name, tool_type_name(t.type), tool_material_name(t.material)),
         fmt::format("{:g}", t.diameter), fmt::format("{}", t.flutes),
         fmt::format("{:g}", t.cutting_length), fmt::format("{:g}", deepest[t.number]),
         fmt::format(
             "{:g}{}", stick,
             too_long ? fmt::format("\nLONGER THAN THE TOOL ({:g} mm)", t.overall_length) : "")});
  }
  d.blocks.push_back(std::move(table));
  d.note(fmt::format(
      "Stick-out: the deepest cut and {:g} mm, so that the holder clears the stock's top.",
      kHolderClearance));
}

std::vector<std::string> step_row(std::size_t n, const SheetStep& s) {
  std::string why;
  if (!s.chosen.empty()) why += "chosen: " + s.chosen;
  for (const std::string& w : s.why)
    why += (why.empty() ? "" : "\n") + w;
  return {fmt::format("{}", n),
          s.title,
          fmt::format("T{}", s.tool.number),
          fmt::format("{:g}", s.depth),
          fmt::format("{:.0f}", s.rpm),
          fmt::format("{:.0f}", s.feed),
          fmt::format("{:.0f}", s.plunge_feed),
          duration(s.time.total_s()),
          duration(s.time.cutting_s),
          why};
}

void operation_section(core::Document& d, const SheetLog& log) {
  d.heading("Operations");
  core::DocBlock table{core::DocBlock::Kind::Table};
  table.header = {"#",           "Operation",     "Tool", "Depth mm", "rev/min",
                  "Feed mm/min", "Plunge mm/min", "Time", "Cutting",  "Why"};
  table.small.assign(table.header.size(), false);
  table.small.back() = true;
  for (std::size_t i = 0; i < log.steps.size(); ++i)
    table.rows.push_back(step_row(i + 1, log.steps[i]));
  d.blocks.push_back(std::move(table));
}

void totals_section(core::Document& d, const LoadedJob& j, const SheetTimer& timer) {
  const sim::StatsReport& r = timer.report();
  d.heading("Cycle time and cost");
  core::DocBlock facts{core::DocBlock::Kind::Facts};
  facts.rows.push_back(
      {"Cycle time", fmt::format("{} (cutting {}, rapids {}, tool changes and the rest {})",
                                 duration(r.total.total_s()), duration(r.total.cutting_s),
                                 duration(r.total.rapid_s), duration(r.total.other_s))});
  const double per_hour = j.machine ? j.machine->cost_per_hour : 0.0;
  facts.rows.push_back(
      {"Cost", per_hour > 0
                   ? fmt::format("{:.2f} (at {:g} an hour of the machine)", r.cost, per_hour)
                   : std::string("not known: the machine profile has no [cost] per_hour")});
  d.blocks.push_back(std::move(facts));
  if (timer.checks().empty()) return;
  d.heading("Checks");
  core::DocBlock list{core::DocBlock::Kind::List};
  for (const core::Diagnostic& diag : timer.checks())
    list.rows.push_back({fmt::format("{}: {}", core::severity_name(diag.severity), diag.message)});
  d.blocks.push_back(std::move(list));
}

}  // namespace

SheetTimer::SheetTimer(const sim::MachineProfile& machine, SheetLog& log)
    : log_(log), stats_(machine, {}, checks_) {
  log_.on_step = [this] { mark(); };
}

void SheetTimer::mark() {
  stats_.finish();  // a step starts from rest: the one before ended at the safe Z
  marks_.push_back(stats_.report().total);
}

void SheetTimer::finish() {
  mark();
  report_ = stats_.report();
  // marks_[0] is the first step's start; marks_[i + 1] its end.
  for (std::size_t i = 0; i < log_.steps.size() && i + 1 < marks_.size(); ++i)
    log_.steps[i].time = between(marks_[i + 1], marks_[i]);
}

core::Document sheet_document(const LoadedJob& j, const SheetLog& log, const SheetTimer& timer,
                              std::string_view program) {
  core::Document d;
  d.title = "Setup sheet: " + (j.job.name.empty() ? std::string("(unnamed)") : j.job.name);
  part_section(d, j, program);
  d.figure(
      "The tool path seen from above, one colour per tool, rapids dashed, the holes green, the "
      "stock's outline grey; the work zero is the drawing's origin.");
  tool_section(d, log);
  operation_section(d, log);
  totals_section(d, j, timer);
  d.note("Written by usina job; times from usina stats' planner on the machine's profile.");
  return d;
}

}  // namespace usina::job
