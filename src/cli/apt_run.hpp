// APT part programs on the road of the verbs that run programs (check,
// draw, stats, trace, convert): a file named *.apt goes through the APT
// processor into the canon stream instead of a G-code dialect (docs/apt.md).
#pragma once

#include <cstdint>
#include <string_view>

#include "canon/sink.hpp"
#include "cli/diagnostic_printer.hpp"
#include "core/source.hpp"

namespace usina::cli {

// Whether `file` names an APT part program: its extension is .apt (any case).
bool is_apt_file(std::string_view file);

// The APT program `id` of `sources` into `sink` (`scale` mm per program
// unit, at most `max_ops` ops as --max-ops says); 0, or 1 when it has errors.
int run_apt_program(const core::SourceManager& sources, std::uint32_t id, double scale,
                    canon::Sink& sink, DiagnosticPrinter& diags, std::uint64_t max_ops);

}  // namespace usina::cli
