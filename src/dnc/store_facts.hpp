// What the library's search reads of a revision (docs/dnc-server.md, "The
// library's list"): its program numbers, the tools it calls and the text of
// its comments, found once when the revision is stored and kept beside it,
// so a search of 10,000 programs reads no program's bytes.
//
// A small scan of the text by the dialect's lexical rules, not a run: a
// program that stops on an error at its third block still has the tools
// and comments of the rest, a subroutine never called still counts, and
// nothing the interpreter makes up (its "M0 (program stop)" comments) is
// taken for the programmer's words. The scan follows the readers' rules
// for what it reads (gcode/fanuc/tape.cpp's block head, romi's
// parenthesised statements), but keeps no expression and reports nothing.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "dnc/store_db.hpp"

namespace usina::dnc {

struct ProgramFacts {
  // The program numbers as written, lower case: "o1000 o0001" (fanuc's ':'
  // written as 'o').
  std::vector<std::string> o_numbers;
  std::vector<std::int64_t> tools;  // the T words' numbers, ascending, each once
  // The comments' text, lower case (ASCII), one comment a line, cut at
  // kMaxCommentBytes; bytes that are not UTF-8 become '?'.
  std::string comments;
};

inline constexpr std::size_t kMaxCommentBytes = 4096;
inline constexpr std::size_t kMaxProgramNumbers = 64;
inline constexpr std::size_t kMaxTools = 1000;
inline constexpr std::int64_t kMaxToolNumber = 99'999'999;  // 8 digits

// The facts of `text` in `dialect` (rs274ngc's rules for an unknown one).
ProgramFacts read_facts(std::string_view text, std::string_view dialect);

// Records the facts of the revision `hash` of `program` (already inserted),
// in the caller's transaction.
StoreResult<void> record_facts(Database& db, std::string_view program, std::string_view hash,
                               const ProgramFacts& facts);

// Reads and records the facts of every revision that has none: what the
// migration to schema version 6 does for the revisions stored before it.
StoreResult<void> record_missing_facts(Database& db);

}  // namespace usina::dnc
