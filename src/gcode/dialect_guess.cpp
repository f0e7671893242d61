#include "gcode/dialect_guess.hpp"

#include <array>
#include <optional>
#include <regex>
#include <vector>

#include <fmt/format.h>

#include "gcode/dialect_clues.hpp"

namespace usina::gcode {
namespace {

// A mark only one dialect's programs carry decides alone; the first found,
// in this order, wins.
std::optional<DialectGuess> decisive_mark(const std::vector<HeadLine>& head) {
  // LinuxCNC's O-word statements and named parameters.
  static const std::regex rs_o(R"(^(N\d+\s*)?O\s*(<[^>]*>|\d+\s*(SUB|IF|WHILE|CALL|DO|REPEAT)\b))");
  // Fanuc's program number or name after the tape start ('%'), or ':1234'.
  static const std::regex fanuc_o(R"(^(O\s*\d{1,8}\b|O[A-Z][A-Z0-9]*\b|:\s*\d{1,8}\b))");
  static const std::regex macro_b(
      R"((^|\s|^N\d+\s*)(WHILE\s*\[|IF\s*\[.*\]\s*(GOTO|THEN)|G65\s*P))");
  static const std::regex romi_end(R"(#\s*($|N\d))");
  for (const HeadLine& l : head)
    if (!l.code.empty() && l.code[0] == '$')
      return DialectGuess{"grbl", fmt::format("a '{}' line", l.code.substr(0, 3))};
  for (const HeadLine& l : head) {
    if (std::regex_search(l.code, rs_o))
      return DialectGuess{"rs274ngc", fmt::format("the O-word '{}'", l.code)};
    if (l.code.find("#<") != std::string::npos)
      return DialectGuess{"rs274ngc", fmt::format("the named parameter in '{}'", l.code)};
  }
  bool after_percent = false;
  for (const HeadLine& l : head) {
    if (after_percent && std::regex_search(l.code, fanuc_o))
      return DialectGuess{"fanuc", fmt::format("'%' and the program number '{}'", l.code)};
    if (std::regex_search(l.code, macro_b))
      return DialectGuess{"fanuc", fmt::format("the Macro B statement '{}'", l.code)};
    if (!l.code.empty()) after_percent = l.code == "%";
  }
  for (const HeadLine& l : head)
    if (std::regex_search(l.code, romi_end)) return DialectGuess{"romi", "'#' ends blocks"};
  return std::nullopt;
}

// Sums the clues per dialect; the highest sum wins, a tie or no clue leaves
// the default (rs274ngc). The reason lists every clue with its weight.
DialectGuess weigh(const std::vector<Clue>& clues) {
  static constexpr std::array<std::string_view, 3> kDialects{"rs274ngc", "grbl", "fanuc"};
  std::array<int, kDialects.size()> sum{};
  for (const Clue& c : clues) {
    for (std::size_t d = 0; d < kDialects.size(); ++d)
      if (c.dialect == kDialects[d]) sum[d] += c.weight;
  }
  std::size_t best = 0;
  bool tie = false;
  for (std::size_t d = 1; d < kDialects.size(); ++d) {
    if (sum[d] > sum[best]) {
      best = d;
      tie = false;
    } else if (sum[d] == sum[best]) {
      tie = true;
    }
  }
  if (clues.empty()) return {"rs274ngc", "no dialect's mark or clue (the default)"};
  std::string sums;
  for (std::size_t d = 0; d < kDialects.size(); ++d)
    if (sum[d] > 0) sums += fmt::format("{}{} {}", sums.empty() ? "" : ", ", kDialects[d], sum[d]);
  std::string list;
  for (const Clue& c : clues)
    list += fmt::format("{}{} ({} +{})", list.empty() ? "" : "; ", c.what, c.dialect, c.weight);
  if (tie && sum[best] > 0) best = 0;  // a tie leaves the default
  return {kDialects[best], fmt::format("{}{}: {}", tie ? "a tie, the default; " : "", sums, list)};
}

}  // namespace

DialectGuess guess_dialect(std::string_view text, std::string_view file_name) {
  const std::vector<HeadLine> head = read_head(text);
  if (auto mark = decisive_mark(head)) return *mark;
  return weigh(weigh_clues(head, text, file_name));
}

}  // namespace usina::gcode
