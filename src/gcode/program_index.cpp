#include "gcode/program_index.hpp"

#include <algorithm>
#include <cstring>

#include "gcode/parser.hpp"
#include "gcode/program_text.hpp"

namespace usina::gcode {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// True when the first word of the line (after '/', blanks and an N number)
// is an O: only those lines are parsed by the index.
bool starts_with_o(std::string_view line) {
  std::size_t i = 0;
  auto skip = [&] {
    while (i < line.size() && is_blank(line[i]))
      ++i;
  };
  skip();
  if (i < line.size() && line[i] == '/') ++i;
  skip();
  if (i < line.size() && (line[i] == 'n' || line[i] == 'N')) {
    ++i;
    while (i < line.size() &&
           (is_blank(line[i]) || line[i] == '.' || (line[i] >= '0' && line[i] <= '9'))) {
      ++i;
    }
  }
  skip();
  return i < line.size() && (line[i] == 'o' || line[i] == 'O');
}

class NullDiagnostics final : public core::DiagnosticSink {
 public:
  void report(core::Diagnostic) override {}
};

}  // namespace

LineView line_at(std::string_view text, std::uint64_t offset) {
  if (offset >= text.size()) return {{}, text.size()};
  const char* base = text.data() + offset;
  const std::size_t left = text.size() - offset;
  const void* nl = std::memchr(base, '\n', left);
  const std::size_t len =
      nl != nullptr ? static_cast<std::size_t>(static_cast<const char*>(nl) - base) : left;
  std::string_view line(base, len);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return {line, offset + len + (nl != nullptr ? 1 : 0)};
}

ProgramIndex ProgramIndex::build(core::SourceFile& file, std::uint32_t file_id) {
  ProgramIndex index;
  const std::string_view text = file.text();
  NullDiagnostics quiet;
  Block block;
  std::uint64_t offset = byte_order_mark_length(text);
  std::uint32_t line = 1;
  while (offset < text.size()) {
    const LineView lv = line_at(text, offset);
    // Cheap test first: most lines of a long program have no O-word. A line
    // over the block limit is left to the interpreter to report.
    if (lv.text.size() <= kMaxBlockLength &&
        (std::memchr(lv.text.data(), 'o', lv.text.size()) != nullptr ||
         std::memchr(lv.text.data(), 'O', lv.text.size()) != nullptr)) {
      if (starts_with_o(lv.text) && parse_block(lv.text, {file_id, line, offset}, block, quiet) &&
          block.o) {
        OEntry e;
        e.kind = block.o->kind;
        e.label = block.o->label;
        e.offset = offset;
        e.next_line = lv.next;
        e.line = line;
        index.entries_.push_back(std::move(e));
      }
    }
    file.release_before(offset);
    offset = lv.next;
    ++line;
  }
  index.link();
  return index;
}

void ProgramIndex::link() {
  std::unordered_map<std::string, std::uint32_t> last;
  // Open `do` loops per label, to tell a do-while's closing `while` from a
  // `while` that opens a loop.
  std::unordered_map<std::string, int> open_do;
  for (std::uint32_t i = 0; i < entries_.size(); ++i) {
    OEntry& e = entries_[i];
    auto it = last.find(e.label);
    if (it != last.end()) {
      e.prev_same = it->second;
      entries_[it->second].next_same = i;
    }
    last[e.label] = i;
    if (e.kind == OKind::Do) ++open_do[e.label];
    if (e.kind == OKind::While && open_do[e.label] > 0) {
      --open_do[e.label];
      e.ends_do = true;
    }
    if (e.kind == OKind::Sub) subs_.emplace(e.label, i);
  }
}

std::uint32_t ProgramIndex::find(std::uint64_t offset) const {
  auto it = std::lower_bound(entries_.begin(), entries_.end(), offset,
                             [](const OEntry& e, std::uint64_t off) { return e.offset < off; });
  if (it == entries_.end() || it->offset != offset) return kNoEntry;
  return static_cast<std::uint32_t>(it - entries_.begin());
}

std::uint32_t ProgramIndex::sub(const std::string& name) const {
  auto it = subs_.find(name);
  return it == subs_.end() ? kNoEntry : it->second;
}

std::uint32_t ProgramIndex::next_of(std::uint32_t from, std::initializer_list<OKind> kinds) const {
  for (std::uint32_t i = entries_[from].next_same; i != kNoEntry; i = entries_[i].next_same) {
    if (std::find(kinds.begin(), kinds.end(), entries_[i].kind) != kinds.end()) return i;
  }
  return kNoEntry;
}

std::uint32_t ProgramIndex::prev_of(std::uint32_t from, std::initializer_list<OKind> kinds) const {
  for (std::uint32_t i = entries_[from].prev_same; i != kNoEntry; i = entries_[i].prev_same) {
    if (std::find(kinds.begin(), kinds.end(), entries_[i].kind) != kinds.end()) return i;
  }
  return kNoEntry;
}

}  // namespace usina::gcode
