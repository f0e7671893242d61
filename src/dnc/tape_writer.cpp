#include "dnc/tape_writer.hpp"

#include <fmt/format.h>

#include "dnc/tape_code.hpp"

namespace usina::dnc {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
    s.remove_suffix(1);
  return s;
}

std::string shown(unsigned char c) {
  if (c >= 0x20 && c < 0x7F) return fmt::format("'{}' (0x{:02X})", static_cast<char>(c), c);
  return fmt::format("byte 0x{:02X}", c);
}

}  // namespace

TapeFormat tape_format(const LinkConfig& c) {
  return TapeFormat{c.code, c.eob, c.leader, c.trailer, c.data_bits == 7};
}

std::int64_t block_number(std::string_view block) {
  std::size_t i = 0;
  while (i < block.size() && (block[i] == ' ' || block[i] == '\t' || block[i] == '/'))
    ++i;
  if (i >= block.size() || (block[i] != 'N' && block[i] != 'n')) return -1;
  ++i;
  std::int64_t n = 0;
  std::size_t digits = 0;
  for (; i < block.size() && block[i] >= '0' && block[i] <= '9' && digits < 18; ++i, ++digits)
    n = n * 10 + (block[i] - '0');
  return digits == 0 ? -1 : n;
}

TapeWriter::TapeWriter(TapeFormat format) : format_(format) {
  for (unsigned c = 0; c < 256; ++c) {
    const std::optional<std::uint8_t> row =
        encode_char(format_.code, static_cast<unsigned char>(c));
    const bool too_wide = format_.seven_bit && format_.code == TapeCode::Ascii && c > 0x7F;
    rows_of_[c] = (row && !too_wide) ? static_cast<std::int16_t>(*row) : std::int16_t{-1};
  }
}

bool TapeWriter::fail(core::Code code, std::string message) {
  diag_ = core::Diagnostic{code, core::Severity::Error,
                           core::SourceLoc{0, static_cast<std::uint32_t>(line_ + 1), 0, 0, 0},
                           std::move(message)};
  return false;
}

void TapeWriter::put_feed(std::uint32_t count, std::vector<std::uint8_t>& rows) {
  rows.insert(rows.end(), count, kNul);
  rows_ += count;
}

bool TapeWriter::put_char(unsigned char c, std::size_t column, std::vector<std::uint8_t>& rows) {
  const std::int16_t row = rows_of_[c];
  if (row < 0) {
    return fail(core::Code::TapeNoCode,
                fmt::format("line {} column {}: {} has no {} tape code; remove it from the "
                            "program (nothing was sent)",
                            line_ + 1, column + 1, shown(c), code_name(format_.code)));
  }
  rows.push_back(static_cast<std::uint8_t>(row));
  ++rows_;
  return true;
}

void TapeWriter::put_eob(std::vector<std::uint8_t>& rows) {
  if (format_.code == TapeCode::Eia) {
    rows.push_back(kEiaEndOfBlock);
    ++rows_;
    return;
  }
  auto put = [&](char c) {
    rows.push_back(*encode_char(format_.code, static_cast<unsigned char>(c)));
    ++rows_;
  };
  switch (format_.eob) {
  case EndOfBlock::Lf: put('\n'); break;
  case EndOfBlock::CrLf:
    put('\r');
    put('\n');
    break;
  case EndOfBlock::Cr: put('\r'); break;
  case EndOfBlock::Semicolon: put(';'); break;
  case EndOfBlock::Hash: put('#'); break;
  }
}

void TapeWriter::open_frame(std::vector<std::uint8_t>& rows) {
  put_feed(format_.leader, rows);
  put_char('%', 0, rows);
  put_eob(rows);
  state_ = State::InFrame;
}

bool TapeWriter::put_block(std::string_view block, std::vector<std::uint8_t>& rows,
                           std::vector<BlockMark>& marks) {
  // The hot loop of a drip feed: a table look-up a byte, one resize a block.
  const std::size_t at = rows.size();
  rows.resize(at + block.size());
  for (std::size_t i = 0; i < block.size(); ++i) {
    const std::int16_t row = rows_of_[static_cast<unsigned char>(block[i])];
    if (row < 0) {
      rows.resize(at + i);
      rows_ += i;
      return put_char(static_cast<unsigned char>(block[i]), i, rows);
    }
    rows[at + i] = static_cast<std::uint8_t>(row);
  }
  rows_ += block.size();
  const char own_end = format_.eob == EndOfBlock::Semicolon ? ';'
                       : format_.eob == EndOfBlock::Hash    ? '#'
                                                            : '\0';
  if (format_.code == TapeCode::Eia || own_end == '\0' || block.back() != own_end) put_eob(rows);
  marks.push_back(BlockMark{rows_, line_ + 1, block_number(block)});
  return true;
}

bool TapeWriter::end_line(std::vector<std::uint8_t>& rows, std::vector<BlockMark>& marks) {
  if (too_long_) {
    return fail(core::Code::BlockTooLong,
                fmt::format("line {} is longer than {} bytes; no control reads such a block "
                            "(nothing more was sent)",
                            line_ + 1, kMaxTapeBlock));
  }
  const std::string_view content = trim(block_);
  bool ok = true;
  if (state_ == State::AfterFrame) {
    ignored_ += content.size();
  } else if (content == "%") {
    // The program's own `%`: the first opens the frame, the next closes it.
    if (state_ == State::BeforeFrame) {
      open_frame(rows);
    } else {
      state_ = State::AfterFrame;
    }
  } else if (!content.empty()) {
    if (state_ == State::BeforeFrame) open_frame(rows);
    ok = put_block(block_, rows, marks);
  }
  block_.clear();
  ++line_;
  return ok;
}

bool TapeWriter::write(std::string_view text, std::vector<std::uint8_t>& rows,
                       std::vector<BlockMark>& marks) {
  std::size_t i = 0;
  while (i < text.size()) {
    // The run of the block up to its line end, appended at once.
    std::size_t end = i;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r')
      ++end;
    if (end > i) {
      after_cr_ = false;
      const std::size_t room = kMaxTapeBlock - std::min(kMaxTapeBlock, block_.size());
      block_.append(text.substr(i, std::min(room, end - i)));
      if (end - i > room) too_long_ = true;
    }
    if (end == text.size()) break;
    const char c = text[end];
    i = end + 1;
    if (c == '\n' && after_cr_) {
      after_cr_ = false;
      continue;
    }
    after_cr_ = c == '\r';
    if (!end_line(rows, marks)) return false;
  }
  return true;
}

bool TapeWriter::finish(std::vector<std::uint8_t>& rows, std::vector<BlockMark>& marks) {
  if ((!block_.empty() || too_long_) && !end_line(rows, marks)) return false;
  if (state_ == State::BeforeFrame) open_frame(rows);
  put_char('%', 0, rows);
  put_feed(format_.trailer, rows);
  state_ = State::AfterFrame;
  return true;
}

}  // namespace usina::dnc
