// ROMI MACH / Interact (spec/romi.md, seed 000's program): blocks end with
// '#', N numbers of four digits step 10, ';' comments, G71 for mm, the arc
// centre I J absolute, a full circle as two halves, the tool's diameter in the tool-change comment
// ("T1 M06;tool 1 d10"), M02 at the end as in the seed's program. Holes are
// written as moves: the spec's G81 measures Z from a work surface a canon
// stream does not know.
#include <fmt/format.h>

#include "post/block_out.hpp"
#include "post/control.hpp"

namespace usina::post {

namespace {

void header(BlockOut& out, const PostOptions& o) {
  out.block(out.comment(o.program_name.empty()
                            ? fmt::format("program {}", o.program_number)
                            : fmt::format("program {} {}", o.program_number, o.program_name)));
  out.block("G90");
  out.block("G71");
  out.block("G17");
  out.block("G40");
}

}  // namespace

Control romi_control() {
  Control c;
  c.name = "romi";
  c.decimals = 3;
  c.two_digit_codes = true;
  c.canned_cycles = false;
  c.absolute_arc_center = true;
  c.full_circle_halves = true;  // spec/romi.md: only the C360 form is a full circle
  c.rotary_axes = false;
  c.probe = false;
  c.inverse_time = false;  // spec/romi.md has no G93 or G95
  c.per_revolution = false;
  c.semicolon_comments = true;
  c.block_end = "#";
  c.line_number_width = 4;
  c.always_line_numbers = true;
  c.dwell_word = "K";
  c.standalone_dwell = false;
  c.header = header;
  c.program_end = "M02";  // as the seed's program ends
  return c;
}

}  // namespace usina::post
