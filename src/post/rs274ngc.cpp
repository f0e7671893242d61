// LinuxCNC (RS274NGC): O words are subroutine labels there, so the program
// number goes in a comment; 4 decimals; G81/G83; P for helix turns.
#include <fmt/format.h>

#include "post/block_out.hpp"
#include "post/control.hpp"

namespace usina::post {

namespace {

void header(BlockOut& out, const PostOptions& o) {
  out.block(out.comment(o.program_name.empty()
                            ? fmt::format("program {}", o.program_number)
                            : fmt::format("program {} {}", o.program_number, o.program_name)));
  // mm, XY plane, absolute, feed per minute, no compensation, no length
  // offset (canon positions are the tool tip's), no cycle, retract to the
  // level the cycle started from.
  out.block("G21 G17 G90 G94 G40 G49 G80 G98");
}

}  // namespace

Control rs274ngc_control() {
  Control c;
  c.name = "rs274ngc";
  c.decimals = 4;
  c.turns_word = true;
  c.header = header;
  return c;
}

}  // namespace usina::post
