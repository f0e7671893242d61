// The fanuc dialect's runner: a Custom Macro B front end over the RS274NGC
// interpreter. It cuts the tape into blocks (fanuc_tape), runs the macro
// statements itself (variables with vacancy, IF, WHILE, GOTO, M98/M99,
// G65/G66), applies Fanuc's number rules and the transformations LinuxCNC
// lacks (G16 polar, G51 scaling, G51.1 mirror, G68 rotation), and hands
// each NC block to the interpreter as evaluated words (the one road below
// the text: interp/evaluated_block.hpp).
#pragma once

#include <array>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include <tl/expected.hpp>

#include "gcode/dialect.hpp"
#include "gcode/fanuc/macro.hpp"
#include "gcode/fanuc/polar_interp.hpp"
#include "gcode/fanuc/tape.hpp"

namespace usina::gcode {

// The fanuc dialect (fanuc/dialect.cpp) and its G/M table (fanuc/codes.cpp).
const Dialect& fanuc_dialect();
std::vector<CodeEntry> fanuc_codes();

}  // namespace usina::gcode

namespace usina::gcode::fanuc {

// The fanuc table resolved (the interpreter's handler names): the front end
// reads it for the control's M codes and the codes usina cannot run. The
// words it hands on are LinuxCNC's (G41 D becomes G41.1 D), so the
// interpreter below runs LinuxCNC's table.
const InterpCodes& code_table();

// A value as a message shows it: up to 10 decimals, no trailing zeros
// ("12.5", "-3", "0").
std::string word_number(double v);

// One word of an NC block after its value was read.
struct NcWord {
  char letter = 0;
  double value = 0.0;            // after the decimal-point rule
  double raw = 0.0;              // as written
  bool integer_literal = false;  // a number written without a point
  bool vacant = false;           // one vacant variable: the word is left out
  bool taken = false;            // used by the front end, not passed on
  std::size_t pos = 0;
  bool checked = false;  // its value as read is in range (word_out_of_range)
  // G in tenths, M whole, as read (kNoCode: not yet known, see Words::code).
  int code = kNoCode;

  static constexpr int kNoCode = -1;
};

struct Words {
  std::vector<NcWord> list;

  // A new word, built where it is kept: a word built on the stack and
  // copied in was read back 16 bytes at a time before its narrower fields'
  // stores had landed, a stalled store-to-load forward on every word of
  // every block (issue 19). Call added() once it is filled.
  NcWord& next() { return list.emplace_back(); }

  void added() {
    const NcWord& w = list.back();
    letters |= letter_bit(w.letter);
    if (w.letter == 'G') g_bits |= g_bit(code(w));
  }

  void add(const NcWord& w) {
    next() = w;
    added();
  }

  // A G word the front end adds (the modal motion of a block of axes only).
  void add_g(double g) {
    NcWord& w = next();
    w.letter = 'G';
    w.value = w.raw = g;
    added();
  }

  void clear() {
    list.clear();
    g_bits = 0;
    letters = 0;
  }

  // A word read as another address (G04's X is its P).
  void relabel(NcWord& w, char letter) {
    w.letter = letter;
    letters |= letter_bit(letter);
  }

  NcWord* find(char letter) {
    return (letters & letter_bit(letter)) != 0 ? lookup(letter) : nullptr;
  }

  NcWord* lookup(char letter);

  // A G word's code in tenths or an M word's whole code.
  static int code(const NcWord& w) { return w.code != NcWord::kNoCode ? w.code : code_of(w); }

  static int code_of(const NcWord& w);

  bool has(char letter) { return find(letter) != nullptr; }

  double get(char letter, double fallback);

  bool has_g(int tenths) const { return (g_bits & g_bit(tenths)) != 0 && holds_g(tenths); }

  bool has_m(int m) const { return (letters & letter_bit('M')) != 0 && holds_m(m); }

  void take_g(int tenths) {
    if ((g_bits & g_bit(tenths)) != 0) drop_g(tenths);
  }

  bool holds_g(int tenths) const;
  bool holds_m(int m) const;
  void drop_g(int tenths);
  void take_m(int m);
  void take(char letter);

  // A bit for each G code the block holds (shared by others) and for each
  // letter: a block is not searched for each of the dozens of codes and
  // addresses asked of it.
  static constexpr std::uint64_t g_bit(int tenths) {
    return std::uint64_t{1} << ((static_cast<std::uint32_t>(tenths) * 2654435761u) >> 26);
  }

  static constexpr std::uint32_t letters_of(std::string_view set) {
    std::uint32_t bits = 0;
    for (char c : set)
      bits |= letter_bit(c);
    return bits;
  }

  static constexpr std::uint32_t letter_bit(char letter) {
    return letter >= 'A' && letter <= 'Z' ? std::uint32_t{1} << (letter - 'A')
                                          : std::uint32_t{1} << 31;
  }

  std::uint64_t g_bits = 0;
  std::uint32_t letters = 0;
};

// The transformations, applied to programmed points in the order mirror,
// scaling, rotation (docs/fanuc.md §7): mirror and scaling per axis X Y Z,
// the rotation in the plane it was commanded in. One mirrored axis of the
// rotation plane turns the rotation the other way (the part is mirrored
// whole), and the rotation centre is mirrored and scaled with the part.
struct Transform {
  std::array<bool, 3> mirror{};
  core::Vec3 mirror_c{};
  bool scaling = false;
  core::Vec3 scale_c{}, scale{1, 1, 1};
  bool rotation = false;
  core::Plane rot_plane = core::Plane::XY;
  core::Vec3 rot_c{};  // programmed; its plane axes are the centre
  double rot_deg = 0;

  bool mirrored() const { return mirror[0] || mirror[1] || mirror[2]; }

  bool active() const { return mirrored() || scaling || rotation; }

  bool affects(int axis) const;  // the axis' value may change
  core::Vec3 mirror_scale(core::Vec3 p) const;
  core::Vec3 apply(core::Vec3 p) const;
  core::Vec3 inverse(core::Vec3 q) const;
  bool reverses(core::Plane plane) const;  // arcs and sides swap
};

std::array<Value, 34> vacant_locals();

// The G76/G87 shift of the `boring_shift` option (+x -x +y -y) as the value
// of parameter 5101 bits 5-4 RD2 RD1 (fanuc/parameters.cpp).
int boring_shift_bits(std::string_view option);

// Stored stroke check 2 (G22, docs/fanuc.md §7): sits between the
// interpreter and the run's sink, follows the tool through every move and,
// while an area is armed, stops the ops at the first move that enters the
// forbidden side; the engine reports it at that move's block.
class StrokeCheck final : public canon::Sink {
 public:
  struct Box {
    core::Vec3 lo, hi;  // trace coordinates, mm
  };

  struct Violation {
    core::SourceLoc loc;
    std::string message;
  };

  StrokeCheck(canon::Sink& next, core::Vec3 start) : next_(next), at_(start) {}

  void on(const canon::Op& op) override;

  void finish() override { next_.finish(); }

  bool stopped() const override { return next_.stopped(); }

  // Unarmed, only where the tool is matters, and it is asked for when an
  // area is armed: the straight moves of `usina check` go by unbuilt.
  bool reads_ops() const override { return area_.has_value() || next_.reads_ops(); }

  void pass(const core::SourceLoc& src) override {
    passed_ = true;
    next_.pass(src);
  }

  // `last_move_end`: where the interpreter's last move ended, the tool's
  // place when a move went by unbuilt since the last op read.
  void arm(Box area, core::Vec3 last_move_end) {
    if (passed_) at_ = last_move_end;
    passed_ = false;
    area_ = area;
  }

  void disarm() { area_.reset(); }

  bool armed() const { return area_.has_value(); }

  bool outside_forbidden = false;  // parameter 1300 bit 0 OUT
  // Why `p` is forbidden, as the error; a value when it is allowed.
  tl::expected<void, std::string> forbidden(core::Vec3 p) const;

  // Where the tool is, once arm() has run: unarmed, the moves that went
  // by unbuilt did not move it here.
  core::Vec3 position() const { return at_; }

  const std::optional<Violation>& violation() const { return violation_; }

 private:
  tl::expected<void, std::string> segment(core::Vec3 a, core::Vec3 b) const;
  tl::expected<void, std::string> path(const std::vector<core::Vec3>& points) const;
  canon::Sink& next_;
  core::Vec3 at_;
  bool passed_ = false;  // a move went by unbuilt since at_ was set
  std::optional<Box> area_;
  std::optional<Violation> violation_;
};

class Engine final : public ProgramRunner, private VariableSource, private CycleHooks {
 public:
  explicit Engine(RunContext& c);
  void set_parameter(int index, double value) override;
  bool run(std::uint32_t file) override;
  std::optional<std::vector<VarFileEntry>> persistent_variables() const override;

  std::optional<RunModes> modes() const override;

 private:
  struct Loop {
    TapePos do_block;
    TapePos end_block;
  };

  // Where a loop's END stands and where the block after it starts.
  struct LoopEnd {
    TapePos end_block;
    TapePos after;
  };

  struct Frame {
    TapePos ret;    // block after the call
    TapePos start;  // the called program's O block (its first block without one)
    TapePos body;   // first block of the called program
    long repeats_left = 0;
    bool macro = false;       // G65/G66: a new local level
    bool modal_call = false;  // G66: its blocks do not trigger the call
    std::vector<Loop> loops;
  };

  struct ModalCall {
    long program = 0;
    long repeats = 1;
    std::array<Value, 34> args{};
  };

  // Where a GOTO leads, found once per jump site, number and program: the
  // target and the loops (DO blocks) open around it.
  struct Jump {
    std::optional<TapePos> target;
    std::vector<std::uint64_t> open_loops;
  };

  using JumpKey = std::tuple<std::uint64_t, std::uint64_t, long>;  // site, from, number

  // Flow (fanuc/engine.cpp).
  bool step();
  bool ends_program(const TapeBlock& b);
  bool end_of_program(const TapeBlock& end);
  bool statement(const TapeBlock& b);
  bool assignment(MacroReader& r, const TapeBlock& b, bool run);
  bool goto_block(long n, const TapeBlock& b, std::size_t pos);
  const Jump& jump(long n, const TapeBlock& b);
  std::optional<TapePos> find_sequence(long n, TapePos from, TapePos start) const;
  bool while_do(MacroReader& r, const TapeBlock& b, std::optional<bool> cond);
  bool end_loop(MacroReader& r, const TapeBlock& b);
  std::optional<LoopEnd> find_end(const TapeBlock& do_block, int m);
  bool call(long program, long times, bool macro, const std::array<Value, 34>* args,
            const TapeBlock& b, std::size_t pos, bool modal);
  bool give_back(long sequence, const TapeBlock& b, std::size_t pos);
  std::optional<TapePos> find_program(long number);
  bool count_jump(const TapeBlock& b);

  std::vector<Loop>& loops() { return frames_.empty() ? main_loops_ : frames_.back().loops; }

  TapePos program_start() const { return frames_.empty() ? main_start_ : frames_.back().start; }

  // NC blocks (fanuc/nc.cpp).
  bool nc_block(const TapeBlock& b);
  bool read_words(const TapeBlock& b, Words& w);
  bool word_in_range(const TapeBlock& b, char letter, std::size_t at, const MacroReader& r,
                     const Value& v);
  void decimal_point(const TapeBlock& b, Words& w);
  double least_increment(char letter, bool inch) const;
  bool macro_call(const TapeBlock& b, Words& w);
  bool fanuc_codes(const TapeBlock& b, Words& w);
  bool convert_codes(const TapeBlock& b, Words& w);
  void cycle_levels(Words& w, bool incremental);

  // The initial level the interpreter's cycles took (mm on the plane's
  // normal), in force while its motion mode is a drilling cycle: in G91
  // R counts from it (interp/cycle_hooks.hpp).
  void cycle_ran(double initial_level_mm) override { cycle_level_ = initial_level_mm; }

  std::optional<double> cycle_level() const;
  std::optional<double> cycle_level_;
  // The hand-over: evaluated words down the interpreter's one road
  // (interp/evaluated_block.hpp), each at the column it was written at.
  bool hand_over(const TapeBlock& b, Words& w);
  // A plain move (most blocks of a long program) straight to the hand-over
  // (fanuc/plain_move.cpp).
  bool plain_modes() const;
  bool plain_move(const Words& w) const;
  bool plain_move_block(const TapeBlock& b, const Words& w);
  std::optional<bool> straight_block(const TapeBlock& b);
  bool plain_move_shortcut_ = true;
  bool hand(const TapeBlock& b, std::span<const EvaluatedWord> words);
  bool hand(const TapeBlock& b, std::initializer_list<EvaluatedWord> words);
  std::vector<EvaluatedWord> handed_;  // reused from block to block
  Words words_;                        // the NC block's words, reused likewise
  void group_one_motion(Words& w);
  // Words of real macros (fanuc_words.cpp). M codes that are not the
  // control's own go to the machine's logic: taken from the block, handed
  // on as machine_code ops.
  bool machine_codes(const TapeBlock& b, Words& w);
  void hand_on_machine_codes(const TapeBlock& b);
  bool machine_words(const TapeBlock& b, Words& w);
  bool look_ahead_modes(const TapeBlock& b, Words& w);
  bool skip_move(const TapeBlock& b, Words& w);
  std::optional<std::set<int>> machine_m_codes_;  // machine_m_codes option; none: all
  std::vector<canon::MachineCode> passed_m_;      // the block's, reused

  bool fine_boring(const TapeBlock& b, Words& w);
  std::array<Value, 34> arguments(Words& w);

  // Transformations (fanuc/transform.cpp).
  bool transform_codes(const TapeBlock& b, Words& w);
  bool transform_words(const TapeBlock& b, Words& w);

  // The interpreter's plane, or `plane`: not an optional plane, whose
  // flag written and read back as one word waited on the store (issue 19).
  void reset_program_point() { reset_program_point(interp_.state().plane); }

  void reset_program_point(core::Plane plane);
  core::Vec3 actual_xyz() const;
  core::Plane block_plane(const Words& w) const;
  void polar_point(const std::array<std::optional<NcWord>, 3>& axis, bool incremental,
                   core::Plane plane, core::Vec3& p);
  bool transformed_arc(const TapeBlock& b, Words& w, core::Plane plane,
                       const std::array<std::optional<NcWord>, 3>& centre, core::Vec3 start_prog);
  bool rotation_start(Words& w, core::Vec3 here);
  void check_after_rotation(const TapeBlock& b, const Words& w);

  // G12.1/G13.1 polar coordinate interpolation (fanuc/polar_nc.cpp).
  bool polar_interp_codes(const TapeBlock& b, Words& w);
  bool polar_interp_switch(const TapeBlock& b, Words& w, bool on, bool off);
  bool polar_interp_move(const TapeBlock& b, Words& w);
  // The axes outside the polar plane (X Y Z A B C): where they go, from, to.
  using PolarOthers = std::array<std::optional<std::pair<double, double>>, 6>;
  bool polar_pieces(const TapeBlock& b, const std::vector<PolarPoint>& points,
                    const PolarOthers& others, std::optional<double> feed);
  std::optional<core::Vec2> polar_interp_centre(const TapeBlock& b, Words& w, core::Vec2 from,
                                                core::Vec2 to, bool ccw);
  PolarAxes polar_axes_;  // polar_axes option (parameters 5460/5461)
  PolarInterp polar_interp_;

  // Offset registers (fanuc/offsets.cpp).
  bool read_offsets(const std::string& path);
  double offset_register(bool h, long n, const TapeBlock& b);
  bool offset_codes(const TapeBlock& b, Words& w);
  bool write_register(const TapeBlock& b, Words& w, long l);
  std::optional<double> register_variable(long index) const;
  std::map<long, std::array<double, 2>> h_regs_, d_regs_;  // geometry, wear
  std::set<long> warned_registers_;
  int length_sign_ = 0;           // G43 +1, G44 -1, G49 0
  bool offsets_written_ = false;  // a G10 or a work offset variable ran (RunModes)
  int comp_side_ = 40;
  long h_register_ = 0, d_register_ = 0;

  // Work coordinate systems: G54.1 P1-P48 kept here and selected through
  // the interpreter's G59.3 slot (Fanuc has no G59.1-G59.3), the external
  // work offset added to every system (fanuc/workspaces.cpp).
  bool work_codes(const TapeBlock& b, Words& w);
  bool work_offset(const TapeBlock& b, Words& w, long l);
  bool additional_offset(const TapeBlock& b, Words& w);
  bool external_offset(const TapeBlock& b, const Axes& value, const std::array<bool, 9>& given);
  bool load_additional(const TapeBlock& b);
  bool reselect(const TapeBlock& b);
  void apply_start_external();
  double program_units(int axis, double machine_value) const;
  double machine_units(int axis, double program_value) const;
  std::optional<double> work_variable(long index) const;
  std::optional<bool> write_work_variable(long index, double v, const TapeBlock& b);
  std::array<Axes, 49> additional_{};  // G54.1 P1-P48, machine units ([0] unused)
  Axes external_{};                    // EXT (#5201-), machine units
  long additional_p_ = 0;              // the active G54.1 P; 0 under G54-G59

  // G10 L50 ... G11 programmable parameter input (fanuc/parameters.cpp).
  bool parameter_block(const TapeBlock& b);
  bool set_fanuc_parameter(const TapeBlock& b, long number, Words& w);
  std::optional<double> parameter_length(const TapeBlock& b, const NcWord& r);
  std::optional<long> parameter_bits(const TapeBlock& b, long number, const NcWord& r,
                                     long modeled);
  bool parameter_mode_ = false;

  // 5114 and 5115: G73's back-off and G83's clearance, which the
  // interpreter asks for at each cycle (interp/cycle_hooks.hpp).
  PeckDistances peck_distances() const override { return pecks_; }

  PeckDistances pecks_;

  // G22/G23 stored stroke check 2 (fanuc/stroke.cpp).
  bool stroke_codes(const TapeBlock& b, Words& w);
  bool stroke_violation();
  bool reported_stroke_ = false;

  // Variables (fanuc/vars.cpp).
  std::optional<Value> read(long index, MacroError& err) override;
  bool write(long index, Value v, const TapeBlock& b, std::size_t pos);
  std::optional<double> system_variable(long index) const;
  double modal_group(int group) const;

  // Diagnostics.
  core::SourceLoc loc_of(const TapeBlock& b, std::size_t pos) const;
  bool error(core::Code code, const TapeBlock& b, std::size_t pos, std::string message);
  void warn(core::Code code, const TapeBlock& b, std::size_t pos, std::string message);
  bool macro_error(const MacroReader& r, const TapeBlock& b);

  core::SourceManager& sources_;
  InterpOptions options_;
  core::DiagnosticSink& diags_;
  StrokeCheck stroke_;  // the interpreter's ops go through it
  Interpreter interp_;
  bool dpi_fanuc_ = false;  // decimal_point=fanuc
  int program_digits_ = 4;

  Tape tape_;
  TapePos pc_;       // the next block
  TapeBlock block_;  // the block that runs (cut into, block after block)
  std::uint32_t main_file_ = 0;
  TapePos main_start_;
  bool main_started_ = false;  // a block with words or an O number was read
  // Where the last block read starts: cut again for a message at the end
  // (a copy of every block, read back whole, waited on its narrow stores).
  TapePos last_at_;
  bool read_any_ = false;
  std::map<std::uint64_t, LoopEnd> loop_ends_;         // by DO block
  std::map<JumpKey, Jump> jumps_;                      // GOTO
  std::map<JumpKey, std::optional<TapePos>> returns_;  // M99 P: site, return point, N
  bool done_ = false;
  bool failed_ = false;
  bool offsets_ok_ = true;
  bool warned_integer_ = false;
  long total_jumps_ = 0;
  std::map<std::uint64_t, long> loop_runs_;  // by DO block
  std::vector<Frame> frames_;
  std::vector<Loop> main_loops_;
  std::vector<std::array<Value, 34>> locals_;
  std::uint16_t inputs_ = 0;  // #1000-#1015 (#1032): interface input signals, from --var-file
  void input_signal(int index, double value);
  void input_signals(double value);
  std::map<long, Value> common_;  // #100-#199, #500-#999, writable system variables
  std::optional<ModalCall> modal_call_;

  // Modal values the interpreter does not keep in Fanuc's terms.
  int motion_ = 0;  // G00..G03 in tenths, as programmed
  double d_ = 0, h_ = 0, m_ = 0, n_ = 0, o_ = 0;
  int length_mode_ = 490, cycle_ = 800;
  // Fanuc keeps a cycle's R and Z as positions until G80 (§7, item 22b).
  std::optional<double> cycle_r_, cycle_z_, cycle_p_;

  struct FineBoring {
    std::optional<double> initial;  // R and Z are cycle_r_ and cycle_z_
    double q = 0, p = 0, f = 0;
    int shift = 0;  // parameter 5101 RD2 RD1 (bits 5 4): 0 +X, 1 -X, 2 +Y, 3 -Y in G17
  } g76_;

  bool fine_boring_holes(const TapeBlock& b, int code, bool to_r, core::Vec2 first, core::Vec2 step,
                         long repeats);

  Transform xf_;
  bool rotation_incremental_ = false;  // parameter 5400 RIN
  bool scale_z_by_p_ = false;          // parameter 5401 SCLZ
  bool polar_ = false;
  core::Plane polar_plane_ = core::Plane::XY;
  double polar_r_ = 0, polar_a_ = 0;
  core::Vec3 prog_{};  // the programmed point before the transformations
  // After G69 cancelled a rotation: its plane, until the first move in it.
  std::optional<core::Plane> after_g69_;
};

}  // namespace usina::gcode::fanuc
