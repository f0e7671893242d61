// The program index: one pass over a file records every O-word statement
// (offset, line, label, kind) and links each to the previous and next
// statement of the same label, so control flow jumps by index and a
// straight-line program still streams (DESIGN.md, "Program index").
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "gcode/block.hpp"

namespace usina::gcode {

inline constexpr std::uint32_t kNoEntry = 0xffffffffu;

struct OEntry {
  OKind kind = OKind::Sub;
  std::string label;
  std::uint64_t offset = 0;     // the line's first byte
  std::uint64_t next_line = 0;  // the first byte after the line
  std::uint32_t line = 0;
  std::uint32_t next_same = kNoEntry;
  std::uint32_t prev_same = kNoEntry;
  bool ends_do = false;  // a `while` that closes a `do` loop
};

class ProgramIndex {
 public:
  // Scans `file`; syntax errors on O-word lines are left to the interpreter.
  static ProgramIndex build(core::SourceFile& file, std::uint32_t file_id);

  const std::vector<OEntry>& entries() const { return entries_; }

  const OEntry& at(std::uint32_t i) const { return entries_[i]; }

  // The entry at a line's offset, or kNoEntry.
  std::uint32_t find(std::uint64_t offset) const;
  // The `sub` entry of a subroutine, or kNoEntry.
  std::uint32_t sub(const std::string& name) const;
  // Following next_same (or prev_same) links from `from`, the first entry
  // whose kind is one of `kinds`; kNoEntry if none.
  std::uint32_t next_of(std::uint32_t from, std::initializer_list<OKind> kinds) const;
  std::uint32_t prev_of(std::uint32_t from, std::initializer_list<OKind> kinds) const;

 private:
  void link();
  std::vector<OEntry> entries_;
  std::unordered_map<std::string, std::uint32_t> subs_;
};

// The line starting at `offset` of `text`: its content without end-of-line
// characters, and the offset of the next line.
struct LineView {
  std::string_view text;
  std::uint64_t next = 0;
};

LineView line_at(std::string_view text, std::uint64_t offset);

}  // namespace usina::gcode
