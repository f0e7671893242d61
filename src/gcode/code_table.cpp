#include "gcode/code_table.hpp"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

namespace usina::gcode {

std::string code_name(char letter, int tenths) {
  return tenths % 10 == 0 ? fmt::format("{}{:02}", letter, tenths / 10)
                          : fmt::format("{}{}.{}", letter, tenths / 10, tenths % 10);
}

void unresolved_handler(std::string_view dialect, const CodeEntry& entry) {
  throw std::logic_error(fmt::format("{} code table: {} (handler '{}') cannot be resolved", dialect,
                                     code_name(entry.letter, entry.code), entry.handler));
}

CodeIndex::CodeIndex(std::string_view dialect, const std::vector<CodeEntry>& codes, int max_tenths)
    : dialect_(dialect),
      codes_(&codes),
      max_tenths_(max_tenths),
      index_(2 * (static_cast<std::size_t>(max_tenths) + 1), 0) {
  for (const CodeEntry& e : codes)
    groups_.push_back(e.group);
  std::sort(groups_.begin(), groups_.end());
  groups_.erase(std::unique(groups_.begin(), groups_.end()), groups_.end());
  if (groups_.size() > static_cast<std::size_t>(kMaxGroups) ||
      codes.size() >= std::numeric_limits<std::uint16_t>::max()) {
    throw std::logic_error(fmt::format("{} code table: too many groups or codes", dialect));
  }
  for (std::size_t i = 0; i < codes.size(); ++i) {
    const CodeEntry& e = codes[i];
    if (e.code < 0 || e.code > max_tenths || (e.letter != 'G' && e.letter != 'M')) {
      throw std::logic_error(
          fmt::format("{} code table: {}{} is not a code of the table", dialect, e.letter, e.code));
    }
    std::uint16_t& at = index_[slot(e.letter, e.code)];
    if (at == 0) at = static_cast<std::uint16_t>(i + 1);
  }
}

bool CodeIndex::has_integer(char letter, int integer) const {
  if (integer < 0 || integer > max_tenths_ / 10) return false;
  for (int t = integer * 10; t <= std::min(integer * 10 + 9, max_tenths_); ++t) {
    if (position(letter, t) >= 0) return true;
  }
  return false;
}

int CodeIndex::rank(int group) const {
  return static_cast<int>(std::lower_bound(groups_.begin(), groups_.end(), group) -
                          groups_.begin());
}

}  // namespace usina::gcode
