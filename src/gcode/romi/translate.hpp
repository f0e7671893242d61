// Below the romi text: a block of evaluated words (interp/evaluated_block.hpp)
// checked by romi's table and run by romi's handlers, which hand the
// RS274NGC interpreter the block in its own words (DESIGN.md, "One road
// below the text"). Step 2 looks every G and M code up in the dialect's
// table by index (romi/codes.hpp) and checks groups and repeated letters;
// the handlers run in the order of their groups (table data: the groups'
// numbers), the block's move, and the groups after it.
//
// What romi shares with RS274NGC (F, S, T, M03-M09, M00-M30, G40-G42,
// straight moves and arcs) is handed as those words; romi's own forms are
// worked here in program coordinates (polar and tangent moves, the blend
// arc, the transformations, G81 as romi reads it, the G24/G25 patterns,
// the G26 pocket, M06's change position) and handed as absolute
// millimetres after the transformation: G21 G90 G90.1 and G0-G3 X Y Z,
// I J as the centre, G41.1/G42.1 D with the radius romi chose. The
// interpreter runs the machine: position, tool, spindle, coolant, cutter
// compensation, the canonical ops. Romi's modal state (romi/state.hpp) is
// a value: a block works on a copy, committed only when it succeeded.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "canon/sink.hpp"
#include "gcode/block.hpp"
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

// Marks the ops of the blocks handed while it lives as a cycle's or a tool
// change's (restored however the cycle ends).
class OpOrigin {
 public:
  OpOrigin(Interpreter& interp, canon::Origin origin) : interp_(interp) {
    interp_.set_origin(origin);
  }

  ~OpOrigin() { interp_.set_origin(canon::Origin::Program); }

  OpOrigin(const OpOrigin&) = delete;
  OpOrigin& operator=(const OpOrigin&) = delete;

 private:
  Interpreter& interp_;
};

// A closed rounded rectangle about c (half sizes a, b; corner radius rr),
// counter-clockwise from the middle of its right side.
canon::Outline rounded_rectangle(Vec2 c, double a, double b, double rr);

class Translator {
 public:
  // `interp`: the interpreter the blocks are handed to, made with
  // romi_rules(); `options`: the run's (its tool table is the user's).
  Translator(const CodeTable& codes, Services& run, const InterpOptions& options,
             const Options& dialect_options, Interpreter& interp);
  Translator(const Translator&) = delete;
  Translator& operator=(const Translator&) = delete;

  // The handler of a name of the dialect's table, or nullptr.
  static Handler handler_named(std::string_view name);

  // The program's start: the dialect's start codes, at `loc`.
  void start(const std::vector<CodeEntry>& start_codes, const core::SourceLoc& loc);

  // One block: its comments go out (in order with the moves compensation
  // holds), its words are sorted and checked, its codes and move run and
  // are handed over, then `after` (the front end's statements that end
  // the block: romi's jumps). The block's state is committed when all of
  // it succeeded, else put back as it was before the block. False after an
  // error (reported, by romi or by the interpreter).
  bool run_evaluated(const EvaluatedBlock& block, const std::function<bool()>& after = {});

  // A block of one plain move (most blocks of a long program; the engine
  // read it, Engine::plain_words), past the steps that would let it by:
  // its result as run_evaluated would give it, or nullopt when romi's modes
  // are not plain and the block takes the whole road (romi/plain_move.cpp).
  std::optional<bool> run_plain_move(const core::SourceLoc& loc, const PlainMove& move);

  // The end of the file without M02/M30: a pending blend is an error. The
  // front end then lets the interpreter finish (held moves go out). False
  // after an error.
  bool finish();

  bool ended() const { return interp_.ended(); }

  // The modal state between blocks.
  const Modal& state() const { return modal_; }

 private:
  bool error(core::Code code, std::uint32_t col, std::string message) {
    return run_.error(code, col, std::move(message));
  }

  bool error(const Fail& f) { return run_.error(f.code, f.col, f.message); }

  void note(core::Code code, core::Severity sev, std::uint32_t col, std::string message) {
    run_.note(code, sev, col, std::move(message));
  }

  // The block's loc for diagnostics and for the blocks handed over.
  void at(const core::SourceLoc& loc) { run_.at(loc); }

  double mm(double v) const { return work_.mm(v); }

  bool incremental(char letter) const {
    return work_.machine.incremental || words_.incremental(letter);
  }

  // The block's steps (romi/translate.cpp).
  void begin_block(const EvaluatedBlock& block);
  bool import(const EvaluatedWord& word);
  bool import_code(char letter, double value, std::uint32_t col);
  bool import_word(const EvaluatedWord& word);
  bool execute();
  void end_block(bool ok);

  // A plain move's steps (romi/plain_move.cpp): what its words set.
  struct PlainWords {
    GCode motion = -1;  // -1: no G word
    bool feed_given = false;
    double feed = 0.0;  // mm/min
    Vec3 end;           // absolute, program units in mm
  };

  bool plain_move_block(const core::SourceLoc& loc, const PlainWords& move);
  void end_plain_move(bool ok);

  std::optional<double> take_whole(char letter, int lo, int hi);
  bool values();

  // Handing over (romi/handover.cpp): words given wait in the block being
  // built; hand() runs it in the interpreter at the current block's loc.
  void give(char letter, double value) { pending_.push_back({letter, value, 0, false}); }

  bool hand();
  bool hand_comments();
  bool hand_move(int g, const Vec3& to);
  bool hand_arc(const Vec3& to, Vec2 center, bool ccw, int turns);

  Vec3 machine_position() const { return xyz(interp_.state().pos); }

  // Handlers (romi/translate.cpp, romi/motion.cpp, romi/cycles.cpp, romi/pocket.cpp).
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
  bool emit_pocket_outline(const Pocket& p);
  bool cut_pocket(const Pocket& p);

  const CodeTable& codes_;
  Services& run_;
  const InterpOptions& options_;
  Options dialect_options_;
  Interpreter& interp_;
  Modal modal_;                         // committed: the state between blocks
  Modal work_;                          // the block's copy; equal to modal_ between blocks
  std::vector<EvaluatedWord> pending_;  // the words of the block being handed over
  bool interp_failed_ = false;          // the interpreter refused a handed block

  // The block being run.
  Words words_;
  BlockCodes block_codes_;
  std::span<const CommentText> comments_;
  bool moved_by_handler_ = false;
};

// Where romi's control differs from LinuxCNC's below the entry: its M06
// leaves the spindle as it was, its comments are text (no "(MSG,"), its
// stop comment says M00.
DialectRules romi_rules();

}  // namespace usina::gcode::romi
