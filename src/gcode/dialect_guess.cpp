#include "gcode/dialect_guess.hpp"

#include <cctype>
#include <regex>
#include <vector>

#include <fmt/format.h>

namespace usina::gcode {
namespace {

constexpr std::size_t kLinesLooked = 200;

// The line in upper case without ( ) comments, trimmed.
std::string clean(std::string_view line) {
  std::string out;
  int depth = 0;
  for (char c : line) {
    if (c == '(') ++depth;
    if (depth == 0 && c != '\r')
      out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (c == ')' && depth > 0) --depth;
  }
  const std::size_t a = out.find_first_not_of(" \t");
  if (a == std::string::npos) return {};
  return out.substr(a, out.find_last_not_of(" \t") - a + 1);
}

}  // namespace

DialectGuess guess_dialect(std::string_view text) {
  std::vector<std::string> lines;
  for (std::size_t start = 0; start <= text.size() && lines.size() < kLinesLooked;) {
    const std::size_t nl = text.find('\n', start);
    const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
    lines.push_back(clean(text.substr(start, end - start)));
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
  static const std::regex rs_o(R"(^(N\d+\s*)?O\s*(<[^>]*>|\d+\s*(SUB|IF|WHILE|CALL|DO|REPEAT)\b))");
  static const std::regex fanuc_o(R"(^(O|:)\d{1,8}\b)");
  static const std::regex macro_b(R"((^|\s|^N\d+\s*)(WHILE\s*\[|IF\s*\[.*\]\s*GOTO|G65\s*P))");
  static const std::regex romi_end(R"(#\s*($|N\d))");
  for (const std::string& l : lines)
    if (!l.empty() && l[0] == '$') return {"grbl", fmt::format("a '{}' line", l.substr(0, 3))};
  for (const std::string& l : lines)
    if (std::regex_search(l, rs_o)) return {"rs274ngc", fmt::format("the O-word '{}'", l)};
  bool percent = false;
  for (const std::string& l : lines) {
    if (l == "%") percent = true;
    if (percent && std::regex_search(l, fanuc_o))
      return {"fanuc", fmt::format("'%' and the program number '{}'", l)};
    if (std::regex_search(l, macro_b))
      return {"fanuc", fmt::format("the Macro B statement '{}'", l)};
  }
  for (const std::string& l : lines)
    if (std::regex_search(l, romi_end)) return {"romi", "'#' ends blocks"};
  return {"rs274ngc", "no other dialect's mark (the default)"};
}

}  // namespace usina::gcode
