// The difference between two sequences of lines: Myers' O(ND) algorithm
// ("An O(ND) Difference Algorithm and Its Variations", 1986) in its
// linear-space form (the middle snake, §4b), after two cuts that make it fast
// on programs: the common head and tail are taken off first, and lines that
// occur in only one of the two sequences are marked changed before the
// search (GNU diff's "discard" step), so a program rewritten in one place
// costs that place. A search whose edit distance grows past a bound splits at
// its furthest point instead of the optimal one (a correct, possibly longer
// diff), so no pair of inputs costs more than about bound × their length.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace usina::dnc {

enum class EditKind { Equal, Delete, Insert };

// `count` lines from a[a_begin] (Equal, Delete) and/or b[b_begin] (Equal, Insert).
struct Edit {
  EditKind kind = EditKind::Equal;
  std::size_t a_begin = 0;
  std::size_t b_begin = 0;
  std::size_t count = 0;
};

struct LineDiff {
  std::vector<Edit> edits;  // in order, covering both sequences
  std::size_t deleted = 0;
  std::size_t inserted = 0;

  bool identical() const { return deleted == 0 && inserted == 0; }
};

// Lines compared by number (intern them first).
LineDiff diff_ids(std::span<const std::uint32_t> a, std::span<const std::uint32_t> b);
// Lines compared as text.
LineDiff diff_lines(std::span<const std::string_view> a, std::span<const std::string_view> b);

}  // namespace usina::dnc
