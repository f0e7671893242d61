// Chaining: a drawing's entities joined end to end into contours, as a CAD
// sketch's segments make one polyline (seed 002, section 4).
#pragma once

#include <vector>

#include "cam/path.hpp"

namespace usina::cam {

// Ends closer than this (mm) are the same point.
inline constexpr double kChainTolerance = 0.01;

// Joins `entities` into paths. Each path starts with the first entity (in
// drawing order) not used yet and grows at its end, then at its start, by the
// first unused entity (in drawing order) with an end within `tolerance`,
// reversed when it is its end that meets. The joined ends become one point
// (the earlier entity's). A path whose ends meet is closed. Arcs stay arcs.
// Paths come out in the drawing order of their first entity.
std::vector<Path> chain(std::vector<Path> entities, double tolerance = kChainTolerance);

}  // namespace usina::cam
