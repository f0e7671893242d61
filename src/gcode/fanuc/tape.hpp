// The fanuc dialect's tape: a program text cut into blocks by Fanuc's
// lexical rules (docs/fanuc.md §1). '%' delimits the tape, ';' and newline
// end a block, '( )' comments may hold ';', 'O1234' / ':1234' starts a
// program, 'N' numbers are the targets of GOTO and M99 P, '/' deletes.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"

namespace usina::gcode::fanuc {

// Where a comment that opens at text[open] ends: after its ')' (inner
// '( )' pairs belong to it: "(READ WITH (DPI=0) ...)"), or at the end of
// its line when it is never closed. The tape, the block head and the macro
// reader all skip a comment as one blank where it stands.
std::size_t skip_comment(std::string_view text, std::size_t open);

// Where a block starts on the tape: its file (a SourceManager id), its
// offset there, and the line it is on. Blocks are named by where they
// stand, so the tape holds no list of blocks and streams in constant memory.
struct TapePos {
  std::uint32_t file = 0;
  std::uint32_t line = 1;
  std::uint64_t offset = 0;
  std::uint64_t line_start = 0;  // offset of the line's first character

  // One number that orders positions of a file (files apart).
  std::uint64_t key() const { return (std::uint64_t{file} << 40) | offset; }

  friend bool operator==(const TapePos& a, const TapePos& b) { return a.key() == b.key(); }

  friend bool operator<(const TapePos& a, const TapePos& b) { return a.key() < b.key(); }

  friend bool operator<=(const TapePos& a, const TapePos& b) { return a.key() <= b.key(); }
};

struct TapeBlock {
  // The block's place: its file and line (and the line's offset), the
  // column where its text starts, no length. Its operations carry it, and
  // the interpreter's diagnostics where no word applies. Made with the
  // block: made as the block was handed over, its four-byte stores were
  // still pending when the interpreter read it whole (issue 19).
  core::SourceLoc loc;
  std::uint32_t col = 1;  // of the block's first character in its line
  // The block's words and statements in the file, after '/', O and N and
  // without the blanks and comments around them; comments between the
  // words stay where they are (readers skip them as blanks), so a position
  // in `text` is a column of the line (loc.col + the position).
  std::string_view text;
  std::string_view comment;  // the first ( ) comment's text
  std::size_t length = 0;    // of the block in the file, its head and comments included
  long sequence = -1;        // N number, -1 when none
  bool deleted = false;      // '/' at the start
  long program = -1;         // O number when the block starts a program
  TapePos at;                // where the block starts
  TapePos next;              // where the block after it starts
  // No block: the file's tape ends at `at` ('%' when `closed`, else the
  // end of the file).
  bool end = false;
  bool closed = false;
};

// The blocks of the program's files, cut from the text where they stand
// when they are read; an index of the O blocks is made as far as a call
// needs it (the first program of each number counts, files in the order
// they were added).
class Tape {
 public:
  // Adds a file whose tape is read from `from` on (past a byte-order
  // mark); returns where its first block may start.
  TapePos add_file(std::uint32_t file, std::string_view text, std::size_t from = 0);

  // The block that starts at `p` or after it (blank lines and stray ';'
  // make no block), or the end of the file's tape.
  TapeBlock cut(TapePos p) const;
  // The same into `b`, every field written: the engine cuts every block
  // into one, which a new block's initialisation made slower (issue 19).
  void cut(TapePos p, TapeBlock& b) const;

  // Where the O block of program `number` stands, if a file holds one.
  std::optional<TapePos> program(long number);

  // The block add_file is cutting (defined in fanuc/tape.cpp; public only so
  // the file's helpers can name it).
  struct PendingBlock;

 private:
  struct File {
    std::uint32_t id = 0;
    std::string_view text;
    TapePos indexed;  // O blocks before it are in programs_
    bool all_indexed = false;
  };

  std::string_view text_of(std::uint32_t file) const;
  bool make_block(std::uint32_t file, std::string_view text, std::size_t stop,
                  const PendingBlock& p, TapeBlock& b) const;
  std::vector<File> files_;
  std::map<long, TapePos> programs_;
};

}  // namespace usina::gcode::fanuc
