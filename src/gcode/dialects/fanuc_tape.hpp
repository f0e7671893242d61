// The fanuc dialect's tape: a program text cut into blocks by Fanuc's
// lexical rules (docs/fanuc.md §1). '%' delimits the tape, ';' and newline
// end a block, '( )' comments may hold ';', 'O1234' / ':1234' starts a
// program, 'N' numbers are the targets of GOTO and M99 P, '/' deletes.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace usina::gcode::fanuc {

struct TapeBlock {
  std::uint32_t file = 0;
  std::uint32_t line = 0;
  std::uint32_t col = 1;  // of the block's first character in its line
  std::uint64_t line_offset = 0;
  std::string_view text;     // without '/', the N word and comments
  std::string_view comment;  // the first ( ) comment's text
  std::size_t length = 0;    // of the block in the file, its head and comments included
  long sequence = -1;        // N number, -1 when none
  bool deleted = false;      // '/' at the start
  long program = -1;         // O number when the block starts a program
  // A block with a comment has its text copied without it: where `text`
  // started in the block (from `col`), and each comment's place in that
  // copy with the characters it took beyond its one blank, so a position
  // in `text` finds its column again (the widths summed up to each
  // comment, in the order of the text).
  std::uint32_t text_start = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> gaps;
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
  std::deque<std::string> stripped_;  // block texts with comments removed
};

}  // namespace usina::gcode::fanuc
