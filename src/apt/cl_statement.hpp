// The statements of a CL text file (research/apt.md §6.2, "reader rules"):
// one a line, '$' at the end of a line continues it on the next, '$$'
// starts a comment; a major word ("GOTO", "TOOL PATH", blanks around it
// allowed), '/', arguments separated by ','; numbers and minor words in any
// order, text in quotes.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"

namespace usina::apt {

struct ClArg {
  enum class Kind : unsigned char { Number, Word, Text };
  Kind kind = Kind::Number;
  double value = 0.0;
  std::string text;  // a word upper-cased; a quoted text as written
  core::SourceLoc loc;
};

struct ClStatement {
  std::string major;  // upper-cased, inner blanks made one ("TOOL PATH")
  std::string rest;   // the text after '/' (or after the major word), as written
  std::vector<ClArg> args;
  core::SourceLoc loc;  // the statement's first character
};

// Hands each statement of `text` to `take` in turn until it returns false.
// A statement longer than kMostClStatementBytes, with more than
// kMostClArguments arguments or a number that is not finite or beyond
// kLargestClNumber is reported (E_CL_TOO_LARGE) and left out.
void for_each_cl_statement(std::string_view text, std::uint32_t file, core::DiagnosticSink& diags,
                           const std::function<bool(const ClStatement&)>& take);

}  // namespace usina::apt
