// Grbl's error numbers and texts (gnea/grbl doc/csv/error_codes_en_US.csv,
// docs/grbl.md §5), and which of them an interpreter diagnostic stands for.
#include <array>

#include <fmt/format.h>

#include "gcode/grbl/dialect.hpp"

namespace usina::gcode::grbl {
namespace {

// Index = Grbl's number; Grbl's short message.
constexpr std::array<std::string_view, 39> kTexts = {
    "",
    "Expected command letter",
    "Bad number format",
    "Invalid statement",
    "Value < 0",
    "Setting disabled",
    "Value < 3 usec",
    "EEPROM read fail",
    "Not idle",
    "G-code lock",
    "Homing not enabled",
    "Line overflow",
    "Step rate > 30kHz",
    "Check Door",
    "Line length exceeded",
    "Travel exceeded",
    "Invalid jog command",
    "Setting disabled",
    "",
    "",
    "Unsupported command",
    "Modal group violation",
    "Undefined feed rate",
    "Invalid gcode ID:23",
    "Invalid gcode ID:24",
    "Invalid gcode ID:25",
    "Invalid gcode ID:26",
    "Invalid gcode ID:27",
    "Invalid gcode ID:28",
    "Invalid gcode ID:29",
    "Invalid gcode ID:30",
    "Invalid gcode ID:31",
    "Invalid gcode ID:32",
    "Invalid gcode ID:33",
    "Invalid gcode ID:34",
    "Invalid gcode ID:35",
    "Invalid gcode ID:36",
    "Invalid gcode ID:37",
    "Invalid gcode ID:38",
};

}  // namespace

std::string_view error_text(int number) {
  if (number < 0 || number >= static_cast<int>(kTexts.size())) return {};
  return kTexts[static_cast<std::size_t>(number)];
}

int error_for(core::Code code) {
  // Only what the interpreter finds from the position (the grbl checks
  // before it catch the rest); the number is what Grbl's gc_execute_line
  // fails with for the same block.
  switch (code) {
  case core::Code::NoFeedRate: return 22;
  case core::Code::ArcRadiusMismatch: return 33;
  case core::Code::ArcZeroLength: return 33;
  case core::Code::ProbeBadMove: return 33;
  case core::Code::ArcRadiusTooSmall: return 34;
  case core::Code::ArcMissingCenter: return 35;
  case core::Code::ModalGroupConflict: return 21;
  case core::Code::RepeatedWord: return 25;
  case core::Code::UnknownGCode: return 20;
  case core::Code::UnknownMCode: return 20;
  case core::Code::UnknownWord: return 20;
  case core::Code::AxisWordsConflict: return 24;
  case core::Code::UnusedWord: return 36;
  case core::Code::MissingWord: return 28;
  default: return 0;
  }
}

std::string error_message(int number, std::string_view detail) {
  return fmt::format("grbl error:{} ({}): {}", number, error_text(number), detail);
}

}  // namespace usina::gcode::grbl
