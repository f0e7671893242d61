// A block's words after evaluation (step 1) and their modal groups (step 2).
#pragma once

#include <array>
#include <cstdint>

#include "gcode/interp/codes.hpp"

namespace usina::gcode {

struct BlockWords {
  // '@' (0), A..Z (1-26) and '^' (30), by their codes: a slot is a
  // subtraction, with no test of the letter (hot: every word of every block).
  static constexpr int kSlots = '^' - '@' + 1;

  static constexpr int slot(char letter) { return letter - '@'; }

  bool has(char letter) const { return (present >> slot(letter)) & 1u; }

  double get(char letter) const { return value[static_cast<std::size_t>(slot(letter))]; }

  // 0 (the block) for a letter the block lacks: its slot may hold the
  // column of an earlier block's word.
  std::uint32_t col_of(char letter) const {
    return has(letter) ? col[static_cast<std::size_t>(slot(letter))] : 0;
  }

  // The column of the first axis word the block has, 0 when none.
  std::uint32_t axis_col() const {
    for (const char c : {'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'}) {
      if (has(c)) return col_of(c);
    }
    return 0;
  }

  void set(char letter, double v, std::uint32_t c) {
    const auto i = static_cast<std::size_t>(slot(letter));
    value[i] = v;
    col[i] = c;
    present |= 1u << slot(letter);
  }

  void clear_letter(char letter) { present &= ~(1u << slot(letter)); }

  // Written as an increment whatever G90/G91 say (EvaluatedWord::incremental).
  bool incremental(char letter) const { return (increments >> slot(letter)) & 1u; }

  void mark_incremental(char letter) { increments |= 1u << slot(letter); }

  bool has_axis() const {
    for (const char c : {'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'}) {
      if (has(c)) return true;
    }
    return false;
  }

  bool has_polar() const { return has('@') || has('^'); }

  std::array<double, kSlots> value{};
  std::array<std::uint32_t, kSlots> col{};
  std::uint32_t present = 0;
  std::uint32_t increments = 0;  // by slot: the words marked as increments

  // G and M codes by modal group (-1: none in this block) and their columns.
  std::array<GCode, kGGroups> g{};
  std::array<std::uint32_t, kGGroups> gcol{};
  std::array<int, kMGroups> m{};
  std::array<std::uint32_t, kMGroups> mcol{};
  bool m7_and_m8 = false;       // LinuxCNC allows both coolants in one block
  std::array<int, 4> user_m{};  // M100..M199, in order
  int user_m_count = 0;

  // The motion this block performs (-1: none).
  GCode motion = -1;

  void reset() {
    present = 0;
    increments = 0;
    g.fill(-1);
    m.fill(-1);
    m7_and_m8 = false;
    user_m_count = 0;
    motion = -1;
  }
};

}  // namespace usina::gcode
