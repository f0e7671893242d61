// Builds a Drawing from the canon stream, seen from above (the XY plane).
//
// Part view: what the part looks like, as seed 000 draws it: the programmed
// contour on CONTOUR (run the interpreter with cutter compensation left
// out), rapids on RAPID, each Hole a circle of its diameter on HOLES, each
// Pocket its outline on POCKETS; the moves a canned cycle, pattern, pocket
// or tool change made (Origin other than Program) are left out.
// Toolpath view: every move, feeds on one layer per tool (TOOLPATH_T<n>),
// rapids on RAPID; features are not drawn (their moves are).
#pragma once

#include "canon/sink.hpp"
#include "core/vec3.hpp"
#include "draw/drawing.hpp"

namespace usina::draw {

enum class View { Part, Toolpath };

class DrawingBuilder final : public canon::Sink {
 public:
  // `start`: where the tool is before the first move.
  DrawingBuilder(Drawing& drawing, View view, core::Vec3 start = {});

  void on(const canon::Op& op) override;

  // Chordal tolerance of arcs out of the XY plane, drawn as polylines (mm).
  static constexpr double kArcTolerance = 0.01;

 private:
  void traverse(const core::Vec3& to, canon::Origin origin);
  void feed(const core::Vec3& to, canon::Origin origin);
  void arc(const canon::Arc& a, canon::Origin origin);
  void spline(const canon::Spline& s, canon::Origin origin);
  void hole(const canon::Hole& h);
  void pocket(const canon::Pocket& p);

  // The layer a feed move of `origin` goes on; nullptr when the view leaves
  // it out.
  Layer* feed_layer(canon::Origin origin);

  Drawing& drawing_;
  View view_;
  core::Vec3 pos_;
  int tool_ = 0;
  Layer* tool_layer_ = nullptr;  // TOOLPATH_T<tool_>, made on first use
  // The layers of the view, looked up once.
  Layer* contour_ = nullptr;
  Layer* rapid_ = nullptr;
  Layer* holes_ = nullptr;
  Layer* pockets_ = nullptr;
};

}  // namespace usina::draw
