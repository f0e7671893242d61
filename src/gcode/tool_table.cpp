#include "gcode/tool_table.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

namespace usina::gcode {
namespace {

using core::Severity;

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
constexpr std::string_view kWordLetters = "TPXYZABCUVWDIJQ";

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

char upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back()))
    s.remove_suffix(1);
  return s;
}

// Quotes user text in a message, cut short so a garbage line stays readable.
std::string quoted(std::string_view s) {
  constexpr std::size_t kMax = 24;
  if (s.size() <= kMax) return fmt::format("'{}'", s);
  return fmt::format("'{}...'", s.substr(0, kMax));
}

enum class NumberError { None, Malformed, OutOfRange };

// The whole of `text` as a number. One leading '+' is allowed: LinuxCNC
// writes offsets as "Z+0.100000" (tool_parse.cc, saveToolTable).
template <class T>
NumberError parse_number(std::string_view text, T& out) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '+' || text.front() == '-'))
      return NumberError::Malformed;
  }
  if (text.empty()) return NumberError::Malformed;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, out);
  if (ec == std::errc::result_out_of_range) return NumberError::OutOfRange;
  if (ec != std::errc{} || ptr != end) return NumberError::Malformed;
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(out)) return NumberError::Malformed;  // from_chars takes "inf", "nan"
  }
  return NumberError::None;
}

// One line being read: where it is, and where its diagnostics go.
struct Line {
  std::string_view text;  // without the end of line
  std::uint32_t file_id = 0;
  std::uint32_t number = 0;
  std::uint64_t offset = 0;
  core::DiagnosticSink* diags = nullptr;

  std::uint32_t col_of(std::string_view part) const {
    return static_cast<std::uint32_t>(part.data() - text.data()) + 1;
  }

  // Errors are E_BAD_TOOL_TABLE; each warning has a code of its own.
  void report(Severity severity, std::string_view at, std::string message,
              core::Code code = core::Code::BadToolTable) const {
    core::SourceLoc loc{file_id, number, col_of(at), static_cast<std::uint32_t>(at.size()), offset};
    diags->report({code, severity, loc, std::move(message)});
  }
};

// Calls `fn(text, line_offset)` for each line of `text`, ends of line removed.
template <class Fn>
void for_each_line(std::string_view text, Fn&& fn) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    while (!line.empty() && line.back() == '\r')
      line.remove_suffix(1);
    fn(line, static_cast<std::uint64_t>(start));
    start = end + 1;
  }
}

// An integer word: its name in messages and the values it may take.
struct IntWord {
  std::string_view what;
  int min = 0;
  int max = std::numeric_limits<int>::max();
};

constexpr IntWord kToolNumber{"tool number"};
constexpr IntWord kPocketNumber{"pocket number"};
constexpr IntWord kOrientation{"orientation", 0, kMaxToolOrientation};

bool read_int_word(const Line& line, const IntWord& word, char letter, std::string_view value,
                   int& out) {
  const std::string_view what = word.what;
  switch (parse_number(value, out)) {
  case NumberError::None: break;
  case NumberError::OutOfRange:
    line.report(Severity::Error, value, fmt::format("{} {} is too large", what, quoted(value)));
    return false;
  case NumberError::Malformed:
    line.report(
        Severity::Error, value,
        fmt::format("{} {} is not an integer; write e.g. {}5", what, quoted(value), letter));
    return false;
  }
  if (out < word.min || out > word.max) {
    const std::string range = word.max == std::numeric_limits<int>::max()
                                  ? fmt::format("{} or more", word.min)
                                  : fmt::format("{}..{}", word.min, word.max);
    line.report(Severity::Error, value,
                fmt::format("{} {} is out of range; it must be {}", what, out, range));
    return false;
  }
  return true;
}

bool read_real_word(const Line& line, char letter, std::string_view value, double& out) {
  switch (parse_number(value, out)) {
  case NumberError::None: return true;
  case NumberError::OutOfRange:
    line.report(Severity::Error, value,
                fmt::format("{} value {} is out of the range of a double", letter, quoted(value)));
    return false;
  case NumberError::Malformed: break;
  }
  line.report(
      Severity::Error, value,
      fmt::format("{} value {} is not a number; write e.g. {}0.25", letter, quoted(value), letter));
  return false;
}

// A real word's name in messages and the values it may take, in mm for a
// length (`length`), degrees otherwise: wide enough for any tool, narrow
// enough that no offset or diameter is absurd. LinuxCNC checks none of
// this, but D-6 made holes of diameter -6, and Z1e300 an infinite move.
struct RealWord {
  std::string_view what;
  double min;
  double max;
  bool length;
};

constexpr double kMaxOffset = 10000.0;  // mm: a 10 m tool offset
constexpr RealWord kOffsetWord{"offset", -kMaxOffset, kMaxOffset, true};
constexpr RealWord kAngleWord{"angle", -360.0, 360.0, false};
constexpr RealWord kDiameterWord{"diameter", 0.0, 1000.0, true};

const RealWord& real_word(char letter) {
  switch (letter) {
  case 'D': return kDiameterWord;
  case 'A':
  case 'B':
  case 'C':
  case 'I':
  case 'J': return kAngleWord;
  default: return kOffsetWord;
  }
}

// The value `v` (as written) of a real word within its range.
bool check_real_word(const Line& line, char letter, std::string_view value, double v,
                     double mm_per_unit) {
  const RealWord& w = real_word(letter);
  const double scale = w.length ? mm_per_unit : 1.0;
  if (v * scale >= w.min && v * scale <= w.max) return true;
  const std::string unit = !w.length ? "degrees" : (mm_per_unit == 1.0 ? "mm" : "machine units");
  line.report(Severity::Error, value,
              fmt::format("{} {}{} is out of range; it must be from {:g} to {:g} {}{}", w.what,
                          letter, value, w.min / scale, w.max / scale, unit,
                          letter == 'D' && v < 0 ? " (a diameter is not negative)" : ""));
  return false;
}

// Stores one word's value in `tool`, lengths scaled to mm.
bool apply_word(const Line& line, char letter, std::string_view value, double mm_per_unit,
                ToolEntry& tool) {
  switch (letter) {
  case 'T': return read_int_word(line, kToolNumber, letter, value, tool.number);
  case 'P': return read_int_word(line, kPocketNumber, letter, value, tool.pocket);
  case 'Q': return read_int_word(line, kOrientation, letter, value, tool.orientation);
  default: break;
  }
  double v = 0;
  if (!read_real_word(line, letter, value, v)) return false;
  if (!check_real_word(line, letter, value, v, mm_per_unit)) return false;
  switch (letter) {
  case 'X': tool.offset.x = v * mm_per_unit; break;
  case 'Y': tool.offset.y = v * mm_per_unit; break;
  case 'Z': tool.offset.z = v * mm_per_unit; break;
  case 'A': tool.abc_offset[0] = v; break;
  case 'B': tool.abc_offset[1] = v; break;
  case 'C': tool.abc_offset[2] = v; break;
  case 'U': tool.uvw_offset[0] = v * mm_per_unit; break;
  case 'V': tool.uvw_offset[1] = v * mm_per_unit; break;
  case 'W': tool.uvw_offset[2] = v * mm_per_unit; break;
  case 'D': tool.diameter = v * mm_per_unit; break;
  case 'I': tool.front_angle = v; break;
  case 'J': tool.back_angle = v; break;
  default: break;
  }
  return true;
}

// Checks one blank-separated token as a word and applies it; false when bad.
bool read_token(const Line& line, std::string_view token, std::uint32_t& seen, double mm_per_unit,
                ToolEntry& tool) {
  const char letter = upper(token.front());
  if (letter < 'A' || letter > 'Z') {
    line.report(Severity::Error, token,
                fmt::format("{} has no word letter; a tool line is words such as T1 P1 Z0.5",
                            quoted(token)));
    return false;
  }
  if (kWordLetters.find(letter) == std::string_view::npos) {
    line.report(Severity::Error, token.substr(0, 1),
                fmt::format("unknown word {} in a tool table; the words are T P X Y Z A B C U V W "
                            "D I J Q, and ';' starts a comment",
                            token.front()));
    return false;
  }
  const std::uint32_t bit = 1u << (letter - 'A');
  if ((seen & bit) != 0) {
    line.report(Severity::Error, token,
                fmt::format("{} given twice on one line; keep one", letter));
    return false;
  }
  seen |= bit;
  const std::string_view value = token.substr(1);
  if (value.empty()) {
    line.report(
        Severity::Error, token,
        fmt::format("{} has no number; write it with the number, no blank: {}5", letter, letter));
    return false;
  }
  return apply_word(line, letter, value, mm_per_unit, tool);
}

// Reads the words before ';'. nullopt when the line is bad (every problem
// reported, not only the first).
std::optional<ToolEntry> read_words(const Line& line, std::string_view words, double mm_per_unit) {
  const std::string_view all = trim(words);
  if (is_digit(all.front())) {
    line.report(Severity::Error, all.substr(0, 1),
                "line starts with a number: the column format of LinuxCNC before 2.4 is not "
                "read; write words, e.g. T1 P1 Z0.5 D0.25 ;comment");
    return std::nullopt;
  }
  ToolEntry tool;
  std::uint32_t seen = 0;
  bool good = true;
  std::size_t i = 0;
  while (i < words.size()) {
    while (i < words.size() && is_blank(words[i]))
      ++i;
    const std::size_t start = i;
    while (i < words.size() && !is_blank(words[i]))
      ++i;
    if (i == start) break;
    good = read_token(line, words.substr(start, i - start), seen, mm_per_unit, tool) && good;
  }
  if (!good) return std::nullopt;
  if ((seen & (1u << ('T' - 'A'))) == 0) {
    line.report(Severity::Error, all, "tool line has no T word (tool number); add one, e.g. T1");
    return std::nullopt;
  }
  if ((seen & (1u << ('P' - 'A'))) == 0) {
    line.report(Severity::Warning, all,
                fmt::format("tool {} has no P word (pocket), which LinuxCNC requires; pocket 0 "
                            "assumed",
                            tool.number),
                core::Code::ToolWithoutPocket);
  }
  return tool;
}

}  // namespace

const ToolEntry* ToolTable::find(int number) const {
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), number,
                                   [](const ToolEntry& e, int n) { return e.number < n; });
  return (it != entries_.end() && it->number == number) ? &*it : nullptr;
}

void ToolTable::set(ToolEntry entry) {
  define(std::move(entry));
  lists_tools_ = true;
}

void ToolTable::define(ToolEntry entry) {
  const auto it = std::lower_bound(entries_.begin(), entries_.end(), entry.number,
                                   [](const ToolEntry& e, int n) { return e.number < n; });
  if (it != entries_.end() && it->number == entry.number) {
    *it = std::move(entry);
  } else {
    entries_.insert(it, std::move(entry));
  }
}

std::optional<ToolTable> read_tool_table(const core::SourceFile& file, std::uint32_t file_id,
                                         double mm_per_unit, core::DiagnosticSink& diags) {
  if (!std::isfinite(mm_per_unit) || mm_per_unit <= 0) {
    throw std::invalid_argument(
        fmt::format("read_tool_table: mm_per_unit {} is not positive", mm_per_unit));
  }
  // Tools by number, each with the line it was last read from; the table is
  // filled in ascending order at the end, so each tool goes at its end
  // (inserting each line's tool in place was quadratic in a table listed in
  // descending order).
  std::map<int, std::pair<ToolEntry, std::uint32_t>> read;
  std::size_t bad_lines = 0;
  std::uint32_t line_number = 0;
  for_each_line(file.text(), [&](std::string_view text, std::uint64_t offset) {
    const Line line{text, file_id, ++line_number, offset, &diags};
    if (line_number == 1 && text.starts_with(kUtf8Bom)) text.remove_prefix(kUtf8Bom.size());
    const std::size_t semicolon = text.find(';');
    const std::string_view words = text.substr(0, semicolon);
    if (trim(words).empty()) return;  // blank or comment-only line
    std::optional<ToolEntry> tool = read_words(line, words, mm_per_unit);
    if (!tool) {
      ++bad_lines;
      return;
    }
    if (semicolon != std::string_view::npos) tool->comment = trim(text.substr(semicolon + 1));
    tool->line = line_number;
    const auto at = read.find(tool->number);
    if (at != read.end()) {
      line.report(Severity::Warning, trim(words),
                  fmt::format("tool {} is also on line {}; this line replaces it", tool->number,
                              at->second.second),
                  core::Code::ToolRedefined);
      at->second = {std::move(*tool), line_number};
    } else {
      const int number = tool->number;
      read.emplace(number, std::pair{std::move(*tool), line_number});
    }
  });
  ToolTable table(true);
  for (auto& entry : read)
    table.set(std::move(entry.second.first));
  if (table.empty() && bad_lines > 0) return std::nullopt;
  return table;
}

}  // namespace usina::gcode
