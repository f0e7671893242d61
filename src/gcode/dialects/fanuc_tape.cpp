#include "gcode/dialects/fanuc_tape.hpp"

#include <algorithm>
#include <cctype>

namespace usina::gcode::fanuc {
namespace {

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// Reads a run of digits (blanks allowed between them) at `i`; -1 if none.
long digits(std::string_view s, std::size_t& i) {
  long v = -1;
  std::size_t j = i;
  while (j < s.size() && (std::isdigit(static_cast<unsigned char>(s[j])) || blank(s[j]))) {
    if (!blank(s[j])) v = (v < 0 ? 0 : v) * 10 + (s[j] - '0');
    if (v > 99'999'999) break;
    ++j;
  }
  if (v >= 0) i = j;
  return v;
}

// The offset of the first line that starts with '%' (blanks before it
// allowed), or npos.
std::size_t first_percent_line(std::string_view text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t k = start;
    while (k < text.size() && blank(text[k]))
      ++k;
    if (k < text.size() && text[k] == '%') return start;
    const std::size_t nl = text.find('\n', start);
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
  return std::string_view::npos;
}

void skip_blanks(std::string_view s, std::size_t& i) {
  while (i < s.size() && blank(s[i]))
    ++i;
}

}  // namespace

std::size_t Tape::add_file(std::uint32_t file, std::string_view text) {
  const std::size_t first = blocks_.size();
  // The tape runs from the line after the first '%' line to the next '%'
  // (a leader before it is skipped); without a tape after a '%' line, the
  // file is read whole.
  std::size_t i = 0;
  std::uint32_t line = 1;
  std::size_t line_start = 0;
  bool closed = false;
  const std::size_t mark = first_percent_line(text);
  if (mark != std::string_view::npos) {
    const std::size_t after = std::min(text.find('\n', mark), text.size());
    if (text.find_first_not_of(" \t\r\n%", after) != std::string_view::npos) {
      line += static_cast<std::uint32_t>(
          std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(mark), '\n'));
      line_start = mark;
      i = after;
    }
  }
  std::size_t start = i;
  std::string_view comment;
  std::string cleaned;
  bool has_comment = false;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> gaps;
  auto end_block = [&](std::size_t stop) {
    std::string_view raw =
        has_comment ? std::string_view(cleaned) : text.substr(start, stop - start);
    TapeBlock b;
    b.file = file;
    b.line = line;
    b.line_offset = line_start;
    b.col = static_cast<std::uint32_t>(start - line_start + 1);
    b.comment = comment;
    std::size_t k = 0;
    skip_blanks(raw, k);
    if (k < raw.size() && raw[k] == '/') {
      b.deleted = true;
      ++k;
      if (k < raw.size() && std::isdigit(static_cast<unsigned char>(raw[k]))) ++k;
      skip_blanks(raw, k);
    }
    if (k < raw.size() && (raw[k] == 'O' || raw[k] == 'o' || raw[k] == ':')) {
      std::size_t j = k + 1;
      const long n = digits(raw, j);
      if (n >= 0) {
        b.program = n;
        programs_.emplace(n, blocks_.size());
        k = j;
      }
    }
    if (k < raw.size() && (raw[k] == 'N' || raw[k] == 'n')) {
      std::size_t j = k + 1;
      const long n = digits(raw, j);
      if (n >= 0) {
        b.sequence = n;
        k = j;
      }
    }
    skip_blanks(raw, k);
    std::string_view rest = raw.substr(k);
    while (!rest.empty() && blank(rest.back()))
      rest.remove_suffix(1);
    if (has_comment) {
      b.text_start = static_cast<std::uint32_t>(rest.data() - raw.data());
      b.gaps = gaps;
      stripped_.emplace_back(rest);
      rest = stripped_.back();
    }
    b.text = rest;
    if (!rest.empty() || b.program >= 0 || b.sequence >= 0 || !comment.empty())
      blocks_.push_back(b);
    cleaned.clear();
    has_comment = false;
    comment = {};
    gaps.clear();
  };
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(') {
      // Inner '( )' pairs are read as part of the comment (programs quote
      // settings in comments: "(READ WITH (DPI=0) ...)").
      std::size_t close = std::string_view::npos;
      int depth = 1;
      for (std::size_t k = i + 1; k < text.size() && text[k] != '\n'; ++k) {
        if (text[k] == '(') ++depth;
        if (text[k] == ')' && --depth == 0) {
          close = k;
          break;
        }
      }
      if (close == std::string_view::npos) close = text.find('\n', i + 1);
      const std::size_t stop = close == std::string_view::npos ? text.size() : close;
      if (!has_comment) cleaned.assign(text.substr(start, i - start));
      if (comment.empty()) comment = text.substr(i + 1, stop - i - 1);
      has_comment = true;
      const std::size_t last =
          (close != std::string_view::npos && text[close] == ')') ? close : stop - 1;
      gaps.emplace_back(static_cast<std::uint32_t>(cleaned.size()),
                        static_cast<std::uint32_t>(last - i));
      cleaned += ' ';
      i = last;
      continue;
    }
    if (c == '%') {
      end_block(i);
      closed = true;
      break;
    }
    if (c == ';' || c == '\n') {
      end_block(i);
      start = i + 1;
      if (c == '\n') {
        ++line;
        line_start = i + 1;
      }
      continue;
    }
    if (has_comment) cleaned += c;
  }
  if (!closed && start < text.size()) end_block(text.size());
  files_.push_back({first, blocks_.size(), closed});
  return first;
}

const Tape::FileSpan& Tape::span_of(std::size_t i) const {
  for (const FileSpan& f : files_) {
    if (i >= f.first && i < f.end) return f;
  }
  return files_.back();
}

std::size_t Tape::program(long number) const {
  auto it = programs_.find(number);
  return it == programs_.end() ? npos : it->second;
}

std::size_t Tape::program_end(std::size_t i) const {
  const FileSpan& f = span_of(i);
  for (std::size_t k = i + 1; k < f.end; ++k) {
    if (blocks_[k].program >= 0) return k;
  }
  return f.end;
}

std::size_t Tape::program_start(std::size_t i) const {
  const FileSpan& f = span_of(i);
  for (std::size_t k = i + 1; k-- > f.first;) {
    if (blocks_[k].program >= 0) return k;
  }
  return f.first;
}

bool Tape::closed(std::size_t i) const {
  return span_of(i).closed;
}

}  // namespace usina::gcode::fanuc
