#include "gcode/var_file.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <iterator>
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

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// Quotes user text in a message, cut short so a garbage line stays readable.
std::string quoted(std::string_view s) {
  constexpr std::size_t kMax = 24;
  if (s.size() <= kMax) return fmt::format("'{}'", s);
  return fmt::format("'{}...'", s.substr(0, kMax));
}

// The whole of `text` as a finite number; one leading '+' allowed, as
// LinuxCNC's sscanf("%d %lf") allows it.
template <class T>
bool parse_number(std::string_view text, T& out) {
  if (!text.empty() && text.front() == '+') {
    text.remove_prefix(1);
    if (!text.empty() && (text.front() == '+' || text.front() == '-')) return false;
  }
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, out);
  if (ec != std::errc{} || ptr != end) return false;
  if constexpr (std::is_floating_point_v<T>) return std::isfinite(out);
  return true;
}

// The blank-separated fields of a line from byte `i` on, at most three (a
// third only tells that there is text after the value).
struct Fields {
  std::array<std::string_view, 3> field;
  std::size_t count = 0;
};

Fields split(std::string_view line, std::size_t i) {
  Fields f;
  while (f.count < 3) {
    while (i < line.size() && is_blank(line[i]))
      ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i]))
      ++i;
    if (i == start) break;
    f.field[f.count++] = line.substr(start, i - start);
  }
  return f;
}

struct Reader {
  std::string_view text;  // the current line, without its end of line
  std::uint32_t file_id = 0;
  std::uint32_t line = 0;
  std::uint64_t offset = 0;
  core::DiagnosticSink* diags = nullptr;
  std::vector<VarFileEntry> entries;
  std::vector<std::uint32_t> lines;  // the line of each entry
  std::size_t bad_lines = 0;

  // Errors are E_BAD_VAR_FILE; each warning has a code of its own.
  void report(Severity severity, std::string_view at, std::string message,
              core::Code code = core::Code::BadVarFile) const {
    const auto col = static_cast<std::uint32_t>(at.data() - text.data()) + 1;
    core::SourceLoc loc{file_id, line, col, static_cast<std::uint32_t>(at.size()), offset};
    diags->report({code, severity, loc, std::move(message)});
  }

  bool fail(std::string_view at, std::string message) {
    report(Severity::Error, at, std::move(message));
    ++bad_lines;
    return false;
  }

  bool read_line();
  bool check_order(std::string_view at, int number);
};

// LinuxCNC rs274ngc_pre.cc, restore_parameters(): numbers must ascend, else
// "Parameter file out of order" and the file is refused.
bool Reader::check_order(std::string_view at, int number) {
  if (entries.empty() || number > entries.back().number) return true;
  const auto it = std::lower_bound(entries.begin(), entries.end(), number,
                                   [](const VarFileEntry& e, int n) { return e.number < n; });
  if (it->number == number) {
    return fail(at, fmt::format("parameter {} is also on line {}; keep one of them", number,
                                lines[static_cast<std::size_t>(it - entries.begin())]));
  }
  return fail(at, fmt::format("parameter {} comes after parameter {} (line {}); LinuxCNC needs "
                              "ascending numbers: move this line up",
                              number, entries.back().number, lines.back()));
}

// Reads `text` into `entries`; false when the line was skipped.
bool Reader::read_line() {
  const std::size_t from = (line == 1 && text.starts_with(kUtf8Bom)) ? kUtf8Bom.size() : 0;
  const Fields f = split(text, from);
  if (f.count == 0) return false;
  const std::string_view num = f.field[0];
  if (!is_digit(num.front()) && num.front() != '+' && num.front() != '-') {
    report(Severity::Warning, num,
           "line skipped: it is not 'NUMBER VALUE' (e.g. '5221 0.000000'), and LinuxCNC skips it",
           core::Code::VarFileLineSkipped);
    ++bad_lines;
    return false;
  }
  int number = 0;
  if (!parse_number(num, number)) {
    return fail(num, fmt::format("parameter number {} is not an integer", quoted(num)));
  }
  if (number < kMinVarFileParameter || number > kMaxVarFileParameter) {
    return fail(num, fmt::format("parameter number {} is out of range; it must be {}..{}", number,
                                 kMinVarFileParameter, kMaxVarFileParameter));
  }
  if (f.count < 2) {
    return fail(num,
                fmt::format("parameter {} has no value; write e.g. '{} 0.000000'", number, number));
  }
  double value = 0;
  if (!parse_number(f.field[1], value)) {
    return fail(f.field[1], fmt::format("value {} of parameter {} is not a finite number",
                                        quoted(f.field[1]), number));
  }
  if (!check_order(num, number)) return false;
  if (f.count > 2) {
    const std::string_view rest =
        text.substr(static_cast<std::size_t>(f.field[2].data() - text.data()));
    report(Severity::Warning, rest,
           fmt::format("text after the value of parameter {} is ignored", number),
           core::Code::VarFileExtraText);
  }
  entries.push_back({number, value});
  lines.push_back(line);
  return true;
}

}  // namespace

std::optional<std::vector<VarFileEntry>> read_var_file(const core::SourceFile& file,
                                                       std::uint32_t file_id,
                                                       core::DiagnosticSink& diags) {
  Reader r;
  r.file_id = file_id;
  r.diags = &diags;
  const std::string_view all = file.text();
  std::size_t start = 0;
  while (start < all.size()) {
    std::size_t end = all.find('\n', start);
    if (end == std::string_view::npos) end = all.size();
    r.text = all.substr(start, end - start);
    while (!r.text.empty() && r.text.back() == '\r')
      r.text.remove_suffix(1);
    ++r.line;
    r.offset = start;
    r.read_line();
    start = end + 1;
  }
  if (r.entries.empty() && r.bad_lines > 0) return std::nullopt;
  return std::move(r.entries);
}

std::string write_var_file(std::span<const VarFileEntry> entries) {
  std::vector<VarFileEntry> sorted(entries.begin(), entries.end());
  for (const VarFileEntry& e : sorted) {
    if (e.number < kMinVarFileParameter || e.number > kMaxVarFileParameter) {
      throw std::invalid_argument(
          fmt::format("write_var_file: parameter number {} is out of range", e.number));
    }
    if (!std::isfinite(e.value)) {
      throw std::invalid_argument(
          fmt::format("write_var_file: parameter {} is not finite", e.number));
    }
  }
  std::stable_sort(sorted.begin(), sorted.end(), [](const VarFileEntry& a, const VarFileEntry& b) {
    return a.number < b.number;
  });
  std::string out;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    // The later of equal numbers wins: skip an entry its successor replaces.
    if (i + 1 < sorted.size() && sorted[i + 1].number == sorted[i].number) continue;
    fmt::format_to(std::back_inserter(out), "{}\t{:.6f}\n", sorted[i].number, sorted[i].value);
  }
  return out;
}

}  // namespace usina::gcode
