// What --dialect auto reads in a program (docs/dialects.md, "Guessing the
// dialect"): its first blocks split into code and comments, how it ends,
// and the weighed clues that lean towards one dialect without deciding alone.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace usina::gcode {

// One line of the program's head: the code in upper case without comments
// or blanks at its ends, and the text of its comments.
struct HeadLine {
  std::string code;
  std::string comments;         // every ( ) and ; comment of the line, lower case
  bool semicolon_text = false;  // a ';' followed by text: a comment (LinuxCNC, Grbl senders)
  bool bare_semicolon = false;  // a ';' ending the line: Fanuc's end of block
};

inline constexpr std::size_t kHeadLines = 200;

// The first `kHeadLines` lines of `text`.
std::vector<HeadLine> read_head(std::string_view text);

// Whether one of the last blocks of `text` is M2, M30 or '%'.
bool ends_with_program_end(std::string_view text);

// A clue that leans towards `dialect` by `weight`; `what` says it in words.
struct Clue {
  std::string_view dialect;
  int weight = 0;
  std::string what;
};

// The clues of a program that no decisive mark has placed. `file_name` may
// be empty (standard input).
std::vector<Clue> weigh_clues(const std::vector<HeadLine>& head, std::string_view text,
                              std::string_view file_name);

}  // namespace usina::gcode
