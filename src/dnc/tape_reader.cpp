#include "dnc/tape_reader.hpp"

#include <algorithm>

#include "dnc/tape_code.hpp"

namespace usina::dnc {

TapeReader::TapeReader(TapeCode code, EndOfBlock eob, bool check_parity, std::size_t max_bytes)
    : code_(code), eob_(eob), check_parity_(check_parity), max_bytes_(max_bytes) {}

bool TapeReader::has_text() const {
  return std::any_of(text_.begin(), text_.end(),
                     [](char c) { return c != '\n' && c != ' ' && c != '\t'; });
}

void TapeReader::put(char c) {
  if (text_.size() >= max_bytes_) {
    too_large_ = true;
    return;
  }
  text_.push_back(c);
}

void TapeReader::bad_row() {
  if (bad_offsets_.size() < kMaxBadRows) bad_offsets_.push_back(rows_);
  ++bad_;
}

void TapeReader::on_char(char c) {
  if (c == '%') {
    // The first `%` opens the program unless a program (a block and its end)
    // came before it, from a control that punches no opening `%`: then it is
    // the end. A label on the leader has no block end.
    if (state_ == State::Open && (!has_text() || text_.find('\n') == std::string::npos)) {
      text_.clear();
      state_ = State::Framed;
      at_open_ = true;  // the `%` block's own end is no line of the program
    } else {
      state_ = State::Closed;
    }
    return;
  }
  const bool own_end =
      (c == ';' && eob_ == EndOfBlock::Semicolon) || (c == '#' && eob_ == EndOfBlock::Hash);
  if (at_open_ && (c == '\n' || c == '\r' || own_end)) return;
  at_open_ = false;
  if (swallow_line_end_ && (c == '\n' || c == '\r')) return;
  swallow_line_end_ = false;
  switch (c) {
  case '\n':
    if (eob_ != EndOfBlock::Semicolon && eob_ != EndOfBlock::Hash) put('\n');
    return;
  case '\r':
    // ISO ignores CR (research/dnc.md §2.3); it is the block end only with `cr`.
    if (eob_ == EndOfBlock::Cr) put('\n');
    return;
  case ';':
    if (eob_ == EndOfBlock::Semicolon) {
      put('\n');
      swallow_line_end_ = true;
      return;
    }
    break;
  case '#':
    if (eob_ == EndOfBlock::Hash) {
      put('#');  // romi keeps `#` in its text: the block end of its dialect
      put('\n');
      swallow_line_end_ = true;
      return;
    }
    break;
  default: break;
  }
  put(c);
}

bool TapeReader::feed(std::span<const std::uint8_t> rows) {
  for (const std::uint8_t row : rows) {
    if (state_ == State::Closed) {
      ++after_end_;
      ++rows_;
      continue;
    }
    const auto seven = static_cast<std::uint8_t>(row & 0x7FU);
    // DC1-DC4 are the link's, never the program's; in EIA 0x13 is the digit 3.
    const bool device_control = (seven >= 0x11 && seven <= 0x14) && code_ != TapeCode::Eia;
    if (device_control || (code_ == TapeCode::Eia && (row == kDc2 || row == kDc4 || row == 0x11))) {
      ++rows_;
      continue;
    }
    const DecodedRow d = decode_row(code_, row, check_parity_);
    switch (d.kind) {
    case DecodedRow::Kind::Char: on_char(d.ch); break;
    case DecodedRow::Kind::Feed:
      // Blank tape inside an EIA program is an error (YASNAC LX3 table 2.4):
      // it is also what a one-hole character that lost its hole looks like.
      if (code_ == TapeCode::Eia && row == kNul && state_ == State::Framed) bad_row();
      break;
    case DecodedRow::Kind::BadParity:
    case DecodedRow::Kind::NoSuchCode: bad_row(); break;
    }
    ++rows_;
  }
  return complete();
}

std::string program_number(std::string_view text) {
  std::size_t at = 0;
  while (at < text.size()) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(at, end - at);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t'))
      line.remove_prefix(1);
    if (!line.empty() && (line.front() == 'O' || line.front() == 'o' || line.front() == ':')) {
      std::size_t n = 1;
      while (n < line.size() && n <= 9 && line[n] >= '0' && line[n] <= '9')
        ++n;
      if (n > 1) return "O" + std::string(line.substr(1, n - 1));
    }
    at = end + 1;
  }
  return {};
}

}  // namespace usina::dnc
