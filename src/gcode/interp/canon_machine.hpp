// The interpreter's canonical machine: takes moves in program coordinates and
// emits canon ops in absolute mm after G92, XY rotation and the work offset
// (the order LinuxCNC's canon layer applies them), each attributed to a block.
// It is the canon boundary of every G-code dialect: an op with a number out
// of canon's range (canon/limits.hpp) is not sent but reported
// (E_VALUE_OUT_OF_RANGE at its block), as is an arc too flat to tell from a
// full circle, and the machine sends nothing more:
// its owner ends the run at the error, as a control stops at an alarm.
#pragma once

#include <string>

#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "gcode/interp/motion.hpp"
#include "gcode/interp/state.hpp"

namespace usina::gcode {

class CanonMachine final : public MotionTarget {
 public:
  CanonMachine(canon::Sink& sink, ModalState& state, core::DiagnosticSink& diags)
      : sink_(&sink), state_(&state), diags_(&diags) {}

  // The state the machine reads (offsets, feed) and updates (position).
  void bind(ModalState& state) { state_ = &state; }

  void traverse(const Vec3& to) override;
  void feed(const Vec3& to) override;
  void arc(const Vec3& to, const Vec3& center, int turn) override;
  void dwell(double seconds) override;
  void spindle(canon::SpindleDir dir) override;
  void hole(const Vec3& top, double depth) override;

  Vec3 position() const override { return xyz(state_->pos); }

  void set_source(const core::SourceLoc& loc) override { src_ = loc; }

  // The end of the last move sent, in today's program coordinates (the
  // current point if nothing moved yet).
  Vec3 last_emitted() const { return moved_ ? to_program(last_) : xyz(state_->pos); }

  // The same point as it went out, in absolute (trace) coordinates: a move
  // that went by unbuilt (Sink::pass) still set it. Only after a move.
  const Vec3& last_absolute() const { return last_; }

  // Moves with every axis (rotary and UVW too).
  void traverse_axes(const Axes& to);
  void feed_axes(const Axes& to);
  // `stop`: where the probe ends (program coordinates), short of `to`.
  void probe_axes(const Axes& to, const Vec3& stop);
  // A spline through `points` (program coordinates, the last one its end).
  void spline(const std::vector<Vec3>& points);
  void arc_axes(const Axes& to, const Vec3& center, int turn);
  void emit(canon::OpKind kind);

  const core::SourceLoc& source() const { return src_; }

  // An op was refused for a number out of range (reported already).
  bool faulted() const { return faulted_; }

  // What the ops emitted from now on are for (Origin::Cycle inside a cycle).
  void set_origin(canon::Origin origin) { origin_ = origin; }

  // The feed rate in effect for the moves emitted from now on (the
  // interpreter's F may wait behind a move held by cutter compensation).
  void set_feed(double feed, FeedMode mode) {
    feed_ = feed;
    feed_mode_ = mode;
  }

  // What a straight move (traverse_axes, feed_axes after set_feed and
  // set_source) changes in the machine: taken before it, put back when its
  // block is refused (Interpreter::roll_back after a plain move).
  struct MoveMark {
    double feed;
    FeedMode feed_mode;
    bool moved;
    bool faulted;
    Vec3 last;
    core::SourceLoc src;
  };

  MoveMark mark() const { return {feed_, feed_mode_, moved_, faulted_, last_, src_}; }

  void put_back(const MoveMark& m) {
    feed_ = m.feed;
    feed_mode_ = m.feed_mode;
    moved_ = m.moved;
    faulted_ = m.faulted;
    last_ = m.last;
    src_ = m.src;
  }

  // Diameter of the tool in the spindle, for hole features.
  void set_tool_diameter(double mm) { hole_diameter_ = mm; }

  // Program coordinates → absolute (trace) coordinates.
  Vec3 to_absolute(const Vec3& p) const;
  // The inverse: absolute → program coordinates.
  Vec3 to_program(const Vec3& abs) const;

 private:
  // Reports why an op cannot be sent; nothing is sent from then on.
  void refuse(const std::string& why);
  // A straight move: built into an op only for a sink that reads ops.
  template <class Move>
  void send(Move&& move);
  std::optional<double> feed_rate() const;
  canon::ProgrammedFeed programmed_feed() const;

  canon::Abc abc_of(const Axes& a) const { return {a[3], a[4], a[5]}; }

  // Pointers, so a copy of the machine can be assigned back (Interpreter::roll_back).
  canon::Sink* sink_;
  ModalState* state_;
  core::DiagnosticSink* diags_;
  bool faulted_ = false;
  core::SourceLoc src_;
  canon::Origin origin_ = canon::Origin::Program;
  double hole_diameter_ = 0.0;
  double feed_ = 0.0;
  Vec3 last_;  // absolute
  bool moved_ = false;
  FeedMode feed_mode_ = FeedMode::UnitsPerMinute;
};

}  // namespace usina::gcode
