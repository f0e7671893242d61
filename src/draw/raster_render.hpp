// What the cairo writers share (draw_raster only: this header names cairo's
// types, which no other part of usina sees): a drawing rendered into an area
// of a surface, the stream that takes a surface's bytes, owners of cairo's
// objects.
#pragma once

#include <cairo.h>

#include <cstdio>
#include <memory>
#include <string>

#include "draw/drawing.hpp"
#include "draw/write_result.hpp"

namespace usina::draw {

// A rectangle in device units (y down).
struct Area {
  double left = 0;
  double top = 0;
  double width = 0;
  double height = 0;
};

// The drawing fitted into `area` on a white ground, with its legend and
// scale bar along the area's bottom (the PNG and PDF pictures' layout).
void render_drawing(cairo_t* cr, const Drawing& drawing, const Area& area, double line_width);

// cairo's write callback: `file` is a std::FILE*.
cairo_status_t write_to_stream(void* file, const unsigned char* data, unsigned int length);

// cairo's words for `s`.
inline std::string status_text(cairo_status_t s) {
  return cairo_status_to_string(s);
}

// Finishes `surface` (its last bytes go to the stream); the error cairo
// reports then, if any.
WriteResult finish_surface(cairo_surface_t* surface);

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};

struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};

using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using Context = std::unique_ptr<cairo_t, ContextDeleter>;

}  // namespace usina::draw
