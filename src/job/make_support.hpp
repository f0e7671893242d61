// The pieces make.cpp builds each operation from: the program's sink, the
// diagnostics located at an operation, the tool and its cutting values.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cam/path.hpp"
#include "cam/program.hpp"
#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "job/geometry.hpp"
#include "job/load.hpp"
#include "job/sheet.hpp"

namespace usina::job {

// The generators' streams as one program: their ends dropped (the job ends
// once), a tool change to the tool already in the spindle dropped.
class ProgramSink final : public canon::Sink {
 public:
  explicit ProgramSink(canon::Sink& next) : next_(next) {}

  void on(const canon::Op& op) override;

  bool stopped() const override { return next_.stopped(); }

  void comment(std::string text);

 private:
  canon::Sink& next_;
  std::optional<int> tool_;
};

// The generators' diagnostics have no place in a file: they get the
// operation's, and its name before their message.
class AtOperation final : public core::DiagnosticSink {
 public:
  AtOperation(core::DiagnosticSink& next, core::SourceLoc loc, std::string what)
      : next_(next), loc_(loc), what_(std::move(what)) {}

  void report(core::Diagnostic d) override;

 private:
  core::DiagnosticSink& next_;
  core::SourceLoc loc_;
  std::string what_;
};

// The contours of an operation's layer; nullopt after an error (a missing
// layer is E_JOB_MISSING_LAYER at the layer's line).
std::optional<std::vector<cam::Path>> layer_paths(const LoadedJob& j, const Operation& op,
                                                  core::DiagnosticSink& diags);

// The named tool, checked to reach the depth; null after an error.
const Tool* named_tool(const LoadedJob& j, const Operation& op, core::DiagnosticSink& diags);

// The cutting values of `op` with `tool`: rpm and feeds from the cutting
// data (or given in the job), capped by the machine. False after an error.
bool cutting_values(const LoadedJob& j, const Operation& op, const Tool& tool, bool slotting,
                    cam::Cutting& cut, std::vector<std::string>& why, core::DiagnosticSink& diags);

// A hole an earlier operation made: what a bore's pilot hole is checked by.
struct MadeHole {
  cam::Vec2 centre;
  double diameter = 0;
  double full_depth = 0;  // mm below Z0 where its full diameter ends (infinity: through)
};

// What every operation's maker is given.
struct Context {
  const LoadedJob& j;
  ProgramSink& sink;
  core::DiagnosticSink& diags;
  SheetLog* sheet = nullptr;    // the setup sheet's record of the steps, if one is written
  std::vector<MadeHole> holes;  // drilled and bored so far, in order
  std::vector<std::pair<int, double>>
      head_settings;  // boring heads and the diameter each is set to
};

// The tool of `op`: named, or the largest flat end mill whose radius is
// within `corner` (the smallest inside corner); `chosen` says why. Null
// after an error.
const Tool* mill_for(Context& cx, const Operation& op, double corner, std::string& chosen);

// The operation's comments (title, tool, the choice, why each number), and
// its cutting values into `cut`; false after an error.
bool prepare(Context& cx, const Operation& op, const Tool& tool, bool slotting,
             const std::string& chosen, cam::Cutting& cut, const std::string& title);

// The elliptical pocket (make_ellipse.cpp: cam/ellipse_pocket.hpp and
// cam/pocket.hpp each have a Ring, so they live in separate files).
bool run_ellipse(Context& cx, const Operation& op, const std::string& title);

// Facing the stock's top and engraving text (make_top.cpp).
bool run_face(Context& cx, const Operation& op, const std::string& title);
bool run_engrave(Context& cx, const Operation& op, const std::string& title);

// Bores: pre-drilled holes finished with a boring bar or head, G85
// (make_bore.cpp).
bool run_bore(Context& cx, const Operation& op, const std::string& title);

// The circles of a hole operation's layer grouped by diameter (only the
// op's `diameter` when given); nullopt after an error (none, or other
// entities on the layer).
std::optional<std::vector<HoleGroup>> layer_holes(Context& cx, const Operation& op);

// A chamfer along the layer's contours (make_chamfer.cpp).
bool run_chamfer(Context& cx, const Operation& op, const std::string& title);

}  // namespace usina::job
