// The romi dialect's G/M table (romi/dialect.cpp: code → modal group → handler
// name), resolved once (gcode/code_table.hpp): each code's handler is a
// member function of romi's translator, its group a rank in the order of
// execution; and the codes of one block by rank.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gcode/code_table.hpp"
#include "gcode/dialect.hpp"

namespace usina::gcode::romi {

class Translator;

// Runs one code of the block (code in tenths); false after reporting an
// error. Every handler has this signature.
using Handler = bool (Translator::*)(int code);

// One code of the table, resolved.
using Code = ResolvedCode<Handler>;

// The romi table resolved (gcode/code_table.hpp), with the rank from which
// the groups run after the block's move.
class CodeTable {
 public:
  static constexpr int kMaxGroups = CodeIndex::kMaxGroups;
  // Codes are whole tenths from 0 to 9990 (G00 to G999): a larger value
  // is not a code (the front end says so before it looks a code up).
  static constexpr int kMaxTenths = 9990;

  // `resolve` gives the handler of a name, or nullptr. Groups from
  // `after_move` on run after the block's move. A handler name nothing
  // resolves, a code out of range or too many groups is a programming
  // error (std::logic_error): the dialect's table is wrong.
  CodeTable(const Dialect& dialect, Handler (*resolve)(std::string_view), int after_move)
      : table_(dialect.name, dialect.codes, kMaxTenths, resolve),
        first_after_move_(table_.index().rank(after_move)) {}

  // The code, or nullptr when the table has none (letter 'G' or 'M').
  const Code* find(char letter, int tenths) const { return table_.find(letter, tenths); }

  // The rank of the first group that runs after the block's move.
  int first_after_move() const { return first_after_move_; }

  int ranks() const { return table_.index().ranks(); }

  std::string_view dialect_name() const { return table_.index().dialect(); }

 private:
  gcode::CodeTable<Handler> table_;
  int first_after_move_;
};

// The codes of one block, at most one a group, in the order of execution.
class BlockCodes {
 public:
  void clear() { present_ = 0; }

  // The code already placed in `c`'s group, or nullptr after placing `c`.
  const Code* place(const Code& c) {
    const std::uint32_t bit = 1u << c.rank;
    if ((present_ & bit) != 0) return by_rank_[static_cast<std::size_t>(c.rank)];
    present_ |= bit;
    by_rank_[static_cast<std::size_t>(c.rank)] = &c;
    return nullptr;
  }

  // Runs `f(const Code&)` on the codes of ranks [from, to) in order while
  // it returns true; false when one returned false.
  template <typename F>
  bool each(int from, int to, F&& f) const {
    for (int r = from; r < to; ++r) {
      if (((present_ >> r) & 1u) == 0) continue;
      if (!f(*by_rank_[static_cast<std::size_t>(r)])) return false;
    }
    return true;
  }

 private:
  std::array<const Code*, CodeTable::kMaxGroups> by_rank_{};
  std::uint32_t present_ = 0;
};

}  // namespace usina::gcode::romi
