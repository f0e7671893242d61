#include "gcode/program_text.hpp"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

namespace usina::gcode {

core::Diagnostic block_too_long(std::string_view block, const core::SourceLoc& start) {
  core::SourceLoc at = start;
  constexpr std::uint64_t kMaxCol = std::numeric_limits<std::uint32_t>::max();
  at.col = static_cast<std::uint32_t>(
      std::min<std::uint64_t>(std::uint64_t{start.col} + kMaxBlockLength, kMaxCol));
  at.length = 1;
  std::string message = fmt::format(
      "a block of {} characters: usina reads blocks of at most {} (a control's block "
      "buffer holds a few hundred); end the block sooner or shorten its comment",
      block.size(), kMaxBlockLength);
  // A file whose lines end with CR alone (classic Mac OS) reads as one
  // block: a CR with more text after it (not the CR of CR LF).
  const std::size_t cr = block.find('\r');
  if (cr != std::string_view::npos && cr + 1 < block.size() && block[cr + 1] != '\n') {
    message += "; its lines end with CR alone: convert the line ends to LF";
  }
  return {core::Code::BlockTooLong, core::Severity::Error, at, std::move(message)};
}

namespace {

constexpr std::string_view kBom = "\xEF\xBB\xBF";

}  // namespace

std::size_t byte_order_mark_length(std::string_view text) {
  return text.starts_with(kBom) ? kBom.size() : 0;
}

std::size_t skip_byte_order_mark(std::string_view text, std::uint32_t file,
                                 core::DiagnosticSink& diags) {
  if (!text.starts_with(kBom)) return 0;
  diags.report({core::Code::ByteOrderMark,
                core::Severity::Warning,
                {file, 1, 1, 3, 0},
                "UTF-8 byte-order mark at the start of the file ignored; some controls refuse it "
                "(LinuxCNC does): save the file without it"});
  return kBom.size();
}

}  // namespace usina::gcode
