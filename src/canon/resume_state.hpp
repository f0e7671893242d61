// The modal state a restart needs at a block (issue 13, "start from block N
// / tool T"): what the gcode side learns from the program before the block
// and a post writes back as a preamble. Plain data in the program's own
// units and frame, so a post writes it without knowing the dialect's reader.
#pragma once

#include <cstdint>
#include <optional>

#include "canon/op.hpp"

namespace usina::canon {

struct ResumeState {
  std::uint32_t line = 0;            // 1-based line of the start block in the file
  std::optional<long> n_word;        // its N word, if it has one
  std::optional<int> by_tool;        // the start was asked as "the first change to tool T"
  bool inch = false;                 // G20 (romi G70)
  int plane = 17;                    // 17, 18 or 19
  bool incremental = false;          // G91 in force
  int work_offset = 0;               // G54.. in tenths (540 ... 593) the program selected; 0: none
  std::optional<int> length_offset;  // G43 H<n> in force
  int feed_mode = 94;                // 93, 94 or 95
  std::optional<double> feed;        // F in the program's units (per minute or per revolution)
  std::optional<int> tool;           // the tool in the spindle
  std::optional<double> tool_diameter_mm;  // its diameter, when the program's change gave one
  bool start_block_changes_tool = false;
  double rpm = 0.0;
  SpindleDir spindle = SpindleDir::Off;
  Coolant coolant;
  bool moved = false;             // a move came before the block: `start` and `safe_z` are known
  Vec3 start;                     // the block's start point, program units, absolute
  double safe_z = 0.0;            // the program's highest Z before the block (program units)
  int motion = 10;                // the motion mode to put back after the approach (0 or 10)
  bool block_has_motion = false;  // the block states its own motion word
};

}  // namespace usina::canon
