// G10 L50 ... G11, programmable parameter input (docs/fanuc.md §7): between
// them every block is `N<parameter> [P<axis>] R<value>`. usina applies the
// parameters it models (5114 and 5115, the G73 back-off and G83 clearance;
// 3401 bit 0 DPI, the decimal-point rule; 1300 bit 0 OUT, the side of the
// G22 area) and says of any other that it is not modelled, rather than
// guess. 5101 bits 4-5 RD1 RD2 set the G76/G87 shift direction.
#include <cmath>

#include <fmt/format.h>

#include "gcode/fanuc/engine.hpp"

namespace usina::gcode::fanuc {

bool Engine::parameter_block(const TapeBlock& b) {
  if (b.text.empty() && b.sequence < 0) return true;
  Words w;
  if (!b.text.empty() && b.text[0] == '#') {
    return error(core::Code::NotAllowedInMode, b, 0,
                 "parameter input mode (G10 L50) takes N P R blocks and G11 only");
  }
  if (!read_words(b, w)) return false;
  if (w.has_g(110)) {
    w.take_g(110);
    for (const NcWord& word : w.list) {
      if (!word.taken) {
        return error(core::Code::NotAllowedInMode, b, word.pos,
                     "G11 (end of parameter input) stands alone in its block");
      }
    }
    parameter_mode_ = false;
    return true;
  }
  for (const NcWord& word : w.list) {
    if (word.letter != 'P' && word.letter != 'R') {
      return error(core::Code::NotAllowedInMode, b, word.pos,
                   fmt::format("{} in parameter input mode (G10 L50): a block is N<parameter> "
                               "[P<axis>] R<value>; G11 ends the mode",
                               word.letter));
    }
  }
  if (b.sequence < 0) {
    return error(core::Code::MissingWord, b, 0,
                 "a parameter input block needs N (the parameter number)");
  }
  if (w.find('R') == nullptr)
    return error(core::Code::MissingWord, b, 0, "a parameter input block needs R (the value)");
  return set_fanuc_parameter(b, b.sequence, w);
}

// A length parameter: R with a point in mm (inch on an inch machine), R
// without one in the least input increment (0.001 mm, 0.0001 in).
std::optional<double> Engine::parameter_length(const TapeBlock& b, const NcWord& r) {
  const bool inch = options_.machine_units == core::LengthUnit::Inch;
  const double v = r.integer_literal ? r.raw * (inch ? 0.0001 : 0.001) : r.raw;
  if (v < 0) {
    error(core::Code::BadWordValue, b, r.pos, "this parameter takes a distance of 0 or more");
    return std::nullopt;
  }
  return v * core::mm_per(options_.machine_units);
}

// A bit parameter: R is the byte, bit 0 its lowest (R1 sets bit 0 alone);
// bits outside `modeled` are warned.
std::optional<long> Engine::parameter_bits(const TapeBlock& b, long number, const NcWord& r,
                                           long modeled) {
  if (!r.integer_literal || r.raw < 0 || r.raw > 255) {
    error(core::Code::BadWordValue, b, r.pos,
          fmt::format("parameter {} is a bit parameter: R takes 0..255 without a decimal point "
                      "(bit 0 is 1)",
                      number));
    return std::nullopt;
  }
  const long bits = std::lround(r.raw);
  if ((bits & ~modeled) != 0) {
    warn(core::Code::ParameterNotModeled, b, r.pos,
         fmt::format("parameter {}: usina models {} only; the other bits set ({}) are ignored",
                     number, modeled == 1 ? "bit 0" : "bits 4-5 (RD1 RD2)", bits & ~modeled));
  }
  return bits;
}

bool Engine::set_fanuc_parameter(const TapeBlock& b, long number, Words& w) {
  const NcWord& r = *w.find('R');
  const NcWord* axis = w.find('P');
  const bool modeled =
      number == 5114 || number == 5115 || number == 3401 || number == 1300 || number == 5101;
  if (!modeled) {
    // At the block's N, the parameter number.
    diags_.report({core::Code::ParameterNotModeled, core::Severity::Warning,
                   core::SourceLoc{b.loc.file, b.loc.line, b.col, 1, b.loc.line_offset},
                   fmt::format("parameter {} is not modelled by usina: ignored (it may change "
                               "what the control does)",
                               number)});
    return true;
  }
  if (axis != nullptr) {
    return error(core::Code::BadWordValue, b, axis->pos,
                 fmt::format("parameter {} is not an axis parameter: no P", number));
  }
  if (number == 5114 || number == 5115) {
    const auto mm = parameter_length(b, r);
    if (!mm) return false;
    // 5114: G73's back-off after each peck; 5115: G83's clearance above the
    // last peck.
    if (number == 5114) pecks_.g73_retract_mm = *mm;
    if (number == 5115) pecks_.g83_clearance_mm = *mm;
    return true;
  }
  const auto bits = parameter_bits(b, number, r, number == 5101 ? 0x30 : 1);
  if (!bits) return false;
  if (number == 5101) g76_.shift = static_cast<int>((*bits >> 4) & 3);
  if (number == 3401) dpi_fanuc_ = (*bits & 1) == 0;  // DPI = 1: pocket calculator
  if (number == 1300) stroke_.outside_forbidden = (*bits & 1) != 0;
  return true;
}

// RD2 RD1 = 00 +X, 01 -X, 10 +Y, 11 -Y (in G17; docs/fanuc.md §7).
int boring_shift_bits(std::string_view option) {
  if (option == "-x") return 1;
  if (option == "+y") return 2;
  if (option == "-y") return 3;
  return 0;
}

}  // namespace usina::gcode::fanuc
