// The canonical operations: the one stream between front ends and back ends
// (DESIGN.md; the trace format of spec/trace.md). Plain data, absolute mm,
// after every offset, rotation, scale and mirror: what the tool centre does.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/vec3.hpp"

namespace usina::canon {

using core::Vec2;
using core::Vec3;

// Rotary axes A, B, C in degrees.
using Abc = std::array<double, 3>;

// A feed programmed other than in mm/min, as the program gave it: under G93
// the move takes 1/value minutes, under G95 it advances value mm per spindle
// revolution. A move's `f` is empty then; a post writes the move from this.
struct ProgrammedFeed {
  enum class Mode : unsigned char { PerMinute, InverseTime, PerRevolution };
  Mode mode = Mode::PerMinute;
  double value = 0.0;
};

struct Traverse {
  Vec3 to;
  Abc abc{};
};

struct Feed {
  Vec3 to;
  std::optional<double> f;  // mm/min; empty under inverse-time or per-revolution feed
  Abc abc{};
  ProgrammedFeed programmed{};
};

// Arc or helix about `center` (axial coordinate of the start), axis `normal`;
// turn > 0 counter-clockwise seen from the normal's tip, |turn| − 1 extra turns.
struct Arc {
  Vec3 to;
  Vec3 center;
  Vec3 normal;
  int turn = 1;
  std::optional<double> f;
  Abc abc{};
  ProgrammedFeed programmed{};
};

// A spline move (G5, G5.1, G5.2, G6.2): the curve linearised within the
// interpreter's tolerance, `points` ending at `to`. Its own op, as LinuxCNC's
// canon has NURBS_FEED besides STRAIGHT_FEED (whose traces do not record it).
struct Spline {
  Vec3 to;
  std::vector<Vec3> points;
  std::optional<double> f;
  ProgrammedFeed programmed{};
};

struct Probe {
  Vec3 to;
  Abc abc{};
};

struct Dwell {
  double s = 0.0;
};

struct ToolChange {
  int tool = 0;
  std::optional<double> diameter;  // mm
};

enum class SpindleDir { Cw, Ccw, Off };

struct Spindle {
  double rpm = 0.0;
  SpindleDir dir = SpindleDir::Off;
};

struct Coolant {
  bool mist = false;
  bool flood = false;
};

// How a bare hole (canon/bare_hole.hpp) is cut: drilled, out at rapid
// (G81); bored, fed back out to its top (G85: a boring bar's edge fed out
// does not mark the finished wall as a rapid would); bored with a dwell at
// the bottom, then fed out (G89: a blind bore's shoulder cleaned); bored,
// the spindle stopped at the bottom, out at rapid and started again (G86).
enum class HoleCycle { Drill, Bore, BoreDwell, BoreStop };

// A drilled hole (feature), emitted besides the moves that make it.
struct Hole {
  Vec3 at;  // centre of the hole at the top
  double diameter = 0.0;
  double depth = 0.0;
  HoleCycle cycle = HoleCycle::Drill;
  // mm/min the hole is cut at; empty: the last feed move's rate, as a
  // canned cycle's F carries over (the interpreter's holes). A generator
  // gives it, so the program need not feed to the R plane to set it.
  std::optional<double> f{};
  double dwell = 0.0;  // s at the bottom (BoreDwell)
};

// A closed outline: straight segments and arcs (turn ±1) from `start`.
struct OutlineSegment {
  Vec2 to;
  std::optional<Vec2> center;
  int turn = 0;
};

struct Outline {
  Vec2 start;
  std::vector<OutlineSegment> segs;
};

struct Pocket {
  Outline outline;
  double depth = 0.0;
};

struct Comment {
  std::string text;
};

struct ProgramEnd {};

// Path control (G61, G61.1, G64 P Q): how the control joins one move to the
// next, LinuxCNC's canon SET_MOTION_CONTROL_MODE and SET_NAIVECAM_TOLERANCE.
// Emitted where a block sets it; the interpreter starts in G64 without P.
struct PathMode {
  enum class Mode : unsigned char { ExactPath, ExactStop, Blend };  // G61, G61.1, G64
  Mode mode = Mode::Blend;
  double tolerance = 0.0;  // mm, G64 P; 0: none (as fast as the corners allow)
  double naive_cam = 0.0;  // mm, G64 Q (P when Q is absent): collinear lines merge within it
};

// A code the control hands to the machine's logic as it came (a Fanuc M
// code that is not the control's own: clamps, doors, pallets, probes):
// traced, drawn nowhere, written back by a post.
struct MachineCode {
  char letter = 'M';
  int code = 0;
  std::optional<double> p, q;  // its P and Q words ("M59 P2"), when it has them
};

using OpKind = std::variant<Traverse, Feed, Arc, Spline, Probe, Dwell, ToolChange, Spindle, Coolant,
                            Hole, Pocket, Comment, ProgramEnd, MachineCode, PathMode>;

// Why a move was made: the program's own contour, or the expansion of a
// canned cycle, pattern or pocket (a part drawing leaves those out and draws
// their `Hole`/`Pocket` feature), or a tool-change excursion.
enum class Origin : unsigned char { Program, Cycle, ToolChange };

struct Op {
  OpKind kind;
  core::SourceLoc src;  // the block that made it
  Origin origin = Origin::Program;
};

// The name of an op in the trace ("traverse", "feed", ...).
const char* op_name(const OpKind& kind);

// A path mode's G code ("G61", "G61.1", "G64") and a spindle's direction
// ("cw", "ccw", "off"), as the trace writes them.
const char* path_mode_code(PathMode::Mode m);
const char* spindle_dir_name(SpindleDir d);

// True for the ops that move the tool (traverse, feed, arc, spline, probe).
bool is_motion(const OpKind& kind);

}  // namespace usina::canon
