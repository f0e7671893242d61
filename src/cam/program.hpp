// What every generator shares: the cutting values (tool, feeds, speed,
// heights), their checks, the depth passes, and a writer that turns moves
// into canon ops on a sink and remembers where the tool is.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cam/limits.hpp"
#include "cam/path.hpp"
#include "canon/sink.hpp"
#include "core/diagnostic.hpp"

namespace usina::cam {

using core::Vec3;

// The work's top face is Z0; depths are below it, heights above it.
struct Cutting {
  int tool = 1;
  double tool_diameter = 6.0;  // mm
  double feed = 600.0;         // mm/min, in the plane
  double plunge_feed = 200.0;  // mm/min, down into the work
  double rpm = 10000.0;
  double safe_z = 5.0;  // mm above the top, clear of clamps: every rapid in the plane is here
  // Not a cutting value but every generator's: the bound on its work (limits.hpp).
  double max_moves = kDefaultMaxMoves;
};

// Every check of `c` (the ranges of limits.hpp); true when all pass.
bool check_cutting(const Cutting& c, core::DiagnosticSink& diags);

// Reports an error of `code` with `message`; returns false (for `return fail(...)`).
bool fail(core::DiagnosticSink& diags, core::Code code, std::string message);

// The Z of each depth pass: n equal steps no deeper than `step` each, the
// last exactly at −depth (seed 002 eq. 4: n = depth / step rounded up, the
// step recomputed so all are equal). Depth and step must be above zero.
std::vector<double> depth_levels(double depth, double step);

class ProgramWriter {
 public:
  ProgramWriter(canon::Sink& sink, const Cutting& c) : sink_(sink), cut_(c) {}

  // A comment naming the program, the tool (with its diameter) and the spindle.
  void begin(const std::string& title);
  // Up to the safe Z, spindle off, program end.
  void end();

  // Up to the safe Z (when below it), then over to `xy` at the safe Z.
  void rapid_over(Vec2 xy);
  // Straight down (or up) to `z` at the plunge feed.
  void plunge(double z);
  // Up to the safe Z at rapid.
  void retract();
  void rapid(const Vec3& to);

  void feed(const Vec3& to);
  // An arc in the XY plane (a helix when `z` differs from the tool's Z).
  void arc(Vec2 to, Vec2 center, int turn, double z);
  // The path's segments at height z, from wherever the tool is (its start).
  void path(const Path& p, double z);

  void emit(canon::OpKind op);

  void set_origin(canon::Origin o) { origin_ = o; }

  Vec3 position() const { return pos_; }

  const Cutting& cutting() const { return cut_; }

 private:
  canon::Sink& sink_;
  Cutting cut_;
  Vec3 pos_;
  bool known_ = false;  // whether pos_ is where the tool is (not before the first move)
  canon::Origin origin_ = canon::Origin::Program;
};

}  // namespace usina::cam
