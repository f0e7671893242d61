// Below the romi text: runs a block of evaluated words (steps 2-4 of
// DESIGN.md's interpreter). The front end (romi/engine.cpp) hands it the
// entry every dialect hands its runner below the text, an EvaluatedBlock
// (interp/evaluated_block.hpp), with romi's lower-case words marked as
// increments. Step 2 looks every G and M code up in the dialect's table by
// index (romi/codes.hpp) and checks groups and repeated letters; step 4
// runs the handlers in the order of their groups (table data: the groups'
// numbers), the block's move, and the groups after it. The block works on
// a copy of the modal state (romi/state.hpp), committed only when the
// block succeeded.
//
// Geometry is worked in program coordinates (the programmed point, polar
// centres, the direction of travel); every point then goes through the
// transformation (rotation, scale, mirror), cutter compensation and the
// canonical machine shared with the RS274NGC interpreter.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "canon/sink.hpp"
#include "gcode/block.hpp"
#include "gcode/interp/canon_machine.hpp"
#include "gcode/interp/evaluated_block.hpp"
#include "gcode/interp/interpreter.hpp"
#include "gcode/romi/codes.hpp"
#include "gcode/romi/services.hpp"
#include "gcode/romi/state.hpp"
#include "gcode/romi/words.hpp"

namespace usina::gcode::romi {

// Groups from this number on run after the block's move (romi/dialect.cpp).
inline constexpr int kAfterMoveGroup = 60;

struct Fail {
  core::Code code = core::Code::Unsupported;
  std::uint32_t col = 0;
  std::string message;
};

// Marks the ops emitted while it lives as a cycle's (restored however the
// cycle ends).
class CycleOrigin {
 public:
  explicit CycleOrigin(CanonMachine& m) : m_(m) { m_.set_origin(canon::Origin::Cycle); }

  ~CycleOrigin() { m_.set_origin(canon::Origin::Program); }

  CycleOrigin(const CycleOrigin&) = delete;
  CycleOrigin& operator=(const CycleOrigin&) = delete;

 private:
  CanonMachine& m_;
};

// A closed rounded rectangle about c (half sizes a, b; corner radius rr),
// counter-clockwise from the middle of its right side.
canon::Outline rounded_rectangle(Vec2 c, double a, double b, double rr);

class Executor {
 public:
  Executor(const CodeTable& codes, Services& run, const InterpOptions& options,
           const Options& dialect_options, canon::Sink& sink, core::DiagnosticSink& diags);
  Executor(const Executor&) = delete;
  Executor& operator=(const Executor&) = delete;

  // The handler of a name of the dialect's table, or nullptr.
  static Handler handler_named(std::string_view name);

  // The program's start: the dialect's start codes, at `loc`.
  void start(const std::vector<CodeEntry>& start_codes, const core::SourceLoc& loc);

  // Steps 2-4 of one block: its comments go out (in order with the moves
  // compensation holds), its words are sorted and checked, its codes and
  // move run, then `after` (the front end's statements that end the block:
  // romi's jumps). The block's state is committed when all of it succeeded
  // (and the machine sent every op), else put back as it was before the
  // block. False after an error (reported).
  bool run_evaluated(const EvaluatedBlock& block, const std::function<bool()>& after = {});

  // The end of the file without M02/M30: a pending blend is an error, held
  // moves go out. False after an error.
  bool finish();

  bool ended() const { return ended_; }

  // The canonical machine refused an op (reported already).
  bool faulted() const { return machine_.faulted(); }

  // The modal state between blocks.
  const Modal& state() const { return modal_; }

 private:
  bool error(core::Code code, std::uint32_t col, std::string message) {
    return run_.error(code, col, std::move(message));
  }

  bool error(const Fail& f) { return run_.error(f.code, f.col, f.message); }

  bool error(const InterpError& e) { return run_.error(e); }

  void note(core::Code code, core::Severity sev, std::uint32_t col, std::string message) {
    run_.note(code, sev, col, std::move(message));
  }

  // The block's loc for diagnostics and ops.
  void at(const core::SourceLoc& loc) {
    run_.at(loc);
    machine_.set_source(loc);
  }

  double mm(double v) const { return work_.mm(v); }

  bool incremental(char letter) const {
    return work_.machine.incremental || words_.incremental(letter);
  }

  // The block's steps (romi/exec.cpp).
  void begin_block(const EvaluatedBlock& block);
  void comments();
  bool import(const EvaluatedWord& word);
  bool import_code(char letter, double value, std::uint32_t col);
  bool import_word(const EvaluatedWord& word);
  bool execute();
  void end_block(bool ok);

  std::optional<double> take_whole(char letter, int lo, int hi);
  bool values();
  void in_order(std::function<void()> effect);

  // Handlers (romi/exec.cpp, romi/motion.cpp, romi/cycles.cpp, romi/pocket.cpp).
  bool h_motion(int code);
  bool h_plane(int code);
  bool h_distance(int code);
  bool h_units(int code);
  bool h_retract(int code);
  bool h_comp(int code);
  bool h_cycle(int code);
  bool h_mirror(int code);
  bool h_scale(int code);
  bool h_rotate(int code);
  bool h_grid(int code);
  bool h_bolt_circle(int code);
  bool h_pocket(int code);
  bool h_tool_change(int code);
  bool h_spindle(int code);
  bool h_coolant(int code);
  bool h_stop(int code);
  bool h_end(int code);

  // Moves (romi/motion.cpp).
  bool move();
  std::optional<Vec3> line_end(const Vec3& start, Fail& fail) const;
  std::optional<Vec2> polar_end(Vec2 p0, Fail& fail) const;
  Vec3 cartesian_end(const Vec3& start) const;
  bool arc_block();
  bool arc_cartesian();
  bool arc_polar();
  bool tangent_arc(Vec2 p0, bool ccw);
  bool swept_arc(Vec2 p0, Vec2 center, double sweep, bool ccw);
  bool blend(const Vec3& next_end);
  bool emit_line(const Vec3& end, bool rapid);
  bool emit_arc(const Vec3& end, Vec2 center, bool ccw, int turns);
  bool require_feed(const char* what);

  // Cycles (romi/cycles.cpp).
  bool drill_at(Vec2 p);
  bool at_pattern_point(Vec2 p);
  bool ring(Vec2 c, double a, double b, double rr, double z);
  std::optional<double> tool_diameter_from_comments() const;

  // The G26 pocket's steps (romi/pocket.cpp).
  struct Pocket;
  bool pocket_allowed();
  bool read_pocket(Pocket& p);
  bool check_pocket(const Pocket& p);
  void emit_pocket_outline(const Pocket& p);
  bool cut_pocket(const Pocket& p);

  const CodeTable& codes_;
  Services& run_;
  const InterpOptions& options_;
  Options dialect_options_;
  Modal modal_;           // committed: the state between blocks
  Modal work_;            // the block's copy; equal to modal_ between blocks
  CanonMachine machine_;  // reads and moves work_.machine

  // The block being run.
  Words words_;
  BlockCodes block_codes_;
  std::span<const CommentText> comments_;
  bool moved_by_handler_ = false;
  bool ended_ = false;
};

}  // namespace usina::gcode::romi
