// The APT processor of a part program: input translation (statements,
// symbols, geometry in canonical form) and the point-to-point part of the
// arithmetic, writing CL records (research/apt.md §2). Every statement with
// an error is reported and left out; processing goes on, so one run reports
// every error, as IBM's processor does.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "apt/cl.hpp"
#include "apt/symbols.hpp"

namespace usina::apt {

struct AptResult {
  std::vector<ClRecord> records;
  std::vector<Definition> definitions;
};

AptResult process(std::string_view text, std::uint32_t file, core::DiagnosticSink& diags);

}  // namespace usina::apt
