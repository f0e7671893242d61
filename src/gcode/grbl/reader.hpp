// Grbl's side of each line of a program, read one at a time: its line
// reader, its checks with Grbl's error numbers, its `$` commands, and the
// words the interpreter runs for the line. What a line changes (Grbl's modal
// state, settings, the modes a jog keeps) stands only once the interpreter
// and the checks of its moves accepted it, as Grbl discards a refused line
// whole (grbl/runner.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"
#include "gcode/dialect.hpp"
#include "gcode/grbl/dialect.hpp"

namespace usina::gcode::grbl {

// What a line asks of the run.
enum class LineKind {
  Nothing,  // nothing to run: blank, comments, '%', a setting, a report, after the end
  Refused,  // Grbl refuses it (reported)
  Run,      // the interpreter runs handed(); accept() once it and the checks pass
};

class LineReader {
 public:
  LineReader(const Dialect& d, const OptionValues& options, std::uint32_t file);

  // Reads line `n`, starting at `offset` of the file; its warnings and
  // Grbl's error go to `diags`, in the order Grbl meets them.
  LineKind read(std::uint32_t n, std::uint64_t offset, std::string_view text,
                std::vector<core::Diagnostic>& diags);

  // After Run: what the interpreter runs for the line (Grbl's words as it
  // read them, at the user's columns, and the modes a jog kept; a `$`
  // command's move), the column its block starts at, and what the checks
  // of its moves need.
  // A line of one plain move (check_plain_block) is handed as the move
  // (plain_move(), else null), and its words are made only when asked.
  const PlainMove* plain_move() const { return plain_ ? &move_ : nullptr; }

  const HandedBlock& handed();

  std::uint32_t block_col() const { return block_col_; }

  const MachineFacts& facts() const { return facts_; }

  // The line read was run: what it changed stands.
  void accept();

 private:
  // The modes a `$J=` jog or `$H` changed in the interpreter and Grbl kept:
  // put back on the next G-code line (distance, feed mode, F) and on the
  // next line moving with the modal motion (the motion mode).
  struct Restore {
    bool modes = false;
    bool motion = false;
    Modal before;
  };

  // Between lines; a value, so a line works on a copy.
  struct State {
    Modal modal;
    Restore restore;
    bool ended = false;
  };

  LineKind after_end(std::string_view text);
  bool straight(std::string_view text);
  LineKind block();
  LineKind system();
  LineKind fail(const Failure& f);
  void warn(core::Code code, std::uint32_t col, std::string message);
  void warnings_of_the_line();
  bool keeps_modes(const Accepted& acc) const;
  void append_kept_modes(const Accepted& acc);

  CodeIndex codes_;
  const OptionValues& options_;
  std::uint32_t file_;
  std::size_t max_length_;
  bool straight_lines_;  // the straight road (no whole_road option: its tests)
  State now_;
  State next_;  // the line's, until accept()
  Settings settings_;
  std::optional<Settings> next_settings_;  // a `$` line's, until accept()
  Travel travel_;                          // of settings_
  bool warned_after_end_ = false;
  // The line being read.
  core::SourceLoc loc_;
  std::vector<core::Diagnostic>* diags_ = nullptr;
  StrippedLine stripped_;
  std::vector<Word> words_;
  HandedBlock handed_;
  bool plain_ = false;  // the line is one plain move, move_
  PlainMove move_;
  bool handed_made_ = false;    // handed_ holds the line's words
  bool words_of_line_ = false;  // words_ holds them as Grbl read them
  std::string_view line_;       // the line being read
  std::uint32_t block_col_ = 1;
  MachineFacts facts_;
};

}  // namespace usina::gcode::grbl
