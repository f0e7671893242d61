#include "dnc/tape_code.hpp"

#include <array>

namespace usina::dnc {
namespace {

// EIA RS-244: channel n is bit n-1; channel 5 (0x10) is the odd-parity hole.
struct EiaEntry {
  char ch;
  std::uint8_t row;
};

constexpr std::array<EiaEntry, 50> kEia{{
    {'0', 0x20},
    {'1', 0x01},
    {'2', 0x02},
    {'3', 0x13},
    {'4', 0x04},
    {'5', 0x15},
    {'6', 0x16},
    {'7', 0x07},
    {'8', 0x08},
    {'9', 0x19},
    {'A', 0x61},
    {'B', 0x62},
    {'C', 0x73},
    {'D', 0x64},
    {'E', 0x75},
    {'F', 0x76},
    {'G', 0x67},
    {'H', 0x68},
    {'I', 0x79},
    {'J', 0x51},
    {'K', 0x52},
    {'L', 0x43},
    {'M', 0x54},
    {'N', 0x45},
    {'O', 0x46},
    {'P', 0x57},
    {'Q', 0x58},
    {'R', 0x49},
    {'S', 0x32},
    {'T', 0x23},
    {'U', 0x34},
    {'V', 0x25},
    {'W', 0x26},
    {'X', 0x37},
    {'Y', 0x38},
    {'Z', 0x29},
    {' ', 0x10},
    {'+', 0x70},
    {'-', 0x40},
    {'/', 0x31},
    {'.', 0x6B},
    {',', 0x3B},
    {'(', 0x1A},
    {')', 0x4A},
    {'%', kEiaEndOfRecord},  // ER: end of record
    {'\n', kEiaEndOfBlock},  // EOB (channel 8; the one even row)
    {'\b', 0x2A},            // BS
    {'\t', 0x3E},            // TAB
    {'\x7f', kDel},          // DEL: all of channels 1-7
    {'\0', kNul},            // blank tape
}};

// Both directions of the table, built once at compile time.
struct EiaTables {
  std::array<std::int16_t, 256> to_row{};
  std::array<std::int16_t, 256> to_char{};
};

constexpr EiaTables make_eia_tables() {
  EiaTables t;
  for (auto& v : t.to_row)
    v = -1;
  for (auto& v : t.to_char)
    v = -1;
  for (const EiaEntry& e : kEia) {
    t.to_row[static_cast<unsigned char>(e.ch)] = e.row;
    t.to_char[e.row] = static_cast<unsigned char>(e.ch);
  }
  // No case on tape: a lower-case letter is punched as its capital.
  for (int c = 'a'; c <= 'z'; ++c)
    t.to_row[static_cast<std::size_t>(c)] = t.to_row[static_cast<std::size_t>(c - 'a' + 'A')];
  t.to_row[static_cast<unsigned char>('\r')] = kEiaEndOfBlock;
  return t;
}

constexpr EiaTables kEiaTables = make_eia_tables();

// Every row of the table has an odd number of holes, but EOB and blank.
constexpr bool eia_table_is_odd() {
  for (const EiaEntry& e : kEia) {
    if (e.row == kEiaEndOfBlock || e.row == kNul) continue;
    if (even_parity(e.row)) return false;
  }
  return true;
}

static_assert(eia_table_is_odd(), "an EIA row must have an odd number of holes");

DecodedRow decode_eia(std::uint8_t row, bool check_parity) {
  using Kind = DecodedRow::Kind;
  if (row == kNul || row == kDel) return {Kind::Feed, 0};
  if (row == kEiaEndOfBlock) return {Kind::Char, '\n'};
  if (check_parity && even_parity(row)) return {Kind::BadParity, 0};
  const std::int16_t c = kEiaTables.to_char[row];
  if (c < 0) return {Kind::NoSuchCode, 0};
  return {Kind::Char, static_cast<char>(c)};
}

DecodedRow decode_iso(std::uint8_t row, bool check_parity) {
  using Kind = DecodedRow::Kind;
  if (check_parity && !even_parity(row)) return {Kind::BadParity, 0};
  const auto c = static_cast<std::uint8_t>(row & 0x7FU);
  if (c == kNul || c == kDel) return {Kind::Feed, 0};
  return {Kind::Char, static_cast<char>(c)};
}

}  // namespace

std::optional<std::uint8_t> encode_char(TapeCode code, unsigned char c) {
  switch (code) {
  case TapeCode::Ascii: return c;
  case TapeCode::Iso:
    if (c > 0x7F) return std::nullopt;
    return static_cast<std::uint8_t>(even_parity(c) ? c : (c | 0x80U));
  case TapeCode::Eia: {
    const std::int16_t row = kEiaTables.to_row[c];
    if (row < 0) return std::nullopt;
    return static_cast<std::uint8_t>(row);
  }
  }
  return std::nullopt;
}

DecodedRow decode_row(TapeCode code, std::uint8_t row, bool check_parity) {
  switch (code) {
  case TapeCode::Ascii:
    if (row == kNul) return {DecodedRow::Kind::Feed, 0};
    return {DecodedRow::Kind::Char, static_cast<char>(row)};
  case TapeCode::Iso: return decode_iso(row, check_parity);
  case TapeCode::Eia: return decode_eia(row, check_parity);
  }
  return {DecodedRow::Kind::NoSuchCode, 0};
}

}  // namespace usina::dnc
