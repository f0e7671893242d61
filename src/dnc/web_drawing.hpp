// The 2D drawing of a revision for the web page (docs/web.md, "The
// drawing"): the program run through its dialect into the draw back end,
// the same DrawingBuilder and writers as `usina draw`, in memory. Bounded
// for a browser: at most `max_entities` entities (the moves past them are
// counted and named in a note, as `usina draw` warns), SVG lines merged
// within half a pixel of a 4096-pixel picture, and an answer past
// `max_bytes` refused.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "draw/builder.hpp"

namespace usina::dnc {

enum class DrawingFormat { Svg, Dxf };

struct DrawingSettings {
  std::string dialect = "rs274ngc";
  draw::View view = draw::View::Part;
  DrawingFormat format = DrawingFormat::Svg;
  std::uint64_t max_ops = 100'000'000;  // canon operations, as the check
  // About 9 MB of SVG or 20 MB of DXF: more than a page shows.
  std::size_t max_entities = 100'000;
  std::size_t max_bytes = 32u << 20;
  // The picture the SVG is simplified for (DXF keeps usina draw's 0.01 mm).
  int picture_pixels = 4096;
};

// What the route answers: 200 with the drawing (complete or not), or a
// refusal (422: nothing to draw; 413: too large) with its reason.
struct DrawingAnswer {
  unsigned status = 200;
  bool complete = true;  // false: the run stopped on an error, or moves were left out
  std::string note;      // why it is incomplete, or the refusal's reason
  std::string body;      // the SVG or DXF
};

DrawingAnswer program_drawing(std::string_view text, const DrawingSettings& settings);

// The answer as one string for the tool-path cache, and back; nothing when
// `bytes` is no encoded answer.
std::string encode_drawing_answer(const DrawingAnswer& answer);
std::optional<DrawingAnswer> decode_drawing_answer(std::string_view bytes);

}  // namespace usina::dnc
