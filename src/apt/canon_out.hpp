// CL records as the canon stream (docs/trace.md), so that every back end
// (trace, draw, stats, the posts) reads an APT program.
#pragma once

#include <vector>

#include "apt/cl.hpp"
#include "canon/sink.hpp"

namespace usina::apt {

// `scale`: mm per program unit (1 for a program in mm, 25.4 in inches).
void to_canon(const std::vector<ClRecord>& records, double scale, canon::Sink& sink);

}  // namespace usina::apt
