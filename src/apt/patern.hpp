// PATERN: a named list of points (research/apt.md §3, the forms of the
// PERSONAL APT mini-manual) and the order in which GOTO/pattern visits them.
// The definition forms are in patern.cpp (forms::pattern_form).
#pragma once

#include <vector>

#include <tl/expected.hpp>

#include "apt/geometry.hpp"

namespace usina::apt {

// The most points one pattern holds (RANDOM and PARLEL multiply them).
inline constexpr std::size_t kMaxPatternPoints = 100000;
// ... all the patterns a program defines, and all the points its
// GOTO/pattern statements visit (each is kept in memory).
inline constexpr std::size_t kMostProgramPatternPoints = 1000000;

struct PatternVisit {
  core::Vec3 p;
  double avoid = 0.0;  // AVOID: the rise the tool goes over on its way here (0: none)
};

// GOTO/pattern[,INVERS][,OMIT|RETAIN,i[,THRU,j]...][,AVOID,h,i[,THRU,j]...]:
// `mods` are the arguments after the pattern; the points are numbered from 1
// in the pattern's own order, whatever INVERS says.
tl::expected<std::vector<PatternVisit>, GeomError> pattern_visits(const Geom& pattern,
                                                                  const std::vector<Arg>& mods);

}  // namespace usina::apt
