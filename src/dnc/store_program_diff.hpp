// The diff of two programs, plain (their lines as they are) or normalised
// (store_normalise.hpp), and its unified-diff text.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dnc/store_diff.hpp"
#include "dnc/store_normalise.hpp"

namespace usina::dnc {

struct ProgramDiff {
  std::vector<Block> old_blocks;  // plain: every line as it is (without its LF)
  std::vector<Block> new_blocks;
  LineDiff diff;
};

ProgramDiff plain_diff(std::string_view old_text, std::string_view new_text);
ProgramDiff normalised_diff(std::string_view old_text, std::string_view new_text,
                            const NormaliseRules& rules = {});

// "--- old\n+++ new\n@@ -l,n +l,n @@\n ..." with `context` lines around each
// change; line numbers are the programs' own (a normalised hunk starts at the
// line its first block came from). Empty when the programs do not differ.
std::string unified_diff(const ProgramDiff& d, std::string_view old_label,
                         std::string_view new_label, std::size_t context = 3);

}  // namespace usina::dnc
