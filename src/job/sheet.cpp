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

// Text from the job's author, the tool library and the drawing: escaped
// wherever it goes into the page.
std::string esc(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
    case '&': out += "&amp;"; break;
    case '<': out += "&lt;"; break;
    case '>': out += "&gt;"; break;
    case '"': out += "&quot;"; break;
    case '\'': out += "&#39;"; break;
    default: out += c;
    }
  }
  return out;
}

// 75 s as "1 min 15 s", 4000 s as "1 h 6 min 40 s".
std::string duration(double s) {
  const long total = std::lround(std::max(0.0, s));
  const long h = total / 3600, m = total / 60 % 60, sec = total % 60;
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

void part_section(std::string& h, const LoadedJob& j, std::string_view program) {
  const Job& job = j.job;
  const Material& m = j.materials[j.material];
  h += "<h2>Part and stock</h2>\n<table class=\"facts\">\n";
  const auto row = [&h](std::string_view k, const std::string& v) {
    h += fmt::format("<tr><th scope=\"row\">{}</th><td>{}</td></tr>\n", k, v);
  };
  row("Program", esc(program));
  row("Stock", esc(stock_text(job.stock)));
  row("Material", esc(m.name) + (m.description.empty() ? "" : " — " + esc(m.description)));
  row("Work zero", "the drawing's X0 Y0 on the stock's top face (Z0); depths are below it");
  row("Safe Z", fmt::format("{:g} mm above Z0 for every rapid", job.safe_z));
  row("Machine", j.machine ? esc(j.machine->name) : "none given: no limits, generic times");
  row("Setup", job.setup_note.empty() ? "(no setup_note in the job file)" : esc(job.setup_note));
  h += "</table>\n";
}

// Each tool once, in the order of first use, with the stick-out its
// deepest step needs.
void tool_section(std::string& h, const SheetLog& log) {
  std::vector<const SheetStep*> first;
  std::map<int, double> deepest;
  for (const SheetStep& s : log.steps) {
    auto [it, added] = deepest.emplace(s.tool.number, s.depth);
    if (added) first.push_back(&s);
    it->second = std::max(it->second, s.depth);
  }
  h += "<h2>Tools</h2>\n<table>\n<thead><tr><th scope=\"col\">T</th><th scope=\"col\">Tool</th>"
       "<th scope=\"col\">Ø mm</th><th scope=\"col\">Flutes</th><th scope=\"col\">Cutting "
       "length mm</th><th scope=\"col\">Deepest cut mm</th><th scope=\"col\">Stick-out at "
       "least mm</th></tr></thead>\n<tbody>\n";
  for (const SheetStep* s : first) {
    const Tool& t = s->tool;
    const double stick = deepest[t.number] + kHolderClearance;
    const bool too_long = t.overall_length > 0 && stick > t.overall_length;
    h += fmt::format(
        "<tr><td>T{}</td><td>{} ({}, {})</td><td>{:g}</td><td>{}</td><td>{:g}</td><td>{:g}</td>"
        "<td>{:g}{}</td></tr>\n",
        t.number, esc(t.name), tool_type_name(t.type), tool_material_name(t.material), t.diameter,
        t.flutes, t.cutting_length, deepest[t.number], stick,
        too_long ? fmt::format(" <strong>longer than the tool ({:g} mm)</strong>", t.overall_length)
                 : "");
  }
  h += fmt::format(
      "</tbody>\n</table>\n<p class=\"note\">Stick-out: the deepest cut and {:g} mm, so that "
      "the holder clears the stock's top.</p>\n",
      kHolderClearance);
}

void step_row(std::string& h, std::size_t n, const SheetStep& s) {
  std::string why;
  if (!s.chosen.empty()) why += esc("chosen: " + s.chosen) + "<br>";
  for (const std::string& w : s.why)
    why += esc(w) + "<br>";
  h += fmt::format(
      "<tr><td>{}</td><td>{}</td><td>T{}</td><td>{:g}</td><td>{:.0f}</td><td>{:.0f}</td>"
      "<td>{:.0f}</td><td>{}</td><td>{}</td><td class=\"why\">{}</td></tr>\n",
      n, esc(s.title), s.tool.number, s.depth, s.rpm, s.feed, s.plunge_feed,
      duration(s.time.total_s()), duration(s.time.cutting_s), why);
}

void operation_section(std::string& h, const SheetLog& log) {
  h += "<h2>Operations</h2>\n<table>\n<thead><tr><th scope=\"col\">#</th><th "
       "scope=\"col\">Operation</th><th scope=\"col\">Tool</th><th scope=\"col\">Depth mm</th>"
       "<th scope=\"col\">rev/min</th><th scope=\"col\">Feed mm/min</th><th "
       "scope=\"col\">Plunge mm/min</th><th scope=\"col\">Time</th><th scope=\"col\">Cutting</th>"
       "<th scope=\"col\">Why</th></tr></thead>\n<tbody>\n";
  for (std::size_t i = 0; i < log.steps.size(); ++i)
    step_row(h, i + 1, log.steps[i]);
  h += "</tbody>\n</table>\n";
}

void totals_section(std::string& h, const LoadedJob& j, const SheetTimer& timer) {
  const sim::StatsReport& r = timer.report();
  h += "<h2>Cycle time and cost</h2>\n<table class=\"facts\">\n";
  h += fmt::format(
      "<tr><th scope=\"row\">Cycle time</th><td>{} (cutting {}, rapids {}, "
      "tool changes and the rest {})</td></tr>\n",
      duration(r.total.total_s()), duration(r.total.cutting_s), duration(r.total.rapid_s),
      duration(r.total.other_s));
  const double per_hour = j.machine ? j.machine->cost_per_hour : 0.0;
  h += per_hour > 0 ? fmt::format(
                          "<tr><th scope=\"row\">Cost</th><td>{:.2f} (at {:g} an hour of the "
                          "machine)</td></tr>\n",
                          r.cost, per_hour)
                    : std::string(
                          "<tr><th scope=\"row\">Cost</th><td>not known: the machine profile "
                          "has no [cost] per_hour</td></tr>\n");
  h += "</table>\n";
  if (timer.checks().empty()) return;
  h += "<h2>Checks</h2>\n<ul>\n";
  for (const core::Diagnostic& d : timer.checks())
    h += fmt::format("<li>{}: {}</li>\n", core::severity_name(d.severity), esc(d.message));
  h += "</ul>\n";
}

constexpr std::string_view kStyle = R"(body{font-family:sans-serif;margin:1.5em;color:#111}
table{border-collapse:collapse;margin:.5em 0 1em}th,td{border:1px solid #999;padding:.25em .5em;
text-align:left;vertical-align:top}td.why{font-size:.85em}p.note{font-size:.85em}
figure svg{max-width:100%;height:auto;max-height:14cm;border:1px solid #999}
@media print{body{margin:0}h2{break-after:avoid}tr{break-inside:avoid}})";

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

std::string sheet_html(const LoadedJob& j, const SheetLog& log, const SheetTimer& timer,
                       std::string_view picture_svg, std::string_view program) {
  const std::string name = j.job.name.empty() ? "(unnamed)" : j.job.name;
  std::string h = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Setup "
      "sheet: {}</title>\n<style>{}</style>\n</head>\n<body>\n<h1>Setup sheet: {}</h1>\n",
      esc(name), kStyle, esc(name));
  part_section(h, j, program);
  h += "<figure>\n";
  h += picture_svg;
  h += "\n<figcaption>The tool path seen from above, one colour per tool, rapids dashed, the "
       "holes green, the stock's outline grey; the work zero is the drawing's "
       "origin.</figcaption>\n</figure>\n";
  tool_section(h, log);
  operation_section(h, log);
  totals_section(h, j, timer);
  h += "<p class=\"note\">Written by usina job; times from usina stats' planner on the machine's "
       "profile.</p>\n</body>\n</html>\n";
  return h;
}

}  // namespace usina::job
