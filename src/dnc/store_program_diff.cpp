#include "dnc/store_program_diff.hpp"

#include <algorithm>

#include <fmt/format.h>

namespace usina::dnc {
namespace {

std::vector<Block> lines_of(std::string_view text) {
  std::vector<Block> out;
  std::uint32_t line = 1;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t nl = text.find('\n', start);
    const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
    out.push_back({std::string(text.substr(start, end - start)), line++});
    start = end + 1;
  }
  return out;
}

LineDiff diff_blocks(const std::vector<Block>& a, const std::vector<Block>& b) {
  std::vector<std::string_view> av;
  av.reserve(a.size());
  for (const Block& x : a)
    av.push_back(x.text);
  std::vector<std::string_view> bv;
  bv.reserve(b.size());
  for (const Block& x : b)
    bv.push_back(x.text);
  return diff_lines(av, bv);
}

// A hunk: edits [first, last) of the diff, with context around them.
struct Hunk {
  std::size_t first;
  std::size_t last;
};

std::vector<Hunk> hunks_of(const LineDiff& d, std::size_t context) {
  std::vector<Hunk> out;
  for (std::size_t i = 0; i < d.edits.size(); ++i) {
    if (d.edits[i].kind == EditKind::Equal) continue;
    // Changes side by side, or apart by no more than twice the context, share a hunk.
    const bool joins =
        !out.empty() &&
        (out.back().last == i || (out.back().last + 1 == i && d.edits[i - 1].count <= 2 * context));
    if (joins) {
      out.back().last = i + 1;
    } else {
      out.push_back({i, i + 1});
    }
  }
  return out;
}

std::uint32_t line_at(const std::vector<Block>& blocks, std::size_t i) {
  if (blocks.empty()) return 0;
  return i < blocks.size() ? blocks[i].line : blocks.back().line + 1;
}

void write_hunk(std::string& out, const ProgramDiff& d, const Hunk& h, std::size_t context) {
  const auto& e = d.diff.edits;
  // Context before the first change and after the last, inside the Equal edits beside them.
  const std::size_t lead = h.first > 0 ? std::min(context, e[h.first - 1].count) : 0;
  const std::size_t trail = h.last < e.size() ? std::min(context, e[h.last].count) : 0;
  const std::size_t a0 = e[h.first].a_begin - lead;
  const std::size_t b0 = e[h.first].b_begin - lead;
  std::string body;
  std::size_t a_count = 0;
  std::size_t b_count = 0;
  const auto emit = [&](char mark, const Block& blk) { body += mark + blk.text + '\n'; };
  for (std::size_t k = 0; k < lead; ++k, ++a_count, ++b_count)
    emit(' ', d.old_blocks[a0 + k]);
  for (std::size_t i = h.first; i < h.last; ++i) {
    const Edit& x = e[i];
    for (std::size_t k = 0; k < x.count; ++k) {
      if (x.kind != EditKind::Insert) ++a_count;
      if (x.kind != EditKind::Delete) ++b_count;
      if (x.kind == EditKind::Insert) {
        emit('+', d.new_blocks[x.b_begin + k]);
      } else {
        emit(x.kind == EditKind::Delete ? '-' : ' ', d.old_blocks[x.a_begin + k]);
      }
    }
  }
  const Edit& after = h.last < e.size() ? e[h.last] : e.back();
  for (std::size_t k = 0; k < trail; ++k, ++a_count, ++b_count)
    emit(' ', d.old_blocks[after.a_begin + k]);
  out += fmt::format("@@ -{},{} +{},{} @@\n", line_at(d.old_blocks, a0), a_count,
                     line_at(d.new_blocks, b0), b_count);
  out += body;
}

}  // namespace

ProgramDiff plain_diff(std::string_view old_text, std::string_view new_text) {
  ProgramDiff d{lines_of(old_text), lines_of(new_text), {}};
  d.diff = diff_blocks(d.old_blocks, d.new_blocks);
  return d;
}

ProgramDiff normalised_diff(std::string_view old_text, std::string_view new_text,
                            const NormaliseRules& rules) {
  ProgramDiff d{normalise_program(old_text, rules), normalise_program(new_text, rules), {}};
  d.diff = diff_blocks(d.old_blocks, d.new_blocks);
  return d;
}

std::string unified_diff(const ProgramDiff& d, std::string_view old_label,
                         std::string_view new_label, std::size_t context) {
  if (d.diff.identical()) return {};
  std::string out = fmt::format("--- {}\n+++ {}\n", old_label, new_label);
  for (const Hunk& h : hunks_of(d.diff, context))
    write_hunk(out, d, h, context);
  return out;
}

}  // namespace usina::dnc
