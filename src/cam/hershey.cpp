#include "cam/hershey.hpp"

#include <charconv>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace usina::cam {
namespace {

// Reads characters across line ends (a record may wrap).
class RecordReader {
 public:
  explicit RecordReader(std::string_view text) : text_(text) {}

  bool at_end() {
    while (pos_ < text_.size() && (text_[pos_] == '\n' || text_[pos_] == '\r'))
      step();
    return pos_ >= text_.size();
  }

  // The next `n` characters, line ends skipped; false when the text ends first.
  bool take(std::size_t n, std::string& out) {
    out.clear();
    while (out.size() < n && pos_ < text_.size()) {
      const char c = text_[pos_];
      step();
      if (c != '\n' && c != '\r') out.push_back(c);
    }
    return out.size() == n;
  }

  // Starts the next record on a new line (what follows a record on its line is ignored).
  void next_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n')
      step();
  }

  std::size_t line() const { return line_; }

 private:
  void step() {
    if (text_[pos_++] == '\n') ++line_;
  }

  std::size_t line_ = 1;
  std::string_view text_;
  std::size_t pos_ = 0;
};

std::optional<int> number(std::string_view field) {
  while (!field.empty() && field.front() == ' ')
    field.remove_prefix(1);
  int v = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  if (ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return v;
}

HersheyGlyph glyph_of(std::string_view pairs) {
  HersheyGlyph g;
  g.left = pairs[0] - 'R';
  g.right = pairs[1] - 'R';
  g.strokes.emplace_back();
  for (std::size_t i = 2; i + 1 < pairs.size(); i += 2) {
    if (pairs[i] == ' ' && pairs[i + 1] == 'R') {
      g.strokes.emplace_back();
      continue;
    }
    g.strokes.back().push_back(
        {static_cast<double>(pairs[i] - 'R'), -static_cast<double>(pairs[i + 1] - 'R')});
  }
  std::erase_if(g.strokes, [](const auto& s) { return s.empty(); });
  return g;
}

std::optional<HersheyFont> bad(core::DiagnosticSink& diags, const std::string& name,
                               std::size_t line, std::string_view what) {
  diags.report({core::Code::FontUnreadable,
                core::Severity::Error,
                {},
                fmt::format("{}:{}: not a Hershey .jhf font: {}", name, line, what)});
  return std::nullopt;
}

}  // namespace

const HersheyGlyph* HersheyFont::glyph(char c) const {
  const int i = static_cast<unsigned char>(c) - 32;
  if (i < 0 || static_cast<std::size_t>(i) >= glyphs.size()) return nullptr;
  return &glyphs[static_cast<std::size_t>(i)];
}

std::string hershey_file(const std::string& font, const std::string& dir) {
  if (font.find('/') != std::string::npos || font.ends_with(".jhf")) return font;
  return dir + "/" + font + ".jhf";
}

std::optional<HersheyFont> parse_hershey(std::string_view text, const std::string& name,
                                         core::DiagnosticSink& diags) {
  HersheyFont font{name, {}};
  RecordReader in(text);
  std::string head;
  std::string pairs;
  while (!in.at_end()) {
    const std::size_t line = in.line();
    if (!in.take(8, head)) return bad(diags, name, line, "a record shorter than its header");
    const auto count = number(std::string_view(head).substr(5, 3));
    if (!count || *count < 1) {
      return bad(diags, name, line, "columns 6-8 are not a count of pairs");
    }
    if (!in.take(2 * static_cast<std::size_t>(*count), pairs)) {
      return bad(diags, name, line, "the record ends before its pairs");
    }
    for (char c : pairs) {
      if (c < ' ' || c > '~') return bad(diags, name, line, "a character outside ASCII");
    }
    font.glyphs.push_back(glyph_of(pairs));
    in.next_line();
  }
  if (font.glyphs.empty()) return bad(diags, name, 1, "no glyphs");
  return font;
}

std::optional<HersheyFont> read_hershey(const std::string& file, core::DiagnosticSink& diags) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    diags.report({core::Code::FontUnreadable,
                  core::Severity::Error,
                  {},
                  fmt::format("{}: cannot open the font (the hershey-fonts-data package "
                              "installs them in /usr/share/hershey-fonts)",
                              file)});
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_hershey(text.str(), file, diags);
}

}  // namespace usina::cam
