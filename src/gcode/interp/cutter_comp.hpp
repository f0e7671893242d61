// Cutter radius compensation (G40, G41, G42, G41.1, G42.1): the tool-centre
// path LinuxCNC's interpreter makes of a programmed contour, move by move,
// with its corner rules, its held move and its errors (LinuxCNC 2.10,
// src/emc/rs274ngc/interp_convert.cc convert_straight_comp1/2 and
// convert_arc_comp1/2, interp_queue.cc).
//
// How LinuxCNC does it, and so how this does it:
// - The first move after G41/G42 is the entry move. A straight entry ends a
//   tool radius from the programmed end, perpendicular to the entry move
//   itself, on the compensation side. An arc entry ends a tool radius from
//   the programmed end along the arc's radius, and runs from the tool's
//   current point on a circle whose centre is on that radius.
// - Every later move is offset by the tool radius: a straight move
//   sideways, an arc by changing its radius (centre kept). The move is held
//   until the next move in the plane is known, because the corner between
//   them decides where it ends:
//   - convex corner (the tool on the outside): the held move keeps its end
//     and an arc of the tool radius about the programmed corner joins it to
//     the next move (a straight traverse for G0);
//   - concave corner (the tool on the inside): the held move's end is moved
//     back to where the two offset paths intersect; an error if that makes
//     it run backwards ("gouging");
//   - within 0.05 rad of tangent: no arc, no intersection.
// - G40 releases the held move where it is; the move after G40 is an
//   ordinary move from there, and must be straight.
// - Compensation works in G17 (XY) and G18 (ZX: Z is "x", X is "y", as
//   LinuxCNC's lathe code sees it); moves with no motion in the plane are
//   held with the move before them.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "core/arc.hpp"
#include "core/diagnostic.hpp"
#include "core/vec3.hpp"
#include "gcode/interp/motion.hpp"

namespace usina::gcode {

// G41 keeps the tool left of the programmed path, G42 right (seen along the
// direction of motion, from the tip of the plane's normal).
enum class CompSide { Off, Left, Right };

// One per interpreter; a value (copyable), so a block can work on a copy.
//
// How the interpreter drives it (LinuxCNC's order of execution):
// - G41/G42/G41.1/G42.1 → start() before the block's motion; radius in mm
//   (tool table diameter / 2, or D / 2 for G41.1/G42.1).
// - While active(): every G0/G1 goes to straight(), every G2/G3 to arc(),
//   with the block's programmed end (and centre) in program coordinates
//   (mm, work coordinates). Omitted in-plane axes and G91 distances are
//   taken from the programmed point, not from where the tool is (LinuxCNC
//   find_ends): that is programmed_position(), which is also simply the end
//   of the last programmed block. Rapids are compensated too.
// - F, G93/G94/G95, G4, M3/M4/M5, S, M7/M8/M9, comments and messages while
//   holding(): give them to defer(), so they come out after the held move
//   and before the next one, as LinuxCNC's queue orders them (a changed F
//   applies to the next move, not to the held one).
// - G40 → stop() before the block's motion. Then the next move must be
//   straight: call straight()/arc() for it too (they pass moves through when
//   compensation is off and reject that arc), or check arc_allowed().
// - M0, M1, M60 → flush() (compensation stays on); M2, M30 → flush() then
//   reset(). A program that ends without them: flush() before the end.
// - MotionTarget::position() must be LinuxCNC's current point: the tool
//   position before the entry move, and after stop() the programmed end of
//   the last block (not the compensated end that was emitted).
// - Not allowed while active() (the interpreter's checks, as in LinuxCNC):
//   G17/G18/G19 changing the plane, M6, G43/G49, G92 and G5x changes, G28,
//   G30, G38, canned cycles, G33, G76, G5.x splines, G53, M62-M68.
class CutterComp {
 public:
  // Work the interpreter hands over to be done in order with held moves.
  using Deferred = std::function<void(MotionTarget&)>;

  // G41/G42 (radius from the tool table), G41.1/G42.1 (radius = D / 2).
  // A negative radius swaps the side; radius 0 compensates nothing.
  // `orientation` is a lathe tool's orientation (1-8; 0 and 9 for a mill),
  // honoured in G18: the emitted point is the tool's origin, not the centre
  // of its nose radius (LinuxCNC interp_queue.cc latheorigin_x/z).
  // `metric`: the program is in G21, where LinuxCNC lets a concave corner
  // lengthen an arc more (see kSweepSlack in cutter_comp.cpp).
  InterpResult start(CompSide side, double radius, core::Plane plane, int orientation = 0,
                     bool metric = false);

  // A programmed straight move (G0 when `rapid`, else G1) to `programmed_end`.
  InterpResult straight(const Vec3& programmed_end, bool rapid, const core::SourceLoc& loc,
                        MotionTarget& target);

  // A programmed arc (G2: turn < 0, G3: turn > 0; |turn| > 1 with P) to
  // `programmed_end` about `programmed_center`, found from the programmed
  // start; the axial part of the end makes a helix.
  InterpResult arc(const Vec3& programmed_end, const Vec3& programmed_center, int turn,
                   const core::SourceLoc& loc, MotionTarget& target);

  // Runs `op` now when no move is held, else after the held moves.
  void defer(const core::SourceLoc& loc, Deferred op, MotionTarget& target);

  // G40: releases the held moves where they end and turns compensation off.
  InterpResult stop(MotionTarget& target);

  // M0/M1/M2/M30/M60: releases the held moves where they end; compensation
  // stays as it is (the next corner then has nothing to trim).
  InterpResult flush(MotionTarget& target);

  // M2/M30 after flush(), and a new program: off, nothing held or pending.
  void reset() { *this = CutterComp{}; }

  bool active() const { return side_ != CompSide::Off; }

  CompSide side() const { return side_; }

  double radius() const { return radius_; }

  bool holding() const { return !queue_.empty(); }

  // False just after G40 until a straight move (LinuxCNC arc_not_allowed).
  bool arc_allowed() const { return !arc_not_allowed_; }

  // The programmed point while compensating (after the entry move); empty
  // when the tool position is the programmed point.
  std::optional<Vec3> programmed_position() const;

 private:
  enum class Kind { Traverse, Feed, Arc, Deferred };

  // A held move (tool centre, plane coordinates) or deferred work.
  struct Held {
    Kind kind = Kind::Feed;
    core::SourceLoc loc;
    Vec2 end;
    double axial = 0.0;
    // Straight: the direction a moved end must not reverse (LinuxCNC keeps
    // the programmed direction, or the offset normal for an entry move).
    Vec2 direction;
    // Arc: centre, its axial coordinate (the start's), turn, and the sweep
    // a moved end may not exceed (0: not checked).
    Vec2 center;
    double center_axial = 0.0;
    int turn = 0;
    double sweep = 0.0;
    Deferred op;
  };

  // The programmed arc of arc(), in plane coordinates.
  struct ArcIn {
    Vec2 end;
    Vec2 center;
    double axial = 0.0;
    int turn = 0;
  };

  static Held straight_move(Kind kind, const core::SourceLoc& loc, Vec2 end, double axial,
                            Vec2 direction = {});

  // An arc's centre, its axial coordinate (the start's) and its turn.
  struct About {
    Vec2 center;
    double axial = 0.0;
    int turn = 0;
  };

  static Held arc_move(const core::SourceLoc& loc, Vec2 end, double axial, const About& about,
                       double sweep);

  double side_sign() const { return side_ == CompSide::Left ? 1.0 : -1.0; }

  bool compensating() const { return active() && radius_ > 0.0; }

  bool tool_inside(int turn) const;
  bool not_beyond_radius(double length) const;
  double corner_turn(double into, double out_of) const;
  Vec3 to_program(Vec2 p, double axial) const;

  InterpResult pass_straight(const Vec3& end, bool rapid, const core::SourceLoc& loc,
                             MotionTarget& target);
  InterpResult entry_straight(Vec2 end, double axial, bool rapid, const core::SourceLoc& loc,
                              const MotionTarget& target);
  InterpResult next_straight(Vec2 end, double axial, bool rapid, const core::SourceLoc& loc,
                             MotionTarget& target);
  InterpResult entry_arc(const ArcIn& in, const core::SourceLoc& loc, const MotionTarget& target);
  InterpResult next_arc(const ArcIn& in, const core::SourceLoc& loc, MotionTarget& target);

  // Concave corners: where the held move must end.
  std::optional<Vec2> line_line_corner(double beta) const;
  std::optional<Vec2> arc_line_corner(Vec2 end) const;
  std::optional<Vec2> line_arc_corner(const ArcIn& in, double into) const;
  std::optional<Vec2> arc_arc_corner(const ArcIn& in) const;
  InterpResult trim_concave(std::optional<Vec2> corner, const char* what, MotionTarget& target);

  void hold(Held h) { queue_.push_back(std::move(h)); }

  void emit(const Held& h, MotionTarget& target) const;
  void release(MotionTarget& target);
  InterpResult move_end_and_release(Vec2 to, MotionTarget& target);
  InterpResult check_move_end(const Held& h, Vec2 to) const;
  void emit_corner(Vec2 to, Vec2 about, bool rapid, const core::SourceLoc& loc,
                   MotionTarget& target);

  CompSide side_ = CompSide::Off;
  double radius_ = 0.0;
  core::Plane plane_ = core::Plane::XY;
  int orientation_ = 0;
  bool metric_ = false;
  bool first_move_ = true;
  bool arc_not_allowed_ = false;
  // LinuxCNC's current point (tool centre) and programmed point, in the
  // plane, and their common axial coordinate.
  Vec2 tool_;
  Vec2 programmed_;
  double axial_ = 0.0;
  std::vector<Held> queue_;
  // Where the first held move starts, when known (LinuxCNC `endpoint`).
  std::optional<Vec2> queue_start_;
};

}  // namespace usina::gcode
