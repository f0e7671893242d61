#include "gcode/fanuc/tape.hpp"

#include <algorithm>
#include <array>
#include <cctype>

namespace usina::gcode::fanuc {
namespace {

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// Skips blanks and comments (a comment reads as a blank).
void skip_space(std::string_view s, std::size_t& i) {
  while (i < s.size() && (blank(s[i]) || s[i] == '(')) {
    i = s[i] == '(' ? skip_comment(s, i) : i + 1;
  }
}

// Reads a run of digits (blanks and comments allowed between them) at `i`;
// -1 if none.
long digits(std::string_view s, std::size_t& i) {
  long v = -1;
  std::size_t j = i;
  while (j < s.size() &&
         (std::isdigit(static_cast<unsigned char>(s[j])) || blank(s[j]) || s[j] == '(')) {
    if (s[j] == '(') {
      j = skip_comment(s, j);
      continue;
    }
    if (!blank(s[j])) v = (v < 0 ? 0 : v) * 10 + (s[j] - '0');
    if (v > 99'999'999) break;
    ++j;
  }
  if (v >= 0) i = j;
  return v;
}

// The characters a block is made of, as against the blanks, comments,
// block ends and '%' the tape is cut at.
// The characters where cutting a block decides something.
constexpr std::array<bool, 256> kDecides = [] {
  std::array<bool, 256> t{};
  for (unsigned char c : {'(', '%', ';', '\n'})
    t[c] = true;
  return t;
}();

unsigned decides(char c) {
  return kDecides[static_cast<unsigned char>(c)] ? 1u : 0u;
}

// The offset of the first character at `i` or after it where cutting
// decides something, or the end of the text: four characters a test (one
// branch), since a block's words and blanks are most of the tape.
std::size_t next_decider(std::string_view text, std::size_t i) {
  const char* p = text.data();
  for (; i + 4 <= text.size(); i += 4) {
    if ((decides(p[i]) | decides(p[i + 1]) | decides(p[i + 2]) | decides(p[i + 3])) != 0) break;
  }
  while (i < text.size() && decides(p[i]) == 0)
    ++i;
  return i;
}

// The offset of the first line from `start` on that starts with '%'
// (blanks before it allowed), or npos.
std::size_t first_percent_line(std::string_view text, std::size_t start) {
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

}  // namespace

namespace {

// skip_comment(), and whether the comment was closed.
std::size_t comment_end(std::string_view text, std::size_t open, bool& closed) {
  int depth = 1;
  closed = true;
  for (std::size_t k = open + 1; k < text.size() && text[k] != '\n'; ++k) {
    if (text[k] == '(') ++depth;
    if (text[k] == ')' && --depth == 0) return k + 1;
  }
  closed = false;
  return std::min(text.find('\n', open + 1), text.size());
}

}  // namespace

std::size_t skip_comment(std::string_view text, std::size_t open) {
  bool closed = false;
  return comment_end(text, open, closed);
}

// The block being cut from the tape: where it started, its first comment,
// and where its last character outside a comment ends (blanks and comments
// after it are not part of its text).
struct Tape::PendingBlock {
  std::size_t start = 0;
  std::uint32_t line = 1;
  std::size_t line_start = 0;
  std::string_view comment;
  std::size_t content_end = 0;
};

namespace {

// Where a file's tape starts. The tape runs from the line after the first
// '%' line to the next '%' (a leader before it is skipped); without a tape
// after a '%' line, the file is read whole.
Tape::PendingBlock tape_start(std::string_view text, std::size_t from, std::size_t& i) {
  Tape::PendingBlock p;
  i = from;
  p.line_start = from;
  const std::size_t mark = first_percent_line(text, from);
  if (mark != std::string_view::npos) {
    const std::size_t after = std::min(text.find('\n', mark), text.size());
    if (text.find_first_not_of(" \t\r\n%", after) != std::string_view::npos) {
      p.line += static_cast<std::uint32_t>(
          std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(mark), '\n'));
      p.line_start = mark;
      i = after;
    }
  }
  p.start = i;
  return p;
}

// Reads a block's head: the '/' of block delete (with its optional switch
// digit), the O (or ':') program number and the N sequence number, in the
// order Fanuc allows them; returns where the block's words start.
std::size_t read_block_head(std::string_view raw, TapeBlock& b) {
  std::size_t k = 0;
  skip_space(raw, k);
  if (k < raw.size() && raw[k] == '/') {
    b.deleted = true;
    ++k;
    if (k < raw.size() && std::isdigit(static_cast<unsigned char>(raw[k]))) ++k;
    skip_space(raw, k);
  }
  if (k < raw.size() && (raw[k] == 'O' || raw[k] == 'o' || raw[k] == ':')) {
    std::size_t j = k + 1;
    const long n = digits(raw, j);
    if (n >= 0) {
      b.program = n;
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
  skip_space(raw, k);
  return k;
}

}  // namespace

TapePos Tape::add_file(std::uint32_t file, std::string_view text, std::size_t from) {
  std::size_t i = 0;
  const PendingBlock p = tape_start(text, std::min(from, text.size()), i);
  const TapePos start{file, p.line, i, p.line_start};
  files_.push_back({file, text, start, false});
  return start;
}

std::string_view Tape::text_of(std::uint32_t file) const {
  for (const File& f : files_) {
    if (f.id == file) return f.text;
  }
  return {};
}

TapeBlock Tape::cut(TapePos at) const {
  TapeBlock b;
  cut(at, b);
  return b;
}

void Tape::cut(TapePos at, TapeBlock& b) const {
  const std::string_view text = text_of(at.file);
  PendingBlock p{at.offset, at.line, at.line_start, {}, at.offset};
  for (std::size_t i = at.offset; i < text.size(); ++i) {
    const char c = text[i];
    if (!kDecides[static_cast<unsigned char>(c)]) {
      // A run of the block's own characters and blanks, words and blanks
      // alike (a loop that stopped at each blank stopped at every word):
      // the block's content ends after its last character that is not blank.
      const std::size_t j = next_decider(text, i + 1);
      std::size_t end = j;
      while (end > i && blank(text[end - 1]))
        --end;
      if (end > i) p.content_end = end;
      i = j - 1;
      continue;
    }
    if (c == '(') {
      bool shut = false;
      const std::size_t after = comment_end(text, i, shut);
      if (p.comment.empty()) p.comment = text.substr(i + 1, after - i - (shut ? 2 : 1));
      i = after - 1;
      continue;
    }
    if (c == '%') {
      if (make_block(at.file, text, i, p, b)) {
        b.next = {at.file, p.line, i, p.line_start};
        return;
      }
      b = TapeBlock{};
      b.at = {at.file, p.line, i, p.line_start};
      b.end = b.closed = true;
      return;
    }
    if (c == ';' || c == '\n') {
      const bool made = make_block(at.file, text, i, p, b);
      p.start = i + 1;
      p.comment = {};
      if (c == '\n') {
        ++p.line;
        p.line_start = i + 1;
      }
      if (made) {
        b.next = {at.file, p.line, p.start, p.line_start};
        return;
      }
      continue;
    }
  }
  if (p.start < text.size() && make_block(at.file, text, text.size(), p, b)) {
    b.next = {at.file, p.line, text.size(), p.line_start};
    return;
  }
  b = TapeBlock{};
  b.at = {at.file, p.line, std::max<std::uint64_t>(at.offset, text.size()), p.line_start};
  b.end = true;
}

// The pending block cut at `stop` into `b`; false when it is empty. Every
// field of `b` but `next` (cut's) is written here, in place: `b =
// TapeBlock{}` built a whole block on the stack and copied it in, read back
// before its stores had landed (issue 19).
bool Tape::make_block(std::uint32_t file, std::string_view text, std::size_t stop,
                      const PendingBlock& p, TapeBlock& b) const {
  const std::string_view raw = text.substr(p.start, stop - p.start);
  b.sequence = -1;  // the head's words, when the block has them
  b.deleted = false;
  b.program = -1;
  b.end = b.closed = false;
  b.col = static_cast<std::uint32_t>(p.start - p.line_start + 1);
  b.comment = p.comment;
  b.length = stop - p.start;
  b.at = {file, p.line, p.start, p.line_start};
  const std::size_t k = read_block_head(raw, b);
  const std::size_t end = p.content_end > p.start + k ? p.content_end - p.start : k;
  b.text = raw.substr(k, end - k);
  b.loc = {file, p.line, b.col + static_cast<std::uint32_t>(k), 0, p.line_start};
  // Blank lines and stray ';' make no block.
  return !b.text.empty() || b.program >= 0 || b.sequence >= 0 || !p.comment.empty();
}

std::optional<TapePos> Tape::program(long number) {
  if (auto it = programs_.find(number); it != programs_.end()) return it->second;
  for (File& f : files_) {
    while (!f.all_indexed) {
      const TapeBlock b = cut(f.indexed);
      if (b.end) {
        f.all_indexed = true;
        break;
      }
      f.indexed = b.next;
      if (b.program >= 0 && programs_.emplace(b.program, b.at).second && b.program == number)
        return b.at;
    }
  }
  return std::nullopt;
}

}  // namespace usina::gcode::fanuc
