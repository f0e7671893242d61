// The fanuc dialect's runner: a Custom Macro B front end over the RS274NGC
// interpreter. It cuts the tape into blocks (fanuc_tape), runs the macro
// statements itself (variables with vacancy, IF, WHILE, GOTO, M98/M99,
// G65/G66), applies Fanuc's number rules and the transformations LinuxCNC
// lacks (G16 polar, G51 scaling, G51.1 mirror, G68 rotation), and hands
// each NC block, as RS274NGC words with numbers, to the interpreter.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "gcode/dialect.hpp"
#include "gcode/dialects/fanuc_macro.hpp"
#include "gcode/dialects/fanuc_tape.hpp"

namespace usina::gcode::fanuc {

// One word of an NC block after its value was read.
struct NcWord {
  char letter = 0;
  double value = 0.0;            // after the decimal-point rule
  double raw = 0.0;              // as written
  bool integer_literal = false;  // a number written without a point
  bool vacant = false;           // one vacant variable: the word is left out
  bool taken = false;            // used by the front end, not passed on
  std::size_t pos = 0;
};

struct Words {
  std::vector<NcWord> list;
  NcWord* find(char letter);

  bool has(char letter) { return find(letter) != nullptr; }

  double get(char letter, double fallback);
  bool has_g(int tenths) const;
  bool has_m(int m) const;
  void take_g(int tenths);
  void take_m(int m);
  void take(char letter);
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

class Engine final : public ProgramRunner, private VariableSource {
 public:
  explicit Engine(RunContext& c);
  void set_parameter(int index, double value) override;
  bool run(std::uint32_t file) override;

 private:
  struct Loop {
    std::size_t do_block;
    std::size_t end_block;
  };

  struct Frame {
    std::size_t ret = 0;   // block after the call
    std::size_t body = 0;  // first block of the called program
    std::size_t end = 0;   // exclusive
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

  // Flow (fanuc_engine.cpp).
  bool step();
  bool end_of_program();
  bool statement(const TapeBlock& b);
  bool assignment(MacroReader& r, const TapeBlock& b, bool run);
  bool goto_block(long n, const TapeBlock& b, std::size_t pos);
  bool while_do(MacroReader& r, const TapeBlock& b, std::optional<bool> cond);
  bool end_loop(MacroReader& r, const TapeBlock& b);
  std::size_t find_end(std::size_t do_block, int m, const TapeBlock& b);
  bool call(long program, long times, bool macro, const std::array<Value, 34>* args,
            const TapeBlock& b, std::size_t pos, bool modal);
  bool give_back(long sequence, const TapeBlock& b, std::size_t pos);
  std::size_t find_program(long number);
  bool count_jump(const TapeBlock& b);

  std::vector<Loop>& loops() { return frames_.empty() ? main_loops_ : frames_.back().loops; }

  // NC blocks (fanuc_nc.cpp).
  bool nc_block(const TapeBlock& b);
  bool read_words(const TapeBlock& b, Words& w);
  void decimal_point(const TapeBlock& b, Words& w);
  double least_increment(char letter, const Words& w) const;
  bool macro_call(const TapeBlock& b, Words& w);
  bool fanuc_codes(const TapeBlock& b, Words& w);
  bool convert_codes(const TapeBlock& b, Words& w);
  void cycle_levels(Words& w, bool incremental);
  bool hand_over(const TapeBlock& b, Words& w);
  void group_one_motion(Words& w);
  bool fine_boring(const TapeBlock& b, Words& w);
  std::array<Value, 34> arguments(Words& w);

  // Transformations (fanuc_transform.cpp).
  bool transform_codes(const TapeBlock& b, Words& w);
  bool transform_words(const TapeBlock& b, Words& w);
  void reset_program_point(std::optional<core::Plane> plane = std::nullopt);
  core::Vec3 actual_xyz() const;
  core::Plane block_plane(const Words& w) const;
  void polar_point(const std::array<std::optional<NcWord>, 3>& axis, bool incremental,
                   core::Plane plane, core::Vec3& p);
  bool transformed_arc(const TapeBlock& b, Words& w, core::Plane plane,
                       const std::array<std::optional<NcWord>, 3>& centre, core::Vec3 start_prog);
  bool rotation_start(Words& w, core::Vec3 here);

  // Offset registers (fanuc_offsets.cpp).
  bool read_offsets(const std::string& path);
  double offset_register(bool h, long n, const TapeBlock& b);
  bool offset_codes(const TapeBlock& b, Words& w);
  bool write_register(const TapeBlock& b, Words& w, long l);
  std::optional<double> register_variable(long index) const;
  std::map<long, std::array<double, 2>> h_regs_, d_regs_;  // geometry, wear
  std::set<long> warned_registers_;
  int length_sign_ = 0;  // G43 +1, G44 -1, G49 0
  int comp_side_ = 40;
  long h_register_ = 0, d_register_ = 0;

  // Variables (fanuc_vars.cpp).
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
  Interpreter interp_;
  bool dpi_fanuc_ = false;  // decimal_point=fanuc
  int program_digits_ = 4;

  Tape tape_;
  std::size_t pc_ = 0;
  std::uint32_t main_file_ = 0;
  std::size_t main_end_ = 0;
  bool done_ = false;
  bool failed_ = false;
  bool offsets_ok_ = true;
  bool warned_integer_ = false;
  long total_jumps_ = 0;
  std::map<std::size_t, long> loop_runs_;
  std::vector<Frame> frames_;
  std::vector<Loop> main_loops_;
  std::vector<std::array<Value, 34>> locals_;
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
};

}  // namespace usina::gcode::fanuc
