// The drawing model: named layers of plane entities (LINE, ARC, CIRCLE,
// POLYLINE) in the XY plane, in mm. The writers (DXF, SVG, PNG/PDF) read it;
// a DrawingBuilder fills it from the canon stream.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "draw/entity.hpp"
#include "draw/entity_list.hpp"

namespace usina::draw {

// Start and end points of an arc.
Vec2 arc_start(const Arc& a);
Vec2 arc_end(const Arc& a);
// The angle an arc sweeps, in (0, 2π), whichever its direction.
double arc_sweep(const Arc& a);

// An axis-aligned box; empty until a point is added.
struct Box {
  Vec2 min;
  Vec2 max;
  bool empty = true;

  void add(Vec2 p);
  void add(const Box& b);

  double width() const { return empty ? 0.0 : max.x - min.x; }

  double height() const { return empty ? 0.0 : max.y - min.y; }
};

Box bounds_of(const Entity& e);

// The part of the plane a picture of the drawing shows: its bounds plus a
// margin of 5 % of the larger side (at least 1 mm). An empty drawing shows
// the 10 mm square about the origin.
Box view_box(const Box& bounds);

struct Rgb {
  unsigned char r = 0;
  unsigned char g = 0;
  unsigned char b = 0;
};

// How a layer is drawn: an AutoCAD colour index for DXF, the colour of the
// SVG/PNG/PDF pictures (on white paper), dashed or continuous.
struct LayerStyle {
  int aci = 7;
  Rgb rgb;
  bool dashed = false;
};

// The run of moves the layer's last line stands for (drawing.cpp): the
// directions its end may still take so that the line passes within the
// drawing's tolerance of every point the moves went through, as angles from
// `dir` (radians), and how far from the line's start they reached.
struct LineRun {
  std::size_t entity = static_cast<std::size_t>(-1);  // the line's index; none
  Vec2 dir;
  double lo = 0.0;
  double hi = 0.0;
  double reach = 0.0;
};

// Entities from `first` on were drawn with `tool` (until the next run).
struct ToolRun {
  std::size_t first = 0;
  int tool = 0;
};

struct Layer {
  std::string name;
  LayerStyle style;
  EntityList entities;
  // On CONTOUR: which tool cut which entities, so that the pictures colour
  // the contour by tool (the toolpath view has a layer per tool instead).
  std::vector<ToolRun> tool_runs;
  LineRun run;
};

class Drawing {
 public:
  // The layer named `name`, made on first use with the style of its name
  // (layer_style.hpp).
  Layer& layer(std::string_view name);

  // Layers in the order of the writers: CONTOUR, RAPID, HOLES, POCKETS, then
  // the tool layers by tool number, then any other by name.
  std::vector<const Layer*> layers() const;

  // How far a drawn line may pass from the points of the moves it stands
  // for (mm; 0: within 1 nm, every bend kept). A picture need not show more:
  // usina draw gives 0.01 mm, the chordal tolerance of its arcs.
  void set_tolerance(double mm) { tolerance_ = mm; }

  // The drawing becomes a picture of `width` x `height` pixels (or dots):
  // lines also merge within half a pixel, at the scale of the bounds so far.
  // The bounds only grow, so that scale is never coarser than the picture's.
  void set_picture(int width, int height) {
    picture_width_ = width;
    picture_height_ = height;
  }

  // A straight segment; merged into the layer's last line when it goes on
  // from that line's end, forward, and the merged line passes within the
  // tolerance of every point (a collinear run, a dense curve seen from
  // afar). Segments shorter than 1 nm (moves along Z only) add nothing.
  void add_line(Layer& layer, Vec2 from, Vec2 to);
  void add_arc(Layer& layer, const Arc& arc);
  void add_circle(Layer& layer, const Circle& circle);
  // Consecutive equal points are dropped, collinear runs merged; two points
  // left become a line, fewer nothing.
  void add_polyline(Layer& layer, std::vector<Vec2> points, bool closed = false);

  // How many bytes of entities a layer made from now on holds in memory,
  // and all layers together, before older ones go to the drawing's
  // temporary file in `folder` (entity_list.hpp; empty folder: $TMPDIR or
  // /tmp; the folder only until the file is made).
  void set_hold(std::size_t layer_bytes, std::size_t drawing_bytes = SpillFile::kHoldLimit,
                std::string folder = {});

  const Box& bounds() const { return bounds_; }

  std::size_t entity_count() const;

  // Why a writer could not read all of a layer's entities back (entity_list.hpp);
  // none when it could. Every writer asks when it is done.
  std::optional<std::string> read_error() const;

 private:
  double line_tolerance() const;
  bool extend_run(Layer& layer, Vec2 from, Vec2 to);
  void start_run(Layer& layer, Vec2 from, Vec2 to);

  // Before the layers, which use it until they are gone.
  std::unique_ptr<SpillFile> spill_ = std::make_unique<SpillFile>();
  std::vector<std::unique_ptr<Layer>> layers_;
  Box bounds_;
  double tolerance_ = 0.0;
  int picture_width_ = 0;
  int picture_height_ = 0;
  std::size_t hold_bytes_ = EntityList::kHoldBytes;
};

}  // namespace usina::draw
