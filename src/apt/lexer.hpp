// APT source text as statements and tokens (research/apt.md §3.1): one
// statement a line, '$' at the end of a line continues it on the next, '$$'
// starts a comment to the end of the line, "LABEL)" before a statement.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"

namespace usina::apt {

enum class TokKind : std::uint8_t { Word, Number, Punct, End };

struct Token {
  TokKind kind = TokKind::End;
  std::string text;  // a word upper-cased; the punctuation character
  double value = 0.0;
  std::size_t pos = 0;  // index of its first character in the statement text
  core::SourceLoc loc;
};

// One logical statement: its text (continuations joined) and, for each of
// its characters, where it stands in the file.
struct Statement {
  std::string text;
  std::vector<core::SourceLoc> where;
  core::SourceLoc loc;  // the statement's first character

  // the line as written, filled by the processor.
};

// Hands each statement of `text` to `take` in turn (one statement in
// memory at a time); `file` is the SourceManager index.
void for_each_statement(std::string_view text, std::uint32_t file,
                        const std::function<void(const Statement&)>& take);

// Every statement of `text` (tests).
std::vector<Statement> split_statements(std::string_view text, std::uint32_t file);

// The tokens of one statement; a character that starts no token is reported
// (E_APT_SYNTAX) and skipped. The last token is End.
std::vector<Token> tokenize(const Statement& st, core::DiagnosticSink& diags);

// The location of character `i` of `st` (its end when past the text).
core::SourceLoc loc_at(const Statement& st, std::size_t i);

}  // namespace usina::apt
