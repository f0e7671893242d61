// One character to one tape row and back, in the three codes a control
// reads (research/dnc.md §2.3): ASCII as it is; ISO 840, 7-bit ASCII with
// even parity on channel 8 (bit 7); EIA RS-244, a code of its own with odd
// parity on channel 5 (bit 4) and the end of block on channel 8.
//
// The EIA table (tape_code.cpp) follows RS-244's layout: digits on channels
// 1-4 with channel 6 for zero, letters a-i on channels 6+7, j-r on 7, s-z on
// 6, each with channel 5 added where the count of holes would be even; the
// control-out/in codes `(` = 2-4-5 and `)` = 2-4-7 are those of the
// YASNAC LX3 function-character table (research/dnc.md [34]).
#pragma once

#include <cstdint>
#include <optional>

#include "dnc/link_config.hpp"

namespace usina::dnc {

// The row of the end-of-block code in EIA (channel 8 alone) and of ER, EIA's
// end of record (ISO's `%`).
inline constexpr std::uint8_t kEiaEndOfBlock = 0x80;
inline constexpr std::uint8_t kEiaEndOfRecord = 0x0B;
inline constexpr std::uint8_t kNul = 0x00;
inline constexpr std::uint8_t kDel = 0x7F;
inline constexpr std::uint8_t kDc2 = 0x12;  // a control starts to punch
inline constexpr std::uint8_t kDc4 = 0x14;  // a control ends its punch

// The row of `c` in `code`, or nothing when the code has no such character.
// ASCII passes every byte; ISO every 7-bit byte; EIA letters (either case),
// digits, space, `+ - / . , ( ) %`, LF or CR (the end of block), DEL, BS, TAB.
std::optional<std::uint8_t> encode_char(TapeCode code, unsigned char c);

// What a received row means.
struct DecodedRow {
  enum class Kind : std::uint8_t {
    Char,        // `ch` is a character of the program (LF for EIA's end of block)
    Feed,        // NUL or DEL: tape feed and "all mark", ignored by a reader
    BadParity,   // the row's parity is wrong for the code
    NoSuchCode,  // a row with the right parity that the code does not define
  };
  Kind kind = Kind::Char;
  char ch = 0;
};

// `check_parity` is false when the UART has taken the parity bit off (7 data
// bits: channel 8 never reaches usina, the UART checked it).
DecodedRow decode_row(TapeCode code, std::uint8_t row, bool check_parity);

// The number of holes is even (ISO's rule for every row).
constexpr bool even_parity(std::uint8_t row) {
  unsigned v = row;
  v ^= v >> 4U;
  v ^= v >> 2U;
  v ^= v >> 1U;
  return (v & 1U) == 0U;
}

}  // namespace usina::dnc
