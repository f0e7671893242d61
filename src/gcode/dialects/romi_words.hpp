// A romi block's words other than G and M, evaluated: what the front end
// hands the executor (with the block's codes, romi_codes.hpp). A handler
// takes the letters it uses; a letter nobody took is an error.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

namespace usina::gcode::romi {

class Words {
 public:
  struct Slot {
    bool present = false;
    bool incremental = false;  // this word alone (a lower-case letter)
    bool taken = false;
    double value = 0.0;
    std::uint32_t col = 0;
  };

  void reset() { slots_.fill({}); }

  bool has(char c) const { return at(c).present; }

  // Present and not yet taken by a handler.
  bool open(char c) const { return at(c).present && !at(c).taken; }

  double get(char c) const { return at(c).value; }

  // Written as an increment whatever G90/G91 say (lowercase_incremental).
  bool incremental(char c) const { return at(c).incremental; }

  std::uint32_t col(char c) const { return at(c).col; }

  void set(char c, double v, bool incremental, std::uint32_t col) {
    at(c) = {true, incremental, false, v, col};
  }

  std::optional<double> take(char c) {
    Slot& s = at(c);
    if (!s.present) return std::nullopt;
    s.taken = true;
    return s.value;
  }

  // Letters a handler took are no longer the block's to move with.
  void forget_taken() {
    for (Slot& s : slots_) {
      if (s.taken) s.present = false;
    }
  }

  // The first letter present and not taken, or 0.
  char untaken() const {
    for (char c = 'A'; c <= 'Z'; ++c) {
      if (has(c) && !at(c).taken) return c;
    }
    return 0;
  }

 private:
  Slot& at(char c) { return slots_[static_cast<std::size_t>(c - 'A')]; }

  const Slot& at(char c) const { return slots_[static_cast<std::size_t>(c - 'A')]; }

  std::array<Slot, 26> slots_{};
};

}  // namespace usina::gcode::romi
