// '%' lines in the rs274ngc dialect, as LinuxCNC 2.9's rs274 reads them
// (checked with ../shared/conformance/lcnc-trace.sh; docs/rs274ngc.md,
// "'%' lines"): a '%' alone on the program's first line (blank lines and
// blanks before it allowed) opens the program, and the next '%' line ends it
// unread after it, also from a subroutine; any other '%' is an error, after
// the blocks before it have run. usina chooses differently in one case: a
// last '%' with nothing after it in a program it did not open ends the
// program with a warning (LinuxCNC reports an error, having run it all).
#include <fmt/format.h>

#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {
namespace {

constexpr std::string_view kBlanks = " \t\r\n\f\v";
constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

// Only blanks (and a byte-order mark at the very start) before `offset`.
bool first_line(std::string_view text, std::uint64_t offset) {
  std::string_view before = text.substr(0, offset);
  if (before.starts_with(kUtf8Bom)) before.remove_prefix(kUtf8Bom.size());
  return before.find_first_not_of(kBlanks) == std::string_view::npos;
}

}  // namespace

// The parser has checked that the '%' stands alone on its line.
Interpreter::Flow Interpreter::percent_line(const LinePos& where) {
  const std::string_view text = sources_.get(where.file)->text();
  if (percent_mode_) {
    ended_ = true;
    return Flow::End;
  }
  const bool main_file = frames_.empty();
  if (main_file && first_line(text, where.offset)) {
    percent_mode_ = true;
    return Flow::Next;
  }
  if (main_file && text.find_first_not_of(kBlanks, cursor_.offset) == std::string_view::npos) {
    warn(core::Code::UnopenedPercent, 0,
         "a closing '%' but the program did not open with one; taken as its end (LinuxCNC "
         "reports an error)");
    ended_ = true;
    return Flow::End;
  }
  error(core::Code::MisplacedPercent, 0,
        fmt::format("a '%' line in the middle of the {}: '%' opens a program on its first line "
                    "and the next '%' closes it; this program did not open with '%' (LinuxCNC "
                    "stops here too): remove the line, or put a '%' first",
                    main_file ? "program" : "subroutine"));
  return Flow::Error;
}

}  // namespace usina::gcode
