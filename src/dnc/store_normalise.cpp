#include "dnc/store_normalise.hpp"

#include "gcode/dialect.hpp"

namespace usina::dnc {
namespace {

// Tape leader and trailer, and the transfer codes a punched tape or a
// receive can leave in a file.
bool transfer_char(char c) {
  const auto b = static_cast<unsigned char>(c);
  return b == 0x00 || (b >= 0x11 && b <= 0x14) || b == 0x7f || b == '\r';
}

bool blank(char c) {
  return c == ' ' || c == '\t';
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && blank(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && blank(s.back()))
    s.remove_suffix(1);
  return s;
}

bool digit(char c) {
  return c >= '0' && c <= '9';
}

// `s` without its sequence number: "/ N0010 G1 X1" → "/G1 X1".
std::string without_sequence_number(std::string_view s, const NormaliseRules& rules) {
  std::string prefix;
  if (!s.empty() && s.front() == '/') {
    prefix = "/";
    s = trim(s.substr(1));
  }
  const bool n_letter =
      !s.empty() && (s.front() == 'N' || (s.front() == 'n' && !rules.lower_case_meaning));
  if (n_letter && s.size() > 1 && digit(s[1])) {
    std::size_t i = 1;
    while (i < s.size() && digit(s[i]))
      ++i;
    s = trim(s.substr(i));
  }
  return prefix + std::string(s);
}

void add_block(std::vector<Block>& out, std::string_view raw, std::uint32_t line,
               const NormaliseRules& rules) {
  std::string kept;
  kept.reserve(raw.size());
  for (const char c : raw) {
    if (!transfer_char(c)) kept += c;
  }
  std::string_view s = trim(kept);
  if (!s.empty() && s.back() == ';') s = trim(s.substr(0, s.size() - 1));
  if (s.empty() || s == "%") return;
  std::string text = without_sequence_number(s, rules);
  if (text.empty() || text == "/") return;
  out.push_back({std::move(text), line});
}

}  // namespace

std::vector<Block> normalise_program(std::string_view text, const NormaliseRules& rules) {
  std::vector<Block> out;
  out.reserve(text.size() / 24 + 1);
  std::uint32_t line = 1;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    const bool end = i == text.size();
    const char c = end ? '\n' : text[i];
    if (c != '\n' && rules.block_ends.find(c) == std::string_view::npos) continue;
    add_block(out, text.substr(start, i - start), line, rules);
    start = i + 1;
    if (c == '\n') ++line;
  }
  return out;
}

NormaliseRules normalise_rules(std::string_view dialect) {
  const gcode::Dialect* d = gcode::find_dialect(dialect);
  if (d == nullptr) return {};
  return {d->lexical.block_ends, d->lexical.lower_case_meaning};
}

}  // namespace usina::dnc
