// Fanuc (0i/30i milling, ISO): % delimiters, O number, every coordinate
// with a decimal point (without one Fanuc reads least increments), two-digit
// codes, G81/G83 with G98, dwell as G04 X<seconds> (a cycle's P in ms).
#include <fmt/format.h>

#include "post/block_out.hpp"
#include "post/control.hpp"

namespace usina::post {

namespace {

void header(BlockOut& out, const PostOptions& o) {
  out.raw("%");
  std::string o_word = fmt::format("O{:04}", o.program_number);
  if (!o.program_name.empty()) o_word += " " + out.comment(o.program_name);
  out.block(o_word);
  out.block("G21 G17 G90 G94 G40 G49 G80 G98");
}

// The tape's closing '%', after the program end the writer adds.
void footer(BlockOut& out, const PostOptions&) {
  out.raw("%");
}

}  // namespace

Control fanuc_control() {
  Control c;
  c.name = "fanuc";
  c.decimals = 3;
  c.always_point = true;
  c.two_digit_codes = true;
  c.dwell_word = "X";
  c.cycle_dwell_ms = true;
  c.header = header;
  c.footer = footer;
  return c;
}

}  // namespace usina::post
