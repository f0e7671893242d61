// libFuzzer target for the lexer and parser: the input is a program, fed
// line by line to parse_block exactly as the interpreter reads it. Any
// input must give blocks or diagnostics, never a crash or a hang.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/diagnostic.hpp"
#include "gcode/block.hpp"
#include "gcode/parser.hpp"
#include "gcode/program_index.hpp"

namespace {

class DiscardDiagnostics final : public usina::core::DiagnosticSink {
 public:
  void report(usina::core::Diagnostic d) override { (void)d; }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  DiscardDiagnostics diags;
  usina::gcode::Block block;  // reused from line to line, as the interpreter does
  std::uint64_t offset = 0;
  std::uint32_t line = 1;
  while (offset < text.size()) {
    const usina::gcode::LineView lv = usina::gcode::line_at(text, offset);
    const usina::gcode::LinePos where{0, line, offset};
    usina::gcode::parse_block(lv.text, where, block, diags);
    if (lv.next <= offset) break;  // line_at must move forward; stop rather than spin
    offset = lv.next;
    ++line;
  }
  return 0;
}
