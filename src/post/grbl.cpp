// grbl 1.1: no canned cycles (holes become moves), no O numbers, no tool
// changer (a tool change is a comment and an M0 pause unless asked for),
// no rotary axes, no helix turn count.
#include <fmt/format.h>

#include "post/block_out.hpp"
#include "post/control.hpp"

namespace usina::post {

namespace {

void header(BlockOut& out, const PostOptions& o) {
  if (!o.program_name.empty()) out.block(out.comment(o.program_name));
  out.block("G21 G17 G90 G94");
}

}  // namespace

Control grbl_control() {
  Control c;
  c.name = "grbl";
  c.machine_codes = false;  // Grbl runs only its own M codes
  c.decimals = 3;
  c.canned_cycles = false;
  c.per_revolution = false;  // Grbl 1.1 has G93 and G94, not G95
  c.rotary_axes = false;
  c.tool_change_m6 = false;
  c.header = header;
  return c;
}

}  // namespace usina::post
