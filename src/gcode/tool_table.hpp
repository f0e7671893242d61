// LinuxCNC tool tables (`tool.tbl`): one tool a line, words T P X Y Z A B C
// U V W D I J Q and a `;` comment. Read into mm; the interpreter looks tools
// up by number (T, M6, G43 H, G41/G42 D, G10 L1).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "core/vec3.hpp"

namespace usina::gcode {

// One tool. Lengths in mm; angles in degrees, as written (LinuxCNC docs,
// "Tool Table Format": offsets and diameter are in machine units).
struct ToolEntry {
  int number = 0;                      // T
  int pocket = 0;                      // P
  core::Vec3 offset{};                 // X Y Z, mm
  std::array<double, 3> abc_offset{};  // A B C, degrees
  std::array<double, 3> uvw_offset{};  // U V W, mm
  double diameter = 0;                 // D, mm
  double front_angle = 0;              // I, degrees (lathe)
  double back_angle = 0;               // J, degrees (lathe)
  int orientation = 0;                 // Q, 0..9 (lathe)
  std::string comment{};               // text after ';', blanks trimmed
  std::uint32_t line = 0;              // the table's line it was read from (0: not from a file)
};

// Tools by number. Pointers from find() stay valid until the next set() or
// define().
//
// A table that lists tools (one read from a file, or filled by set()) is
// the machine's: a number it does not list is no tool (E_UNKNOWN_TOOL). The
// default table lists none: with no --tool-table a program is checked
// without the machine's table, so every number is a tool whose length and
// diameter are unknown and used as 0 (docs/rs274ngc.md, "Tools").
class ToolTable {
 public:
  ToolTable() = default;

  explicit ToolTable(bool lists_tools) : lists_tools_(lists_tools) {}

  // The tool numbered `number`, or nullptr.
  const ToolEntry* find(int number) const;
  // Adds `entry`, replacing any tool of the same number; the table then
  // lists tools.
  void set(ToolEntry entry);
  // Adds or replaces a tool as the program does (G10 L1/L10/L11): whether
  // the table lists tools does not change.
  void define(ToolEntry entry);

  bool lists_tools() const { return lists_tools_; }

  std::size_t size() const { return entries_.size(); }

  bool empty() const { return entries_.empty(); }

  // Every tool, by ascending number.
  const std::vector<ToolEntry>& entries() const { return entries_; }

 private:
  std::vector<ToolEntry> entries_;  // sorted by number, numbers unique
  bool lists_tools_ = false;
};

// LinuxCNC docs, "Tool Table Format": orientation Q is 0..9.
inline constexpr int kMaxToolOrientation = 9;

// Reads `file` (its diagnostics carry `file_id`). Lengths are in the
// machine's units, `mm_per_unit` mm each (25.4 for an inch machine); they are
// stored in mm. A bad line is reported (E_BAD_TOOL_TABLE, file:line:col) and
// skipped; a tool number given twice is a warning (W_TOOL_REDEFINED) and the
// later line wins; a line without P, a warning (W_TOOL_WITHOUT_POCKET).
// nullopt only when lines were bad and no tool was read; a file of blank and
// comment lines is an empty table (which lists tools: none). Throws std::invalid_argument when
// `mm_per_unit` is not a positive finite number (a programmer error).
std::optional<ToolTable> read_tool_table(const core::SourceFile& file, std::uint32_t file_id,
                                         double mm_per_unit, core::DiagnosticSink& diags);

}  // namespace usina::gcode
