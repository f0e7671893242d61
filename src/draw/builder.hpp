// Builds a Drawing from the canon stream, seen from above (the XY plane).
//
// Part view: what the part looks like, as seed 000 draws it: the programmed
// contour on CONTOUR (run the interpreter with cutter compensation left
// out), rapids on RAPID, each Hole a circle of its diameter on HOLES, each
// Pocket its outline on POCKETS; the moves a canned cycle, pattern, pocket
// or tool change made (Origin other than Program) are left out.
// Toolpath view: every move, feeds on one layer per tool (TOOLPATH_T<n>),
// rapids on RAPID; features are not drawn (their moves are).
//
// The drawing is bounded by what a picture can show: a move that retraces
// one of the last DrawLimits::retrace_window / 2 (up to retrace_window)
// segments, arcs or circles drawn on its layer (at the SVG's 0.0001 mm) adds
// nothing, so a loop going over the same path draws it once; past
// DrawLimits::max_entities entities (or max_polyline_points points of
// polylines) the moves are counted and not drawn, and limit_note() says so.
// Memory stays flat below that: older entities wait in a temporary file
// (entity_list.hpp).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "canon/sink.hpp"
#include "core/vec3.hpp"
#include "draw/drawing.hpp"

namespace usina::draw {

enum class View { Part, Toolpath };

class RetraceWindow;

// What a DrawingBuilder keeps at most.
struct DrawLimits {
  // Some 2 million entities (a DXF or SVG of 100-200 MB) are more than any
  // picture shows: a 2000 x 2000 PNG, an SVG a browser opens. A
  // 1,000,000-block program draws whole.
  std::size_t max_entities = 2'000'000;
  std::size_t max_polyline_points = 8'000'000;
  // Segments, arcs and circles remembered for the retrace test (the last
  // half to all of them; 64 bytes each, twice: 4 MB).
  std::size_t retrace_window = 1u << 15;
};

class DrawingBuilder final : public canon::Sink {
 public:
  // `start`: where the tool is before the first move.
  DrawingBuilder(Drawing& drawing, View view, core::Vec3 start = {}, DrawLimits limits = {});

  ~DrawingBuilder() override;
  DrawingBuilder(const DrawingBuilder&) = delete;
  DrawingBuilder& operator=(const DrawingBuilder&) = delete;

  void on(const canon::Op& op) override;

  // Chordal tolerance of arcs out of the XY plane, drawn as polylines (mm).
  static constexpr double kArcTolerance = 0.01;

  // Moves not drawn because the drawing was full.
  std::uint64_t moves_not_drawn() const { return not_drawn_; }

  // A warning for the user when moves were not drawn, else nullopt;
  // `where_listed` tells the user where to see the moves left out, in the
  // words of the front end ("usina trace lists them" on the command line).
  std::optional<std::string> limit_note(std::string_view where_listed) const;

 private:
  // Whether the drawing has room for one more entity; counts the move when not.
  bool room(const canon::Op& op);
  void traverse(const core::Vec3& to, canon::Origin origin);
  void feed(const core::Vec3& to, canon::Origin origin);
  void arc(const canon::Arc& a, canon::Origin origin);
  void spline(const canon::Spline& s, canon::Origin origin);
  void hole(const canon::Hole& h);
  // Drawing calls that skip a retrace and count polyline points.
  void line(Layer& layer, Vec2 from, Vec2 to);
  void circle(Layer& layer, const Circle& c);
  void polyline(Layer& layer, std::vector<Vec2> points);
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
  DrawLimits limits_;
  std::unique_ptr<RetraceWindow> drawn_;
  std::size_t polyline_points_ = 0;
  std::uint64_t not_drawn_ = 0;
  std::uint32_t first_not_drawn_line_ = 0;
};

}  // namespace usina::draw
