#include "gcode/interp/codes.hpp"

#include <cstdio>
#include <stdexcept>

#include <fmt/format.h>

namespace usina::gcode {

CodeRun code_run_named(std::string_view handler) {
  if (handler == "group_step") return CodeRun::GroupStep;
  if (handler == "user_m") return CodeRun::UserM;
  if (handler == "unsupported") return CodeRun::Unsupported;
  return CodeRun::None;
}

InterpCodes interp_code_table(std::string_view dialect, const std::vector<CodeEntry>& codes) {
  for (const CodeEntry& e : codes) {
    const int groups = e.letter == 'G' ? kGGroups : kMGroups;
    if (e.group < 0 || e.group >= groups) {
      throw std::logic_error(
          fmt::format("{} code table: {} is in group {}, not one of the "
                      "interpreter's",
                      dialect, code_name(e.letter, e.code), e.group));
    }
  }
  return InterpCodes(dialect, codes, kMaxCodeTenths, &code_run_named);
}

std::array<char, 32> g_name(GCode g) {
  std::array<char, 32> out{};
  if (g % 10 == 0) {
    std::snprintf(out.data(), out.size(), "G%d", g / 10);
  } else {
    std::snprintf(out.data(), out.size(), "G%d.%d", g / 10, g % 10);
  }
  return out;
}

}  // namespace usina::gcode
