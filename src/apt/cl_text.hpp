// Readers of the CL files other CAM systems write, as text (research/apt.md
// §6.2): Siemens NX's CLSF and the APT CL of SolidWorks CAM and Creo, into
// the one CL model (cl.hpp), so that every back end reads them through the
// canon stream. The dialects differ in the direction of CIRCLE/'s axis: in
// NX a +k arc runs clockwise, in the others counter-clockwise (the
// right-hand rule); the records hold the right-hand axis.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "apt/cl.hpp"
#include "core/diagnostic.hpp"

namespace usina::apt {

enum class ClDialect { Clsf, AptCl };

// Bounds that keep hostile input finite.
inline constexpr std::size_t kMostClStatementBytes = 64 * 1024;  // continuations joined
inline constexpr std::size_t kMostClArguments = 1024;
inline constexpr double kLargestClNumber = 1e12;

// What a reader hands on: the records, and the unit a UNITS statement sets
// (mm per unit) for the records after it.
struct ClConsumer {
  std::function<bool(ClRecord&&)> record;  // false: stop reading
  std::function<void(double)> units;
};

// Reads the CL text of file `file` in order. Each statement that writes
// records is preceded by a source record (1000, its line). Every error is a
// diagnostic at its line and column (E_CL_...); the statement is left out
// and reading goes on.
void read_cl_text(std::string_view text, std::uint32_t file, ClDialect dialect,
                  core::DiagnosticSink& diags, const ClConsumer& out);

// Every record (tests); the units are dropped.
std::vector<ClRecord> read_cl_text(std::string_view text, std::uint32_t file, ClDialect dialect,
                                   core::DiagnosticSink& diags);

}  // namespace usina::apt
