#include "apt/cl.hpp"

#include <cmath>

#include <fmt/format.h>

namespace usina::apt {

ClWord symbol_word(const std::string& name) {
  std::string t = name.substr(0, 6);
  return ClWord::chars(std::string(6 - t.size(), ' ') + t);
}

std::vector<ClWord> text_words(const std::string& text, std::size_t count) {
  std::vector<ClWord> out;
  for (std::size_t i = 0; i < text.size() && out.size() < count; i += 6)
    out.push_back(ClWord::chars(text.substr(i, 6)));
  while (out.size() < count)
    out.push_back(ClWord::chars(""));
  return out;
}

namespace {

void print_word(fmt::memory_buffer& out, const ClRecord& r, std::size_t i) {
  const ClWord& w = r.words[i];
  if (w.kind == ClWord::Kind::Code) {
    fmt::format_to(std::back_inserter(out), "#{}", w.code);
  } else if (w.kind == ClWord::Kind::Text) {
    std::string t = w.text;
    while (!t.empty() && t.back() == ' ')
      t.pop_back();
    fmt::format_to(std::back_inserter(out), "'{}'", t);
  } else {
    const double v = w.real == 0.0 ? 0.0 : w.real;
    // Coordinates of motion records print with 7 decimals, as IBM's CLPRNT
    // (and no "-0.0000000" for a rounding residue).
    if (r.cls == cls::kMotion && i >= 2)
      fmt::format_to(std::back_inserter(out), "{:.7f}", std::fabs(v) < 5e-8 ? 0.0 : v);
    else
      fmt::format_to(std::back_inserter(out), "{}", v);
  }
}

}  // namespace

std::string record_print(const std::vector<ClRecord>& records, std::size_t first) {
  fmt::memory_buffer out;
  std::size_t recno = first - 1;
  for (const ClRecord& r : records) {
    fmt::format_to(std::back_inserter(out), "{} {} {} {} ", ++recno, r.cls, r.sub, r.words.size());
    for (std::size_t i = 0; i < r.words.size(); ++i) {
      if (i > 0) out.push_back(' ');
      print_word(out, r, i);
    }
    out.push_back('\n');
  }
  return fmt::to_string(out);
}

}  // namespace usina::apt
