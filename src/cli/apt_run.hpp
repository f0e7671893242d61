// APT part programs and CL files on the road of the verbs that run programs
// (check, draw, stats, trace, convert): a file named *.apt goes through the
// APT processor, a CL file (NX CLSF, APT CL, binary CLDATA) through its
// reader, into the canon stream instead of a G-code dialect (docs/apt.md).
#pragma once

#include <cstdint>
#include <string_view>

#include "canon/sink.hpp"
#include "cli/diagnostic_printer.hpp"
#include "core/source.hpp"

namespace usina::cli {

enum class ProgramLanguage { Gcode, Apt, Clsf, AptCl, Cldata };

// The names --from takes besides the G-code dialects'.
inline constexpr std::string_view kClLanguages[] = {"apt", "clsf", "aptcl", "cldata"};

// The language of `file`: --from's `from` when it names one of
// kClLanguages (a dialect's name is G-code), else the file's extension:
// .apt, .cls and .clsf (NX), .ncl (Creo), .cldata; any other is G-code.
ProgramLanguage program_language(std::string_view from, std::string_view file);

// The program `id` of `sources` in `language` into `sink` (`scale` mm per
// program unit until a UNITS statement says otherwise, at most `max_ops`
// ops as --max-ops says); 0, or 1 when it has errors.
int run_apt_program(const core::SourceManager& sources, std::uint32_t id, ProgramLanguage language,
                    double scale, canon::Sink& sink, DiagnosticPrinter& diags,
                    std::uint64_t max_ops);

}  // namespace usina::cli
