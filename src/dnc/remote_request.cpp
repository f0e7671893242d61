#include "dnc/remote_request.hpp"

#include <algorithm>
#include <charconv>
#include <vector>

#include <fmt/format.h>

#include "dnc/tape_reader.hpp"

namespace usina::dnc {
namespace {

constexpr std::size_t kMaxLine = 256;  // a request's line; longer ones are read cut

bool is_word_char(char c) {
  return c != ' ' && c != '\t' && c != '=' && c != '/';
}

char upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

std::string upper(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](char c) { return upper(c); });
  return out;
}

// KEY=VALUE and /KEY VALUE pairs of one comment's text.
std::vector<std::pair<std::string, std::string>> pairs_of(std::string_view s) {
  std::vector<std::pair<std::string, std::string>> out;
  std::size_t i = 0;
  auto skip_blank = [&] {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t'))
      ++i;
  };
  auto word = [&] {
    const std::size_t start = i;
    while (i < s.size() && is_word_char(s[i]))
      ++i;
    return s.substr(start, i - start);
  };
  while (i < s.size() && out.size() < 16) {
    skip_blank();
    const bool slash = i < s.size() && s[i] == '/';
    if (slash) ++i;
    const std::string key = upper(word());
    skip_blank();
    const bool equals = i < s.size() && s[i] == '=';
    if (equals) {
      ++i;
      skip_blank();
    }
    if ((slash || equals) && !key.empty()) {
      // KEY=VALUE runs to a blank, so a path in it is seen whole and refused.
      const std::size_t start = i;
      while (i < s.size() && s[i] != ' ' && s[i] != '\t' && (equals || s[i] != '/'))
        ++i;
      out.emplace_back(key, std::string(s.substr(start, i - start)));
    } else if (i < s.size() && !is_word_char(s[i]) && s[i] != '/') {
      ++i;  // a stray `=`: go on past it
    }
  }
  return out;
}

std::optional<std::uint64_t> number(std::string_view s) {
  while (!s.empty() &&
         (s.front() == 'N' || s.front() == 'T' || s.front() == 'n' || s.front() == 't'))
    s.remove_prefix(1);
  std::uint64_t v = 0;
  if (s.empty() || s.size() > 9) return std::nullopt;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

struct Scan {
  RemoteRequest request;
  bool mentioned = false;  // a request key was seen
  std::string error;
};

void apply(Scan& scan, const std::string& key, const std::string& value) {
  if (!scan.error.empty()) return;
  if (key == "PRG" || key == "PROG" || key == "REQ") {
    scan.mentioned = true;
    if (!scan.request.program.empty() && scan.request.program != value) {
      scan.error = fmt::format("it names two programs, {} and {}", scan.request.program, value);
    } else if (!valid_program_name(value)) {
      scan.error = fmt::format("\"{}\" is no program name", value.substr(0, 64));
    } else {
      scan.request.program = value;
    }
  } else if (key == "BL" || key == "LI" || key == "TO") {
    scan.mentioned = true;
    const auto n = number(value);
    if (!n && key == "LI" && valid_program_name(value)) {
      scan.request.operator_name = value;  // CIMCO's (/LI JOHN): a login
    } else if (!n || (key == "TO" && *n > 99999)) {
      scan.error = fmt::format("{} {} is not a number", key, value.substr(0, 20));
    } else if (key == "BL") {
      scan.request.start_block = *n;
    } else if (key == "LI") {
      scan.request.start_line = *n;
    } else {
      scan.request.start_tool = static_cast<std::uint32_t>(*n);
    }
  } else if (key == "OP" && valid_program_name(value)) {
    scan.request.operator_name = value;
  }
}

void scan_line(Scan& scan, std::string_view line) {
  std::size_t at = 0;
  while ((at = line.find('(', at)) != std::string_view::npos) {
    const std::size_t close = line.find(')', at + 1);
    const std::string_view inside = line.substr(
        at + 1, close == std::string_view::npos ? std::string_view::npos : close - at - 1);
    for (const auto& [key, value] : pairs_of(inside))
      apply(scan, key, value);
    if (close == std::string_view::npos) break;
    at = close + 1;
  }
}

}  // namespace

bool valid_program_name(std::string_view name) {
  if (name.empty() || name.size() > 64 || name.front() == '.' || name.front() == '-') return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.';
  });
}

std::optional<tl::expected<RemoteRequest, std::string>> parse_remote_request(
    std::string_view text, const RequestRules& rules) {
  Scan scan;
  std::size_t at = 0;
  for (std::uint32_t n = 0; n < rules.scan_lines && at < text.size(); ++n) {
    std::size_t end = text.find('\n', at);
    if (end == std::string_view::npos) end = text.size();
    scan_line(scan, text.substr(at, std::min(end - at, kMaxLine)));
    at = end + 1;
  }
  const std::string number_word = program_number(text.substr(0, at));
  const bool request_number = rules.request_program != 0 && !number_word.empty() &&
                              number(number_word.substr(1)) == rules.request_program;
  const bool is_request = request_number || (rules.request_program == 0 && scan.mentioned);
  if (!is_request) return std::nullopt;
  if (!scan.error.empty()) return tl::make_unexpected(scan.error);
  if (scan.request.program.empty()) {
    return tl::make_unexpected(std::string("it names no program: write (PRG=NAME)"));
  }
  return scan.request;
}

std::string response_program(std::uint32_t number, std::string_view message) {
  // Letters, digits, space and `. , - + /` are in every tape code (EIA's too).
  std::string clean;
  for (const char c : message) {
    const char u = upper(c);
    const bool ok = (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') || u == ' ' || u == '.' ||
                    u == ',' || u == '-' || u == '+' || u == '/';
    clean.push_back(ok ? u : ' ');
  }
  std::string out = fmt::format("O{:04}\n", number);
  constexpr std::size_t kWidth = 60;
  for (std::size_t at = 0; at < clean.size() && at < 20 * kWidth; at += kWidth) {
    out += fmt::format("(USINA {})\n", clean.substr(at, kWidth));
  }
  out += "M30\n";
  return out;
}

}  // namespace usina::dnc
