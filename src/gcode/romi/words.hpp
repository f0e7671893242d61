// A romi block's words other than G and M, evaluated: what the front end
// hands its handlers (with the block's codes, romi/codes.hpp). A handler
// takes the letters it uses; a letter nobody took is an error.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <optional>

namespace usina::gcode::romi {

class Words {
 public:
  // Nothing given: four stores, once a block.
  void reset() { given_ = forgotten_ = taken_ = incremental_ = 0; }

  bool has(char c) const { return (present() & bit(c)) != 0; }

  // Present and not yet taken by a handler.
  bool open(char c) const { return (present() & ~taken_ & bit(c)) != 0; }

  // The value and column of a letter the block gave (0 when it gave none).
  double get(char c) const { return (given_ & bit(c)) != 0 ? value_[index(c)] : 0.0; }

  std::uint32_t col(char c) const { return (given_ & bit(c)) != 0 ? col_[index(c)] : 0; }

  // Written as an increment whatever G90/G91 say (lowercase_incremental).
  bool incremental(char c) const { return (incremental_ & bit(c)) != 0; }

  void set(char c, double v, bool incremental, std::uint32_t col) {
    given_ |= bit(c);
    forgotten_ &= ~bit(c);
    taken_ &= ~bit(c);
    incremental_ = incremental ? incremental_ | bit(c) : incremental_ & ~bit(c);
    value_[index(c)] = v;
    col_[index(c)] = col;
  }

  std::optional<double> take(char c) {
    if (!has(c)) return std::nullopt;
    taken_ |= bit(c);
    return value_[index(c)];
  }

  // Letters a handler took are no longer the block's to move with.
  void forget_taken() { forgotten_ |= taken_; }

  // The first letter present and not taken, or 0.
  char untaken() const {
    const std::uint32_t left = present() & ~taken_;
    if (left == 0) return 0;
    return static_cast<char>('A' + std::countr_zero(left));
  }

 private:
  static std::size_t index(char c) { return static_cast<std::size_t>(c - 'A'); }

  static std::uint32_t bit(char c) { return 1u << index(c); }

  std::uint32_t present() const { return given_ & ~forgotten_; }

  // By letter, A to Z; a slot means something only while its letter is given.
  std::array<double, 26> value_{};
  std::array<std::uint32_t, 26> col_{};
  std::uint32_t given_ = 0;
  std::uint32_t forgotten_ = 0;
  std::uint32_t taken_ = 0;
  std::uint32_t incremental_ = 0;
};

}  // namespace usina::gcode::romi
