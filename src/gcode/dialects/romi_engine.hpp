// The block engine of the romi dialect (spec/romi.md): reads blocks with
// romi_syntax, looks every G and M code up in the dialect's table (code →
// group → handler name) and runs the handlers in the order of their groups,
// then the block's move. Geometry is worked in program coordinates (the
// programmed point, polar centres, the direction of travel); every point
// then goes through the transformation (rotation, scale, mirror), cutter
// compensation and the canonical machine shared with the RS274NGC
// interpreter.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "gcode/dialect.hpp"
#include "gcode/dialects/romi_syntax.hpp"
#include "gcode/expr.hpp"
#include "gcode/interp/canon_machine.hpp"
#include "gcode/interp/cutter_comp.hpp"

namespace usina::gcode::romi {

// A block's words other than G and M, after evaluation. A handler takes the
// letters it uses; a letter nobody took is an error.
class Words {
 public:
  struct Slot {
    bool present = false;
    bool lower = false;
    bool taken = false;
    double value = 0.0;
    std::uint32_t col = 0;
  };

  void reset() { slots_.fill({}); }

  bool has(char c) const { return at(c).present; }

  // Present and not yet taken by a handler.
  bool open(char c) const { return at(c).present && !at(c).taken; }

  double get(char c) const { return at(c).value; }

  bool lower(char c) const { return at(c).lower; }

  std::uint32_t col(char c) const { return at(c).col; }

  void set(char c, double v, bool lower, std::uint32_t col) {
    at(c) = {true, lower, false, v, col};
  }

  std::optional<double> take(char c) {
    Slot& s = at(c);
    if (!s.present) return std::nullopt;
    s.taken = true;
    return s.value;
  }

  // Letters a handler took are no longer the block's to move with.
  void forget_taken() {
    for (Slot& s : slots_) {
      if (s.taken) s.present = false;
    }
  }

  // The first letter present and not taken, or 0.
  char untaken() const {
    for (char c = 'A'; c <= 'Z'; ++c) {
      if (has(c) && !at(c).taken) return c;
    }
    return 0;
  }

 private:
  Slot& at(char c) { return slots_[static_cast<std::size_t>(c - 'A')]; }

  const Slot& at(char c) const { return slots_[static_cast<std::size_t>(c - 'A')]; }

  std::array<Slot, 26> slots_{};
};

// Mirror, scale, rotation: applied to a programmed point in the order
// rotation, scale, mirror (spec/romi.md, "Transformations").
struct Transform {
  bool mirror_x = false;  // X coordinates flip about X = mirror_at.x
  bool mirror_y = false;
  Vec2 mirror_at;
  double scale_x = 1.0;
  double scale_y = 1.0;
  double rotation_deg = 0.0;
  Vec2 rotation_at;

  Vec2 apply(Vec2 p) const;

  Vec3 apply(const Vec3& p) const {
    const Vec2 q = apply(Vec2{p.x, p.y});
    return {q.x, q.y, p.z};
  }

  // One axis mirrored: arcs and compensation sides swap.
  bool flips() const { return mirror_x != mirror_y; }

  bool uniform() const { return scale_x == scale_y; }
};

struct DrillCycle {
  bool active = false;
  double r = 0.0;      // approach plane above the work surface, mm
  double depth = 0.0;  // below the surface, mm
  double dwell = 0.0;  // s
  bool defined = false;
};

struct Fail {
  core::Code code;
  std::uint32_t col;
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

class Engine final : public ProgramRunner, private ParameterSource {
 public:
  Engine(const Dialect& dialect, RunContext context);

  void set_parameter(int index, double value) override;
  bool run(std::uint32_t file) override;

  // A handler: runs one code of the block (code in tenths).
  using Handler = bool (Engine::*)(int code);

  // Whether a handler of this name is registered (every name in the
  // dialect's table must be: a test checks).
  static bool knows_handler(std::string_view name) { return handlers().count(name) > 0; }

 private:
  // The handlers, by the names the dialect's table uses.
  static const std::unordered_map<std::string_view, Handler>& handlers();

  struct Cursor {
    std::uint64_t offset = 0;
    std::uint32_t line = 1;
    std::uint64_t line_start = 0;
  };

  struct Frame {
    bool call = false;  // (CALL n); otherwise (RPT ...)
    Cursor ret;
    double first = 0, last = 0;
    long remaining = 0;
  };

  struct IndexEntry {
    Cursor at;     // the block's start
    Cursor after;  // the next block's start
  };

  struct PendingBlend {
    core::SourceLoc loc;
    Vec2 center;
    double radius = 0.0;
    bool ccw = true;
    Vec3 start;
  };

  // ParameterSource: P0..P999 are read as named parameters "p<n>".
  double numbered(int index) const override;
  std::optional<double> named(std::string_view name) const override;

  // The block loop (romi_engine.cpp).
  void step();
  bool block();
  bool evaluate_words();
  bool place(char letter, int code, std::uint32_t col);
  bool values();
  bool statements(bool flow);
  bool error(core::Code code, std::uint32_t col, std::string message);

  bool error(const Fail& f) { return error(f.code, f.col, f.message); }

  bool error(const InterpError& e) { return error(e.code, 0, e.message); }

  void note(core::Code code, core::Severity sev, std::uint32_t col, std::string message);
  bool option_on(std::string_view name) const;
  const std::string& option(std::string_view name) const;

  double mm(double v) const { return v * core::mm_per(units_); }

  bool incremental(char letter) const;
  std::optional<double> take_whole(char letter, int lo, int hi);

  // Control flow of the parametric statements (romi_flow.cpp).
  void build_index();
  bool jump_to_block(double n, std::uint32_t col);
  bool after_block_number();
  bool run_statement(const Statement& st);
  bool count_jump();
  bool skip_to(std::uint64_t offset);

  // Handlers (romi_engine.cpp, romi_motion.cpp, romi_cycles.cpp).
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

  // Moves (romi_motion.cpp).
  bool move();
  std::optional<Vec3> line_end(const Vec3& start, Fail& fail) const;
  Vec3 cartesian_end(const Vec3& start) const;
  bool arc_block();
  bool arc_cartesian();
  bool arc_polar();
  bool blend(const Vec3& next_end);
  bool emit_line(const Vec3& end, bool rapid);
  bool emit_arc(const Vec3& end, Vec2 center, bool ccw, int turns);
  bool require_feed(const char* what);
  void in_order(std::function<void()> effect);

  // Cycles (romi_cycles.cpp).
  bool drill_at(Vec2 p);
  bool at_pattern_point(Vec2 p);
  bool ring(Vec2 c, double a, double b, double rr, double z);
  std::optional<double> tool_diameter_from_comments() const;

  // The G26 pocket's steps (romi_pocket.cpp).
  struct Pocket;
  bool pocket_allowed();
  bool read_pocket(Pocket& p);
  bool check_pocket(const Pocket& p);
  void emit_pocket_outline(const Pocket& p);
  bool cut_pocket(const Pocket& p);

  const Dialect& dialect_;
  core::SourceManager& sources_;
  InterpOptions options_;
  OptionValues dialect_options_;
  canon::Sink& sink_;
  core::DiagnosticSink& diags_;
  ModalState machine_state_;  // what the canonical machine reads: machine coordinates
  CanonMachine machine_;
  CutterComp comp_;

  RomiBlock block_;
  Words words_;
  std::vector<std::pair<const CodeEntry*, std::uint32_t>> codes_;  // this block's, by group
  core::SourceLoc loc_;
  std::uint32_t file_ = 0;
  Cursor cursor_;
  std::vector<Frame> frames_;
  std::optional<std::unordered_map<long, IndexEntry>> numbers_;
  std::unordered_map<long, Cursor> subs_;
  std::vector<std::uint64_t> returns_;  // offsets after each (RET) block
  std::array<double, kMaxParam + 1> params_{};
  long jumps_ = 0;
  bool ended_ = false;
  bool failed_ = false;
  bool moved_by_handler_ = false;

  // Modal state (program coordinates).
  int motion_ = 0;  // 0..3: G00..G03
  bool explicit_motion_ = false;
  bool incremental_ = false;
  core::LengthUnit units_ = core::LengthUnit::Mm;
  bool retract_to_r_ = true;
  DrillCycle drill_;
  Transform tf_;
  int offset_register_ = 0;
  Vec3 pos_;
  std::optional<double> direction_;  // of travel at pos_, degrees
  double feed_ = 0.0;
  int selected_tool_ = -1;
  double tool_diameter_ = 0.0;
  std::optional<PendingBlend> blend_;
};

}  // namespace usina::gcode::romi
