// What a post needs to know about a control: a table (number format, block
// end, comments, arcs, cycles) and its header and footer. One control a file.
#pragma once

#include <string>

#include "post/post.hpp"

namespace usina::post {

class BlockOut;

struct Control {
  std::string name;
  int decimals = 3;
  bool always_point = false;         // "X10." for 10 (Fanuc reads "X10" as 10 µm)
  bool two_digit_codes = false;      // "G01", "M03"
  bool canned_cycles = true;         // G81/G83 for bare holes, else expanded moves
  bool absolute_arc_center = false;  // I J K absolute instead of from the start point
  bool turns_word = false;           // P<n> for extra helix turns; else split into full circles
  bool full_circle_halves = false;   // a full circle as two half circles (end = start is ambiguous)
  bool rotary_axes = true;           // A B C words
  bool probe = true;                 // G38.2
  bool machine_codes = true;         // the machine's M codes as they came (Grbl: error:20)
  bool inverse_time = true;          // G93
  bool per_revolution = true;        // G95
  bool semicolon_comments = false;   // ";text" instead of "(text)"
  std::string block_end;             // written after every block ("#" for romi)
  int line_number_width = 0;         // zero-padded N words ("N0010")
  bool always_line_numbers = false;
  bool tool_change_m6 = true;
  std::string dwell_word = "P";  // G4 P<s> (LinuxCNC, grbl) or G4 X<s> (Fanuc)
  // A cycle's dwell P in whole milliseconds (Fanuc: P500 is 0.5 s), and a
  // G86 with none; else P in seconds, and G86 with P0 (LinuxCNC wants it).
  bool cycle_dwell_ms = false;
  // A dwell in a block of its own (G4) the control's dialect reads; romi's
  // spec has none (its only dwell is G81's D, at a drilled hole's bottom).
  bool standalone_dwell = true;
  std::string program_end = "M30";  // after the spindle stop and coolant off
  void (*header)(BlockOut& out, const PostOptions& options) = nullptr;
  // What follows the program end (Fanuc's closing '%'); none for most.
  void (*footer)(BlockOut& out, const PostOptions& options) = nullptr;
};

Control rs274ngc_control();
Control fanuc_control();
Control grbl_control();
Control romi_control();

}  // namespace usina::post
