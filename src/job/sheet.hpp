// The setup sheet of a job (`usina job --sheet part.html`; docs/job.md,
// "Setup sheet"): seed 004 table 7.3's downward data, what the operator
// needs at the machine before the first part. The part and its stock, the
// work zero, the fixtures, each tool with the stick-out it needs, each
// operation with its speeds, feeds and time on the machine's profile, the
// cycle time and its cost. Its content is one core::Document
// (sheet_document), written as HTML with its picture inside (sheet_html)
// or as PDF (draw/document_pdf, through the raster module).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "core/document.hpp"
#include "job/load.hpp"
#include "sim/stats.hpp"

namespace usina::job {

// One operation's work with one tool (a drill layer with two hole sizes
// is two steps).
struct SheetStep {
  std::string title;
  Tool tool;
  double depth = 0;  // the deepest it cuts, mm below Z0
  double rpm = 0;
  double feed = 0;
  double plunge_feed = 0;
  std::string chosen;             // why this tool (tool = "auto"), else empty
  std::vector<std::string> why;   // why each speed and feed
  std::vector<core::Vec2> holes;  // a drill step's hole centres (the picture's circles)
  sim::ToolStats time;            // its share of the program's time (SheetTimer)
  std::size_t operation = 0;      // its operation's index in the job's operations
};

// What make_job tells the sheet: each step as it begins.
struct SheetLog {
  std::vector<SheetStep> steps;
  // Called before a step's first op reaches the sink (SheetTimer's mark).
  std::function<void()> on_step;

  void begin(SheetStep step) {
    if (on_step) on_step();
    steps.push_back(std::move(step));
  }
};

// The minimum stick-out a step asks of its tool: its depth and this much
// more, so that the holder clears the stock's top at the deepest cut.
inline constexpr double kHolderClearance = 2.0;  // mm

// Times the program with stats' planner on the machine's profile and gives
// each step of `log` its share: a sink beside the post.
class SheetTimer final : public canon::Sink {
 public:
  SheetTimer(const sim::MachineProfile& machine, SheetLog& log);

  void on(const canon::Op& op) override { stats_.on(op); }

  // The end of the program: the last step's time, and every step's share.
  void finish() override;

  const sim::StatsReport& report() const { return report_; }

  // What stats' checks said of the program (travel, feeds, spindle).
  const std::vector<core::Diagnostic>& checks() const { return checks_.all(); }

 private:
  void mark();

  SheetLog& log_;
  core::DiagnosticList checks_;
  sim::StatsSink stats_;
  std::vector<sim::ToolStats> marks_;  // the totals when each step began
  sim::StatsReport report_;
};

// What the sheet says, in every format: its title, the part and stock,
// the figure's place and caption, the tools, the operations, the cycle
// time and cost, the checks. `program`: the program's file name.
core::Document sheet_document(const LoadedJob& j, const SheetLog& log, const SheetTimer& timer,
                              std::string_view program);

// A document as one HTML page, every text escaped. `picture_svg`: an SVG
// element put at the figure's place (nothing when empty).
std::string document_html(const core::Document& doc, std::string_view picture_svg);

// The sheet as HTML. `picture_svg`: the tool path seen from above (an SVG
// element, written by the caller).
inline std::string sheet_html(const LoadedJob& j, const SheetLog& log, const SheetTimer& timer,
                              std::string_view picture_svg, std::string_view program) {
  return document_html(sheet_document(j, log, timer, program), picture_svg);
}

}  // namespace usina::job
