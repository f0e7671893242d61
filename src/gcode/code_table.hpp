// A dialect's G/M table (Dialect::codes: code → modal group → handler name)
// resolved once, when its runner is made: a code is found by index, never
// by name per block; each group has a rank (its place among the table's
// groups in ascending order, the order a block runs them in); each handler
// name is resolved to the runner's handler. Every runner reads its
// dialect's table through this: the RS274NGC interpreter (interp/codes.hpp)
// for rs274ngc and fanuc, romi's handlers, grbl's block check.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "gcode/code_entry.hpp"

namespace usina::gcode {

// The codes of a table by letter and tenths, and the ranks of its groups.
class CodeIndex {
 public:
  // Groups a table may have: a block's codes fit one bit each.
  static constexpr int kMaxGroups = 32;

  // Codes are tenths from 0 to `max_tenths` (G38.2: 382); a larger one is
  // not in any table. A code out of range, a letter other than G or M, too
  // many groups or codes is a programming error (std::logic_error): the
  // dialect's table is wrong.
  CodeIndex(std::string_view dialect, const std::vector<CodeEntry>& codes, int max_tenths);

  // The position in the table of the first entry of the code (the one in
  // force, as Dialect::find_code), or -1.
  int position(char letter, int tenths) const {
    if (tenths < 0 || tenths > max_tenths_ || (letter != 'G' && letter != 'M')) return -1;
    return static_cast<int>(index_[slot(letter, tenths)]) - 1;
  }

  const CodeEntry* find(char letter, int tenths) const {
    const int i = position(letter, tenths);
    return i < 0 ? nullptr : &(*codes_)[static_cast<std::size_t>(i)];
  }

  // Some code of `letter` has the whole part `integer` (G38: G38.2 ...).
  bool has_integer(char letter, int integer) const;

  // The rank of a group of the table; of a group it lacks, the rank of the
  // next larger one (ranks() when none).
  int rank(int group) const;

  int ranks() const { return static_cast<int>(groups_.size()); }

  std::string_view dialect() const { return dialect_; }

  const std::vector<CodeEntry>& entries() const { return *codes_; }

 private:
  std::size_t slot(char letter, int tenths) const {
    const std::size_t m_codes = letter == 'M' ? static_cast<std::size_t>(max_tenths_) + 1 : 0;
    return m_codes + static_cast<std::size_t>(tenths);
  }

  std::string_view dialect_;
  const std::vector<CodeEntry>* codes_;
  int max_tenths_;
  std::vector<std::uint16_t> index_;  // by slot(): 0 none, else 1 + position in codes_
  std::vector<int> groups_;           // the groups' numbers, ascending
};

// A code of the table with its group's rank and its resolved handler.
template <typename Handler>
struct ResolvedCode {
  const CodeEntry* entry = nullptr;
  int rank = 0;
  Handler handler{};
};

// "G01", "M06", "G38.2": a code as a message names it.
std::string code_name(char letter, int tenths);

// Throws std::logic_error: `entry`'s handler name resolves to nothing.
[[noreturn]] void unresolved_handler(std::string_view dialect, const CodeEntry& entry);

// The index with every entry's handler resolved by `resolve` (a name →
// the runner's handler; `Handler{}` for a name it does not know, which is a
// programming error: std::logic_error).
template <typename Handler>
class CodeTable {
 public:
  using Code = ResolvedCode<Handler>;

  CodeTable(std::string_view dialect, const std::vector<CodeEntry>& codes, int max_tenths,
            Handler (*resolve)(std::string_view))
      : index_(dialect, codes, max_tenths) {
    codes_.reserve(codes.size());
    for (const CodeEntry& e : codes) {
      const Handler h = resolve(e.handler);
      if (h == Handler{}) unresolved_handler(dialect, e);
      codes_.push_back({&e, index_.rank(e.group), h});
    }
  }

  // The code, or nullptr when the table has none.
  const Code* find(char letter, int tenths) const {
    const int i = index_.position(letter, tenths);
    return i < 0 ? nullptr : &codes_[static_cast<std::size_t>(i)];
  }

  const CodeIndex& index() const { return index_; }

 private:
  CodeIndex index_;
  std::vector<Code> codes_;  // as the table's entries
};

}  // namespace usina::gcode
