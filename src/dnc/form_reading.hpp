// What each cycle of the forms (form_cycles.hpp) gives: its fields read
// into a generator to run, and where that generator's errors go. One file
// a kind of cycle (form_pockets.cpp, form_ellipse.cpp, form_holes.cpp,
// form_profile.cpp):
// the cam headers of the ellipse and of the pockets cannot meet in one
// file (each has its own cam::Ring).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cam/dxf_import.hpp"
#include "cam/program.hpp"
#include "canon/sink.hpp"
#include "core/diagnostic.hpp"
#include "dnc/form_cycles.hpp"
#include "dnc/form_fields.hpp"
#include "post/post.hpp"

namespace usina::dnc {

using Phrase = FieldDiagnostics::Phrase;
using Generate = std::function<bool(canon::Sink&, core::DiagnosticSink&)>;

struct Reading {
  Generate generate;
  std::vector<Phrase> phrases;  // the message's words → the field (FieldDiagnostics)
  std::string_view work_field;
  std::string_view other_field = "";  // an error no phrase names (the drawing's, for a profile)
};

// A drawing sent in a form's `dxf` field (the page's upload; bounded by the
// server's max_upload and the DXF reader's own 64 MiB), with the `layer`
// and `spline_tolerance` fields: what `usina gen --dxf FILE` reads.
struct FormDrawing {
  std::string text;
  cam::DxfOptions options;

  // Its contours, chained; nothing, with the reader's diagnostics, when
  // the text is no drawing (read by the same checked reader as a file).
  std::optional<std::vector<cam::Path>> contours(core::DiagnosticSink& diags) const;
};

FormDrawing read_drawing(FormFields& f);  // form_profile.cpp

// The fields every cycle has (tool, feeds, spindle, safe Z, the bound on
// the work), with docs/gen.md's defaults.
cam::Cutting read_cutting(FormFields& f);
// A point of two coordinate fields; `what` names it ("the centre": "the centre's X").
cam::Vec2 read_point(FormFields& f, std::string_view x, std::string_view y, std::string_view what);

Reading read_ellipse(FormFields& f, post::PostOptions& post);
Reading read_rect_pocket(FormFields& f, post::PostOptions& post);
Reading read_circle_pocket(FormFields& f, post::PostOptions& post);
Reading read_drill_grid(FormFields& f, post::PostOptions& post);
Reading read_bolt_circle(FormFields& f, post::PostOptions& post);
Reading read_engrave(FormFields& f, post::PostOptions& post);
Reading read_profile_dxf(FormFields& f, post::PostOptions& post);
Reading read_pocket_dxf(FormFields& f, post::PostOptions& post);  // form_pockets.cpp

}  // namespace usina::dnc
