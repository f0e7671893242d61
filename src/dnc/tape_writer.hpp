// A program's text to the rows put on the wire, a slice at a time, in
// constant memory (one block at most, kMaxTapeBlock bytes): NUL leader, `%`
// (EIA: ER), the blocks each ended by the machine's end of block, `%`, NUL
// trailer. The leader and trailer are outside the `%` frame because EIA
// controls take a NUL inside it for an error (research/dnc.md §2.3).
//
// The program's own frame is not sent twice: a first line that is `%` is
// the opening of the frame, and a later `%` line closes it; what follows
// that `%` is not sent (counted in ignored_bytes() so the caller can say so).
// Blank lines inside the frame are not sent (a control shows them as empty
// blocks). The block that ends with the end-of-block character itself (a
// romi `#`, a `;`) gets no second one.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"
#include "dnc/link_config.hpp"

namespace usina::dnc {

inline constexpr std::size_t kMaxTapeBlock = 65536;

struct TapeFormat {
  TapeCode code = TapeCode::Iso;
  EndOfBlock eob = EndOfBlock::Lf;
  std::uint32_t leader = 0;
  std::uint32_t trailer = 0;
  bool seven_bit = false;  // a 7-data-bit link: no byte above 127 in ASCII
};

TapeFormat tape_format(const LinkConfig& c);

// Where a block ends on the wire, so a transfer knows the line and block
// (N number) it has sent when its link is lost.
struct BlockMark {
  std::uint64_t wire_end = 0;  // rows written up to and including this block's end
  std::uint64_t line = 0;      // 1-based line of the program
  std::int64_t n_number = -1;  // the block's N word, -1 without one
};

class TapeWriter {
 public:
  explicit TapeWriter(TapeFormat format);

  // Appends the rows of `text`, the next slice of the program, to `rows`
  // and one mark per block to `marks`. False, with E_TAPE_NO_CODE or
  // E_BLOCK_TOO_LONG in `diag`, when a block cannot be written.
  bool write(std::string_view text, std::vector<std::uint8_t>& rows, std::vector<BlockMark>& marks);
  // The last block (a program need not end with a line end), the closing
  // `%` and the trailer.
  bool finish(std::vector<std::uint8_t>& rows, std::vector<BlockMark>& marks);

  const core::Diagnostic& diagnostic() const { return diag_; }

  std::uint64_t rows_written() const { return rows_; }

  std::uint64_t lines_read() const { return line_; }

  std::uint64_t ignored_bytes() const { return ignored_; }

 private:
  enum class State : std::uint8_t { BeforeFrame, InFrame, AfterFrame };

  bool end_line(std::vector<std::uint8_t>& rows, std::vector<BlockMark>& marks);
  bool put_block(std::string_view block, std::vector<std::uint8_t>& rows,
                 std::vector<BlockMark>& marks);
  void open_frame(std::vector<std::uint8_t>& rows);
  bool put_char(unsigned char c, std::size_t column, std::vector<std::uint8_t>& rows);
  void put_eob(std::vector<std::uint8_t>& rows);
  void put_feed(std::uint32_t count, std::vector<std::uint8_t>& rows);
  bool fail(core::Code code, std::string message);

  TapeFormat format_;
  std::array<std::int16_t, 256> rows_of_{};  // each byte's row, -1 for none
  State state_ = State::BeforeFrame;
  std::string block_;      // the line being read (at most kMaxTapeBlock bytes)
  bool after_cr_ = false;  // the last byte was CR: a LF right after it ends nothing
  bool too_long_ = false;
  std::uint64_t line_ = 0;  // lines ended so far
  std::uint64_t rows_ = 0;
  std::uint64_t ignored_ = 0;
  core::Diagnostic diag_;
};

// The N number at the start of a block (after `/` and blanks), or -1.
std::int64_t block_number(std::string_view block);

}  // namespace usina::dnc
