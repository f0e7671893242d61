// A LinuxCNC tool table (`tool.tbl`: `T1 P1 D6.0 ;comment` lines, read by
// gcode/tool_table) as a job's tool library (docs/job.md, "A LinuxCNC tool
// table as the library"). The table gives the number and the diameter; what
// it does not say (type, tool material, flutes, cutting length ...) is read
// from the tool's comment where the comment says it plainly, and is an error
// at the tool's line where it does not: never a guess.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/diagnostic.hpp"
#include "core/source.hpp"
#include "job/tools.hpp"

namespace usina::job {

// The table in `file` (its diagnostics carry `file_id`), lengths in the
// machine's units, `mm_per_unit` mm each. Every problem an error
// (E_BAD_TOOL_TABLE from the table's reader, E_BAD_TOOL_LIBRARY for what a
// tool lacks or says twice) at the tool's line; nullopt after any.
std::optional<std::vector<Tool>> read_tool_table_library(const core::SourceFile& file,
                                                         std::uint32_t file_id, double mm_per_unit,
                                                         core::DiagnosticSink& diags);

}  // namespace usina::job
