// CL records as ISO 4343 text: the statements of a CL file as CAM systems
// write them (PARTNO/..., FEDRAT/..., GOTO/x,y,z, CIRCLE/..., FINI), one a
// line, which posts and viewers read and usina's APT CL reader reads back.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "apt/cl.hpp"

namespace usina::apt {

// The text of `records`, numbers with at most 9 decimals. `units` ("MM", "INCHES" or empty) writes
// a UNITS statement first. A circle's record is written as CIRCLE/ when its motion is one point (an
// arc to it), as a $$ comment before its chords when the motion is several (IBM's segmented
// circles: the chords are the path).
std::string write_iso4343(const std::vector<ClRecord>& records, std::string_view units = {});

}  // namespace usina::apt
