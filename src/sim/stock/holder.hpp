// The holder's check: the holder is a cylinder of its diameter from the
// stick-out up, above the tool (its length is not modelled: whatever is above
// it, the spindle's nose, is taken to be no wider). It cuts nothing, so any
// stock it meets is a collision (E_HOLDER_HITS_STOCK; docs/simulate.md).
//
// Exact per cell, as the sweep: while the holder is over a cell's column the
// stock there is what the move found (before the tool reaches the column),
// lower than the tool's end (while the tool is over it too: no contact, the
// stick-out being at least the end's height), or what the tool left (after
// it). The first and the last are each one comparison of a height with the
// holder's face at its lowest over that stretch of the move. A move going up
// meets at its start what the move before left there, checked by that move:
// a retract from a contact is not a second one.
#pragma once

#include "sim/stock/height_map.hpp"
#include "sim/stock/path.hpp"
#include "sim/stock/tool_shape.hpp"

namespace usina::sim::stock {

// A holder closer to the stock than this is not taken for touching it (mm).
inline constexpr double kHolderContact = 0.001;

enum class HolderStretch {
  BeforeTheTool,  // call before the tool's sweep: the heights the move found
  AfterTheTool,   // call after it: the heights the tool left
};

// The deepest the holder of `tool` goes into the stock over that stretch of
// the move `p`, or `found` (a depth known already) when that is deeper, mm;
// 0 when it clears it (by more than -kHolderContact) and found is 0.
double holder_depth(HeightMap& map, const Path& p, const ToolShape& tool, HolderStretch stretch,
                    double found);

}  // namespace usina::sim::stock
