// LinuxCNC parameter files (`*.var`): the numbered parameters that outlive a
// run (work offsets 5221..5390, G28/G30 homes, ...), one "NUMBER VALUE" a
// line in ascending order. Named parameters are never stored there (LinuxCNC
// docs, G-code overview, "Named Parameters": "They are not stored in files").
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source.hpp"

namespace usina::gcode {

struct VarFileEntry {
  int number = 0;
  double value = 0;  // as written: no unit conversion

  bool operator==(const VarFileEntry&) const = default;
};

// LinuxCNC rs274ngc.hh: RS274NGC_MAX_PARAMETERS is 5602, the size of the
// parameter array; restore_parameters() rejects a number <= 0 or >= 5602.
inline constexpr int kMinVarFileParameter = 1;
inline constexpr int kMaxVarFileParameter = 5601;

// Reads `file` (its diagnostics carry `file_id`; errors E_BAD_VAR_FILE,
// warnings W_VAR_FILE_LINE_SKIPPED and W_VAR_FILE_EXTRA_TEXT). The
// entries come back in ascending order. A line with an error (a malformed or
// missing number or value, a number outside 1..5601, a number not above the
// previous line's, which LinuxCNC refuses) is reported and skipped; a line
// that is not "NUMBER VALUE" at all, which LinuxCNC skips silently, is a
// warning; text after the value is a warning and ignored. An empty file is
// valid (LinuxCNC starts from one). nullopt only when lines were bad and no
// entry was read.
std::optional<std::vector<VarFileEntry>> read_var_file(const core::SourceFile& file,
                                                       std::uint32_t file_id,
                                                       core::DiagnosticSink& diags);

// The inverse: one "NUMBER<tab>VALUE" line per entry, ascending, the value
// with six decimals, as LinuxCNC's save_parameters() writes ("%d\t%f\n").
// When a number is given twice the later entry wins. Throws
// std::invalid_argument for a number outside 1..5601 or a value that is not
// finite (programmer errors: the interpreter never holds such parameters).
std::string write_var_file(std::span<const VarFileEntry> entries);

}  // namespace usina::gcode
