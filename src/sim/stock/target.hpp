// The depths a drawing asks for, against the stock the program left: inside
// the closed contours of a layer (islands, contours inside contours, left
// out: even-odd) every cell should be down to the layer's Z. What stands
// above it by more than a tolerance is material the program left
// (W_MATERIAL_ABOVE_TARGET; docs/simulate.md, "Target depths").
#pragma once

#include <string>
#include <vector>

#include "core/vec3.hpp"
#include "sim/stock/height_map.hpp"

namespace usina::sim::stock {

using core::Vec2;

// One layer of the drawing: its closed contours as polygons (XY, mm) and
// the Z its area must be cut down to.
struct TargetLayer {
  std::string layer;
  double z = 0.0;
  std::vector<std::vector<Vec2>> rings;
  // What the messages call it: "layer POCKET" when empty.
  std::string title;
  // The rings are the area the tool can reach (a job's operation), not the
  // drawing's: its corners are not left to the tool's radius.
  bool reachable = false;
  int operation = 0;  // the job's operation it comes from, from 1; 0: none
};

struct TargetResult {
  std::string layer;
  std::string title;
  bool reachable = false;
  int operation = 0;
  double z = 0.0;
  double area_mm2 = 0.0;       // of the cells whose centres are inside
  double above_mm2 = 0.0;      // of those standing above z + tolerance
  double most_above_mm = 0.0;  // the most one of them stands above z
  Vec2 most_at;                // its cell's centre
  double left_mm3 = 0.0;       // the stock above z there, mm³
};

// The cells of `map` inside `target` compared with its Z.
TargetResult check_target(const HeightMap& map, const TargetLayer& target, double tolerance);

// The warning for a result with material above its target, as
// W_MATERIAL_ABOVE_TARGET's message.
std::string material_above_message(const TargetResult& r, double tolerance);

}  // namespace usina::sim::stock
