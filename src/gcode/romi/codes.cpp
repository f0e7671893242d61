#include "gcode/romi/codes.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace usina::gcode::romi {

std::string code_name(char letter, int tenths) {
  return tenths % 10 == 0 ? fmt::format("{}{:02}", letter, tenths / 10)
                          : fmt::format("{}{}.{}", letter, tenths / 10, tenths % 10);
}

CodeTable::CodeTable(const Dialect& dialect, Handler (*resolve)(std::string_view), int after_move)
    : dialect_name_(dialect.name), index_(2 * (std::size_t{kMaxTenths} + 1), 0) {
  const std::vector<CodeEntry>& codes = dialect.codes;
  // The groups' numbers in order: a group's rank is its place among them.
  std::vector<int> groups;
  groups.reserve(codes.size());
  for (const CodeEntry& e : codes)
    groups.push_back(e.group);
  std::sort(groups.begin(), groups.end());
  groups.erase(std::unique(groups.begin(), groups.end()), groups.end());
  if (groups.size() > static_cast<std::size_t>(kMaxGroups) || codes.size() >= 255) {
    throw std::logic_error("romi code table: too many groups or codes");
  }
  ranks_ = static_cast<int>(groups.size());
  first_after_move_ =
      static_cast<int>(std::lower_bound(groups.begin(), groups.end(), after_move) - groups.begin());
  codes_.reserve(codes.size());
  for (const CodeEntry& e : codes) {
    const Handler h = resolve(e.handler);
    if (h == nullptr || e.code < 0 || e.code > kMaxTenths || (e.letter != 'G' && e.letter != 'M')) {
      throw std::logic_error(fmt::format("romi code table: {} (handler '{}') cannot be resolved",
                                         code_name(e.letter, e.code), e.handler));
    }
    const auto rank = std::lower_bound(groups.begin(), groups.end(), e.group) - groups.begin();
    codes_.push_back({&e, static_cast<int>(rank), h});
    // The first entry of a code is the one in force, as Dialect::find_code.
    std::uint8_t& i = index_[slot(e.letter, e.code)];
    if (i == 0) i = static_cast<std::uint8_t>(codes_.size());
  }
}

}  // namespace usina::gcode::romi
