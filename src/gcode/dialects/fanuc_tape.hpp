// The fanuc dialect's tape: a program text cut into blocks by Fanuc's
// lexical rules (docs/fanuc.md §1). '%' delimits the tape, ';' and newline
// end a block, '( )' comments may hold ';', 'O1234' / ':1234' starts a
// program, 'N' numbers are the targets of GOTO and M99 P, '/' deletes.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace usina::gcode::fanuc {

// Where a comment that opens at text[open] ends: after its ')' (inner
// '( )' pairs belong to it: "(READ WITH (DPI=0) ...)"), or at the end of
// its line when it is never closed. The tape, the block head and the macro
// reader all skip a comment as one blank where it stands.
std::size_t skip_comment(std::string_view text, std::size_t open);

struct TapeBlock {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
  std::uint32_t col = 1;  // of the block's first character in its line
  std::uint64_t line_offset = 0;
  // The block's words and statements in the file, after '/', O and N and
  // without the blanks and comments around them; comments between the
  // words stay where they are (readers skip them as blanks), so a position
  // in `text` is a column of the line.
  std::string_view text;
  std::string_view comment;  // the first ( ) comment's text
  std::size_t length = 0;    // of the block in the file, its head and comments included
  long sequence = -1;        // N number, -1 when none
  bool deleted = false;      // '/' at the start
  long program = -1;         // O number when the block starts a program
};

class Tape {
 public:
  // Appends the blocks of one file, read from `from` on (past a byte-order
  // mark); returns the index of its first block.
  std::size_t add_file(std::uint32_t file, std::string_view text, std::size_t from = 0);

  // The block add_file is cutting (defined in fanuc_tape.cpp; public only so
  // the file's helpers can name it).
  struct PendingBlock;

  const TapeBlock& at(std::size_t i) const { return blocks_[i]; }

  std::size_t size() const { return blocks_.size(); }

  // The block that starts program `number` (its O block), or npos.
  std::size_t program(long number) const;
  // The last block of the program holding block i (before the next O block
  // or the end of that file's blocks), exclusive.
  std::size_t program_end(std::size_t i) const;
  // The first block of the program holding block i.
  std::size_t program_start(std::size_t i) const;
  // Whether the file holding block i closed its tape with '%'.
  bool closed(std::size_t i) const;

  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

 private:
  struct FileSpan {
    std::size_t first = 0;
    std::size_t end = 0;
    bool closed = false;
  };

  const FileSpan& span_of(std::size_t i) const;
  // Cuts the pending block at `stop` and appends it unless it is empty.
  void end_block(std::uint32_t file, std::string_view text, std::size_t stop, PendingBlock& p);
  std::vector<TapeBlock> blocks_;
  std::vector<FileSpan> files_;
  std::map<long, std::size_t> programs_;
};

}  // namespace usina::gcode::fanuc
