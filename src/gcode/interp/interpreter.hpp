// The RS274NGC interpreter (LinuxCNC's language): blocks in, canon ops out.
// Each block runs in four steps (grbl's order): evaluate its words, check
// them, plan the targets, execute in the standard's order of execution.
#pragma once

#include <algorithm>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "canon/sink.hpp"
#include "core/source.hpp"
#include "gcode/block.hpp"
#include "gcode/expr.hpp"
#include "gcode/interp/canned_cycles.hpp"
#include "gcode/interp/canon_machine.hpp"
#include "gcode/interp/codes.hpp"
#include "gcode/interp/cutter_comp.hpp"
#include "gcode/interp/cycle_hooks.hpp"
#include "gcode/interp/evaluated_block.hpp"
#include "gcode/interp/execution_order.hpp"
#include "gcode/interp/state.hpp"
#include "gcode/parameters.hpp"
#include "gcode/parser.hpp"
#include "gcode/program_index.hpp"
#include "gcode/run_services.hpp"
#include "gcode/tool_table.hpp"

namespace usina::gcode {

struct InterpOptions {
  core::LengthUnit machine_units = core::LengthUnit::Mm;  // of the tool table and parameters
  // G73's back-off and G83's clearance above the last peck, unless the
  // front end gives CycleHooks (cycle_hooks.hpp).
  double peck_clearance_mm = 1.0;
  std::vector<std::string> subroutine_path;  // folders searched for o<name> call
  long max_loop_iterations = 10'000'000;     // per run of a loop, so a runaway loop ends
  long max_total_iterations = 10'000'000;    // all loops of the program together
  int max_call_depth = 200;
  double spline_tolerance_mm = 0.001;
  bool block_delete = false;  // '/' blocks skipped (the operator's switch; off as in LinuxCNC)
  // G41/G42 are checked but offset nothing: the moves are the programmed
  // contour (what a part drawing shows), not the tool centre.
  bool ignore_cutter_comp = false;
  ToolTable tools;
  core::Vec3 start{};  // where the tool is when the program starts (usina draw --start)
  // A plain move (G0/G1 X Y Z F) by its shortcut (plain_move.cpp); off, by
  // the whole road, for the tests that compare the two.
  bool plain_move_shortcut = true;
};

// Where a control that runs on this interpreter differs from it: set by the
// dialect's runner (rs274ngc, grbl, fanuc), never by the user's options.
struct DialectRules {
  // The motion mode at the start, in tenths: LinuxCNC's G80; a controller
  // that powers up in another (Grbl: G0) sets it.
  GCode start_motion = 800;
  // A G54-G59.3 word for the system in use re-reads its offsets from the
  // parameters (Grbl; the fanuc front end re-selects to apply #5221...).
  // LinuxCNC's convert_coordinate_system does nothing then: a new value of
  // #5221... waits until the system is selected after another one.
  bool reselect_reloads_work_offsets = true;
  // An L word repeats G74 as any canned cycle (the fanuc front end hands its
  // K repeats on as L). LinuxCNC's check_other_codes leaves G74 out of the
  // codes that take L, so it refuses G74 ... L (2.9 and 2.10).
  bool g74_takes_l = true;
  // The dialect's G/M table resolved (interp/codes.hpp): which codes the
  // control has and their groups. Null: LinuxCNC's, the rs274ngc dialect's.
  const InterpCodes* codes = nullptr;
  // The order in which a block's parts run (execution_order.hpp). Null:
  // LinuxCNC's execute_block order.
  const ExecutionOrder* order = nullptr;
  // M6 stops a running spindle before the change (LinuxCNC). Romi's M06
  // changes the tool with the spindle as the program left it.
  bool tool_change_stops_spindle = true;
  // Comments go out as written: no blanks trimmed, no "(MSG," operator
  // message (romi's `;` comments; its control has no messages).
  bool comments_as_written = false;
  // The stop comment names the code with two digits, "M00 (program stop)",
  // as the control writes it (romi); LinuxCNC's trace says "M0".
  bool two_digit_stop_codes = false;
  // An I J K arc whose centre is nearer than this to its start or its end
  // is refused before its radii are compared: LinuxCNC's RADIUS_TOLERANCE
  // (0.00005 in, 0.00127 mm: "Zero-radius arc"). 0: only a centre on the
  // start point is (Grbl runs a tinier arc as a straight move).
  double min_arc_radius_mm = 0.0;
  // Calls (O-word and M98) that may be nested, when fewer than
  // InterpOptions::max_call_depth: LinuxCNC refuses a tenth level
  // (INTERP_SUB_ROUTINE_LEVELS, the main program counted), "Too many
  // subroutine levels". 0: max_call_depth alone.
  int max_call_nesting = 0;
};

struct BlockWords;

class Interpreter final : private ParameterSource {
 public:
  // `cycle_hooks`: a dialect's own cycle state (cycle_hooks.hpp: the peck
  // distances a program may change, the initial level); null for LinuxCNC's.
  // `rules`: where the dialect's control differs (DialectRules).
  Interpreter(core::SourceManager& sources, InterpOptions options, canon::Sink& sink,
              core::DiagnosticSink& diags, CycleHooks* cycle_hooks = nullptr,
              DialectRules rules = {});
  ~Interpreter() override;
  Interpreter(const Interpreter&) = delete;
  Interpreter& operator=(const Interpreter&) = delete;

  // Sets a numbered parameter before the run (a parameter file).
  void set_parameter(int index, double value) { params_.set(index, value); }

  // Runs the program in `file` to its end (M2/M30, '%' or end of file) or to
  // the first error. True when no error was reported.
  bool run(std::uint32_t file);

  const ModalState& state() const { return state_; }

  // The entry below the text (evaluated_block.hpp): steps 2-4 of one block
  // a front end has evaluated. The words are sorted into modal groups (an
  // unknown code, two codes of one group, a repeated word or a value out of
  // range is an error at its word), the assignments take effect, the block
  // is checked, planned and executed on a copy of the modal state that
  // replaces the state only when the block succeeded. False after an error
  // (reported; the run stops there). Interpreter::run() sends every block of
  // an RS274NGC program through it; a front end with its own reader calls it
  // block by block and ends with finish().
  bool run_evaluated(const EvaluatedBlock& block);

  // A plain move a front end has read already (PlainMove): the block's
  // result as run_evaluated would give it, past the words; nullopt when the
  // move or the interpreter's state is not plain (plain_move.cpp), and the
  // front end hands the words instead.
  std::optional<bool> run_plain_move(const core::SourceLoc& loc, const PlainMove& move);

  bool finish();
  // What run() does before the first block: the work offset and G92 a
  // parameter file holds are put in force. For a run of run_evaluated calls.
  void start_from_parameters();

  // For a front end that reports a refused block and reads on (Grbl's
  // "report and continue", grbl/runner.cpp): checkpoint() marks the state
  // before a block; roll_back() puts back what the block changed (modal
  // state, canonical machine, cycle values, numbered parameters, the
  // program end) after the block, or the front end's check of its ops,
  // refused it, and lets run_evaluated go on. Blocks of cutter compensation,
  // subroutines, loops and named parameters are not covered. The next
  // block run puts back the checkpoint's modal state if it fails (no copy
  // of its own): take the checkpoint just before that block. The copy is
  // made by the block's road: the whole state for run_evaluated, what a
  // plain move changes for run_plain_move.
  void checkpoint();
  void roll_back();

  bool ended() const { return ended_; }

  bool failed() const { return run_.failed(); }

  // For a front end whose control has cycles of its own (romi's G81, G24,
  // G25, G26 and its M06 with a change position), made of blocks it hands
  // over: the ops of those blocks are marked `origin`'s until it is set
  // back to Program; and the features such a cycle leaves, which no block
  // of words says (a hole, a pocket's outline, in program coordinates),
  // sent at `loc` in order with the moves.
  void set_origin(canon::Origin origin) { machine_.set_origin(origin); }

  void hole(const core::SourceLoc& loc, const Vec3& top, double depth);
  void pocket(const core::SourceLoc& loc, canon::Outline outline, double depth);

  const Parameters& parameters() const { return params_; }

  // Where the last move ended, as the ops give it (absolute, trace
  // coordinates), whether or not the sink built them. Only after a move.
  const Vec3& last_move_end() const { return machine_.last_absolute(); }

 private:
  struct Cursor {
    std::uint32_t file = 0;
    std::uint64_t offset = 0;
    std::uint32_t line = 1;
  };

  struct Frame {
    Cursor ret;
    std::string name;
    bool whole_file = false;  // a called file without o<name> sub
    bool fanuc = false;       // M98: returns at M99, no new parameter scope
    long repeats_left = 0;    // M98 L: further runs of the subprogram
    std::uint64_t body = 0;   // M98: where the subprogram's body starts
    std::uint32_t body_line = 0;
    std::uint32_t file = 0;
    std::optional<ModalState> autorestore;  // M73: restored on return
  };

  struct Checkpoint {
    ModalState state;
    CanonMachine machine;
    CannedCycles cycles;
    bool ended = false;
    std::vector<std::pair<int, double>> parameters;  // (index, value before) in write order
  };

  struct LoopCount {
    std::uint32_t file;
    std::uint32_t entry;
    long count;
  };
  enum class Flow { Next, Jumped, End, Error };

  // ParameterSource
  double numbered(int index) const override;
  std::optional<double> named(std::string_view name) const override;
  std::optional<double> predefined(std::string_view name) const;

  // The main loop and control flow (control.cpp).
  Flow step();
  Flow control(const OWord& o, std::uint64_t line_offset);
  Flow percent_line(const LinePos& where);  // percent.cpp
  Flow call(const OWord& o);

  // The calls that may be nested: the dialect's limit within the run's.
  int call_depth_limit() const {
    return rules_.max_call_nesting > 0 ? std::min(rules_.max_call_nesting, options_.max_call_depth)
                                       : options_.max_call_depth;
  }

  Flow leave_sub(const OWord& o);
  Flow branch(const ProgramIndex& idx, std::uint32_t e, const OWord& o);
  Flow loop(const ProgramIndex& idx, std::uint32_t e, const OWord& o);
  Flow loop_back(std::uint32_t e, const OEntry& target, bool after);
  Flow loop_while(const ProgramIndex& idx, std::uint32_t e, const OWord& o);
  Flow loop_repeat(const ProgramIndex& idx, std::uint32_t e, const OWord& o);
  Flow loop_end_repeat(const ProgramIndex& idx, std::uint32_t e, const OWord& o);
  Flow loop_break(const ProgramIndex& idx, std::uint32_t e, const OWord& o);
  Flow leave_loop(const ProgramIndex& idx, std::uint32_t e, std::uint32_t end);
  Flow missing_loop_end(const OWord& o, const char* what);
  Flow unmatched_loop_end(const OWord& o, const char* what);
  std::uint64_t loop_key(std::uint32_t start) const;
  void open_loop(std::uint32_t start);
  bool loop_is_open(std::uint32_t start) const;
  void forget_loop(std::uint32_t start);
  bool count_iteration();
  std::optional<bool> condition(const OWord& o);
  bool fanuc_call(const BlockWords& w);
  bool fanuc_return();
  std::optional<std::uint32_t> load_sub_file(const std::string& name);
  const ProgramIndex& index_of(std::uint32_t file);
  void jump_to(std::uint32_t file, const OEntry& e, bool after);
  bool end_of_file();

  // Step 1 of an RS274NGC block (evaluate.cpp): its values into
  // evaluated_ and assigns_.
  bool evaluate(const Block& b);
  bool evaluate_assigns(const Block& b);
  bool evaluation_failed(core::Code code, std::uint32_t col, std::string message);
  EvaluatedBlock evaluated(const Block& b) const;
  std::vector<EvaluatedWord> evaluated_;
  std::vector<EvaluatedAssign> assigns_;

  // Steps 2-4 (interpreter.cpp, check.cpp, execute.cpp).
  bool sort_words(std::span<const EvaluatedWord> words, BlockWords& w);
  bool sort_word(const EvaluatedWord& word, BlockWords& w);
  [[gnu::noinline]] bool word_refused(const EvaluatedWord& word, core::Code why);
  bool assign(std::span<const EvaluatedAssign> assigns);
  bool place_g(BlockWords& w, GCode g, std::uint32_t col);
  bool place_m(BlockWords& w, int m, std::uint32_t col);
  bool check(BlockWords& w);
  bool check_unused(const BlockWords& w);
  bool check_increments(const BlockWords& w);
  // Step 4 in the dialect's order (execute.cpp, execution_order.hpp).
  bool execute(std::span<const CommentText> notes, BlockWords& w);
  // execute(), and the modal state put back to `before` if it fails.
  bool execute_from(const ModalState& before, std::span<const CommentText> notes, BlockWords& w);
  // The block run by the plain-move shortcut, its result; nullopt when it is
  // not plain in every respect (plain_move.cpp).
  std::optional<bool> plain_move(const EvaluatedBlock& block);
  bool plain_state() const;
  bool plain_move_run(GCode motion, std::optional<double> feed, const Axes& end);
  static bool plain_moves_allowed(const InterpOptions& options, const InterpCodes& codes,
                                  const ExecutionOrder& order);
  bool run_step(ExecStep step, std::span<const CommentText> notes, BlockWords& w);
  bool comments(std::span<const CommentText> notes);
  void feed_mode(const BlockWords& w);
  bool feed(const BlockWords& w);
  bool speed(const BlockWords& w);
  bool select_tool(const BlockWords& w);
  bool change_tool(const BlockWords& w);
  void spindle(const BlockWords& w);
  void coolant(const BlockWords& w);
  void overrides(const BlockWords& w);
  void user_m_codes(const BlockWords& w);
  bool dwell(const BlockWords& w);
  void resync_after_tool_change();
  bool modal_setting(ExecStep step, BlockWords& w);
  bool coord_system(const BlockWords& w);
  bool path_control(const BlockWords& w);
  bool modal_zero(BlockWords& w);
  bool subprogram(const BlockWords& w);
  bool stop(const BlockWords& w);
  bool modal_save_restore(const BlockWords& w);
  void restore_modal(const ModalState& saved);
  std::optional<ModalState> saved_modal_;  // M70
  bool set_units(core::LengthUnit u);
  bool select_coord_system(int n);
  bool tool_length(BlockWords& w);
  bool cutter_comp_mode(BlockWords& w);
  bool g10(BlockWords& w);
  bool g92(BlockWords& w);
  bool home(BlockWords& w, int g);
  void apply_work_offsets(int n);
  bool offset_in_range(const char* what, char letter, double value, std::uint32_t col);
  void write_g92_params();

  // Motion (motion_exec.cpp).
  bool motion(BlockWords& w);
  Axes target(const BlockWords& w, bool machine_coords) const;
  bool straight(BlockWords& w, GCode g, const Axes& end);
  bool arc(BlockWords& w, GCode g, const Axes& end);
  bool arc_in_range(const BlockWords& w, Vec2 start, Vec2 stop, Vec2 center, int first_axis,
                    int second_axis);
  std::optional<Vec2> radius_arc_center(const BlockWords& w, Vec2 start, Vec2 stop, bool ccw,
                                        char first, char second);
  std::optional<Vec2> offset_arc_center(const BlockWords& w, GCode g, Vec2 start, Vec2 stop,
                                        char first, char second);
  bool probe(BlockWords& w, const Axes& end);
  bool cycle(BlockWords& w, GCode g, GCode previous);
  bool spline(BlockWords& w, GCode g, const Axes& end);
  bool require_feed(const BlockWords& w);

  // A word's value as a whole number within [lo, hi] (within 1e-4 of one,
  // as LinuxCNC reads integers); reports E_BAD_WORD_VALUE otherwise.
  std::optional<int> whole(const BlockWords& w, char letter, int lo, int hi);

  bool error(core::Code code, std::uint32_t col, std::string message) {
    return run_.error(code, col, std::move(message));
  }

  bool error(const InterpError& e, std::uint32_t col = 0) { return run_.error(e, col); }

  bool machine_faulted();

  void warn(core::Code code, std::uint32_t col, std::string message) {
    run_.warn(code, col, std::move(message));
  }

  double mm(double program_value) const { return program_value * core::mm_per(state_.units); }

  double machine_mm() const { return core::mm_per(options_.machine_units); }

  double tool_diameter(int tool) const;

  core::SourceManager& sources_;
  InterpOptions options_;
  DialectRules rules_;
  const InterpCodes& codes_;     // rules_.codes, or the rs274ngc table
  const ExecutionOrder& order_;  // rules_.order, or LinuxCNC's
  CycleHooks* cycle_hooks_;
  canon::Sink& sink_;
  RunServices run_;  // the block diagnostics point at, failure, the budget of jumps
  ModalState state_;
  Parameters params_;
  CanonMachine machine_;
  CutterComp comp_;
  CannedCycles cycles_;
  std::optional<Checkpoint> checkpoint_;
  // A checkpoint taken since the last block: that block's failure puts the
  // state back from it, without a copy of its own (interpreter.cpp).
  bool checkpoint_fresh_ = false;

  // What a plain move changes (run_plain_move), all a checkpoint copies
  // before one: the whole state is a few hundred bytes, a tenth of Grbl's
  // check of a plain line (issue 19).
  struct PlainMark {
    GCode motion;
    double feed;
    Axes pos;
    std::optional<double> initial_level;
    CanonMachine::MoveMark machine;
  };
  // checkpoint() asked, its copy not yet made: the block's road makes the
  // one it needs (take_checkpoint, or a PlainMark).
  enum class Marked { None, Pending, Whole, Plain };
  Marked marked_ = Marked::None;
  PlainMark plain_mark_{};
  void take_checkpoint();
  void mark_plain_move();
  // Runs `effect` now, or after the move cutter compensation holds.
  void in_order(std::function<void()> effect);
  bool comp_forbids(const BlockWords& w);
  Block block_;
  std::unique_ptr<BlockWords> words_;
  Cursor cursor_;
  std::vector<Frame> frames_;
  std::vector<LoopCount> loops_;
  std::unordered_map<std::uint64_t, long> iterations_;
  std::uint32_t pending_elseif_ = kNoEntry;
  bool at_eof_ = false;
  bool tool_changed_ = false;
  bool plain_moves_ = false;  // plain_moves_allowed(), asked once
  std::unordered_map<std::uint32_t, ProgramIndex> indexes_;
  std::unordered_map<std::string, std::uint32_t> sub_files_;
  bool percent_mode_ = false;
  bool ended_ = false;
  double value_ = 0.0;
  bool value_returned_ = false;
  // Sticky spline state: the previous G5's second control point, for a G5 without I J.
  std::optional<Vec2> last_g5_ctrl_;
  // A NURBS block being read (G5.2 ... G5.3): control points and weights.
  std::vector<Vec2> nurbs_points_;
  std::vector<double> nurbs_weights_;
  int nurbs_order_ = 0;
  void emit_polyline(const std::vector<Vec2>& pts);
  bool nurbs_g6(BlockWords& w, const Axes& end);

  struct G6Curve {
    int order = 0;
    std::vector<Vec2> points;
    std::vector<double> weights;
    std::vector<double> knots;
  } g6_;
};

}  // namespace usina::gcode
