// The rows a control punches, back to a program's text: DC2/DC4 (the
// punch's start and end, research/dnc.md §2.2) and DC1/DC3 stripped, NUL and
// DEL (feed) skipped, each row's parity checked, EIA translated, the
// machine's end of block turned into LF, and the text framed by `%`: the
// first `%` opens the program (what came before is leader or label), the
// next one ends it. The program is named from its first O number.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "dnc/link_config.hpp"

namespace usina::dnc {

inline constexpr std::size_t kMaxBadRows = 16;  // the positions kept of bad rows

class TapeReader {
 public:
  TapeReader(TapeCode code, EndOfBlock eob, bool check_parity, std::size_t max_bytes);

  // Reads `rows`; true once the closing `%` has arrived (later rows are only
  // counted in rows_after_end()).
  bool feed(std::span<const std::uint8_t> rows);

  bool complete() const { return state_ == State::Closed; }

  // Something of a program arrived (more than leader, feed and line ends).
  bool has_text() const;

  bool too_large() const { return too_large_; }

  const std::string& text() const { return text_; }

  std::uint64_t rows_read() const { return rows_; }

  std::uint64_t rows_after_end() const { return after_end_; }

  // Rows whose parity is wrong or that are no character of the code: their
  // count and the first kMaxBadRows offsets (0-based, among all rows read).
  std::uint64_t bad_rows() const { return bad_; }

  const std::vector<std::uint64_t>& bad_offsets() const { return bad_offsets_; }

 private:
  enum class State : std::uint8_t { Open, Framed, Closed };
  void put(char c);
  void bad_row();
  void on_char(char c);

  TapeCode code_;
  EndOfBlock eob_;
  bool check_parity_;
  std::size_t max_bytes_;
  State state_ = State::Open;
  std::string text_;
  bool swallow_line_end_ = false;
  bool at_open_ = false;
  bool too_large_ = false;
  std::uint64_t rows_ = 0;
  std::uint64_t after_end_ = 0;
  std::uint64_t bad_ = 0;
  std::vector<std::uint64_t> bad_offsets_;
};

// "O1234" from the program's first block that starts with O (or `:`, the
// ISO program number) and digits; empty when there is none.
std::string program_number(std::string_view text);

}  // namespace usina::dnc
