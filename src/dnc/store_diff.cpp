#include "dnc/store_diff.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <unordered_map>

namespace usina::dnc {
namespace {

using Id = std::uint32_t;

// A search step count past which the middle snake gives up optimality.
constexpr std::ptrdiff_t kMaxCost = 2048;

// The sequences being compared and the "changed" marks being filled in.
struct Work {
  std::span<const Id> a;
  std::span<const Id> b;
  std::vector<char>& a_changed;
  std::vector<char>& b_changed;
  std::vector<std::ptrdiff_t> forward;
  std::vector<std::ptrdiff_t> backward;
};

struct Point {
  std::ptrdiff_t x = 0;
  std::ptrdiff_t y = 0;
};

// The search over a[a0, a0 + n) and b[b0, b0 + m).
struct Search {
  Work& w;
  std::ptrdiff_t a0, n, b0, m;

  Id at_a(std::ptrdiff_t i) const { return w.a[static_cast<std::size_t>(a0 + i)]; }

  Id at_b(std::ptrdiff_t i) const { return w.b[static_cast<std::size_t>(b0 + i)]; }

  std::ptrdiff_t slide_forward(std::ptrdiff_t x, std::ptrdiff_t y) const {
    while (x < n && y < m && at_a(x) == at_b(y))
      ++x, ++y;
    return x;
  }

  std::ptrdiff_t slide_backward(std::ptrdiff_t x, std::ptrdiff_t y) const {
    while (x < n && y < m && at_a(n - x - 1) == at_b(m - y - 1))
      ++x, ++y;
    return x;
  }

  static std::ptrdiff_t next_x(const std::vector<std::ptrdiff_t>& v, std::ptrdiff_t off,
                               std::ptrdiff_t k, std::ptrdiff_t d) {
    const auto i = static_cast<std::size_t>(off + k);
    if (k == -d || (k != d && v[i - 1] < v[i + 1])) return v[i + 1];
    return v[i - 1] + 1;
  }

  // The split point: where the paths from both ends meet (§4b), or, past
  // kMaxCost, the forward path that got furthest.
  std::optional<Point> middle() const;
};

std::optional<Point> Search::middle() const {
  const std::ptrdiff_t max_d = (n + m + 1) / 2;
  const std::ptrdiff_t off = std::min(max_d, kMaxCost) + 1;
  auto& f = w.forward;
  auto& r = w.backward;
  f.assign(static_cast<std::size_t>(2 * off + 2), -1);
  r.assign(static_cast<std::size_t>(2 * off + 2), -1);
  f[static_cast<std::size_t>(off + 1)] = 0;
  r[static_cast<std::size_t>(off + 1)] = 0;
  const std::ptrdiff_t delta = n - m;
  const bool odd = (delta % 2) != 0;
  Point best{0, 0};
  for (std::ptrdiff_t d = 0; d <= max_d; ++d) {
    for (std::ptrdiff_t k = -d; k <= d; k += 2) {
      std::ptrdiff_t x = next_x(f, off, k, d);
      if (x < 0 || x > n || x - k > m || x - k < 0) continue;
      x = slide_forward(x, x - k);
      f[static_cast<std::size_t>(off + k)] = x;
      if (x + (x - k) > best.x + best.y) best = {x, x - k};
      const std::ptrdiff_t rk = delta - k;
      if (odd && rk >= -(d - 1) && rk <= d - 1) {
        const std::ptrdiff_t rx = r[static_cast<std::size_t>(off + rk)];
        if (rx >= 0 && x + rx >= n) return Point{x, x - k};
      }
    }
    for (std::ptrdiff_t k = -d; k <= d; k += 2) {
      std::ptrdiff_t x = next_x(r, off, k, d);
      if (x < 0 || x > n || x - k > m || x - k < 0) continue;
      x = slide_backward(x, x - k);
      r[static_cast<std::size_t>(off + k)] = x;
      const std::ptrdiff_t fk = delta - k;
      if (!odd && fk >= -d && fk <= d) {
        const std::ptrdiff_t fx = f[static_cast<std::size_t>(off + fk)];
        if (fx >= 0 && fx + x >= n) return Point{n - x, m - (x - k)};
      }
    }
    if (d >= kMaxCost) return best;
  }
  return std::nullopt;  // not reached: the paths meet by max_d
}

void mark_all(std::vector<char>& marks, std::span<const std::size_t> index, std::size_t from,
              std::size_t to) {
  for (std::size_t i = from; i < to; ++i)
    marks[index.empty() ? i : index[i]] = 1;
}

// Compares w.a[a0, a1) with w.b[b0, b1), marking what differs.
void compare(Work& w, std::span<const std::size_t> a_index, std::span<const std::size_t> b_index,
             std::size_t a0, std::size_t a1, std::size_t b0, std::size_t b1) {
  while (a0 < a1 && b0 < b1 && w.a[a0] == w.b[b0])
    ++a0, ++b0;
  while (a0 < a1 && b0 < b1 && w.a[a1 - 1] == w.b[b1 - 1])
    --a1, --b1;
  if (a0 == a1 || b0 == b1) {
    mark_all(w.a_changed, a_index, a0, a1);
    mark_all(w.b_changed, b_index, b0, b1);
    return;
  }
  const Search s{w, static_cast<std::ptrdiff_t>(a0), static_cast<std::ptrdiff_t>(a1 - a0),
                 static_cast<std::ptrdiff_t>(b0), static_cast<std::ptrdiff_t>(b1 - b0)};
  const std::optional<Point> p = s.middle();
  // A split that leaves one half the whole would never end: all changed then.
  if (!p || (p->x == 0 && p->y == 0) || (p->x == s.n && p->y == s.m)) {
    mark_all(w.a_changed, a_index, a0, a1);
    mark_all(w.b_changed, b_index, b0, b1);
    return;
  }
  const std::size_t ax = a0 + static_cast<std::size_t>(p->x);
  const std::size_t by = b0 + static_cast<std::size_t>(p->y);
  compare(w, a_index, b_index, a0, ax, b0, by);
  compare(w, a_index, b_index, ax, a1, by, b1);
}

// Keeps the lines of `seq` that occur in `other`; the rest are changed.
std::vector<Id> keep_shared(std::span<const Id> seq, std::span<const Id> other, Id ids,
                            std::vector<char>& changed, std::vector<std::size_t>& index) {
  std::vector<char> present(ids, 0);
  for (const Id id : other)
    present[id] = 1;
  std::vector<Id> kept;
  for (std::size_t i = 0; i < seq.size(); ++i) {
    if (present[seq[i]] != 0) {
      kept.push_back(seq[i]);
      index.push_back(i);
    } else {
      changed[i] = 1;
    }
  }
  return kept;
}

LineDiff script(const std::vector<char>& a_changed, const std::vector<char>& b_changed) {
  LineDiff out;
  std::size_t i = 0;
  std::size_t j = 0;
  const auto push = [&out](EditKind kind, std::size_t a, std::size_t b, std::size_t count) {
    if (count == 0) return;
    if (!out.edits.empty() && out.edits.back().kind == kind) {
      out.edits.back().count += count;
    } else {
      out.edits.push_back({kind, a, b, count});
    }
  };
  while (i < a_changed.size() || j < b_changed.size()) {
    std::size_t n = 0;
    while (i + n < a_changed.size() && a_changed[i + n] != 0)
      ++n;
    push(EditKind::Delete, i, j, n);
    out.deleted += n, i += n;
    n = 0;
    while (j + n < b_changed.size() && b_changed[j + n] != 0)
      ++n;
    push(EditKind::Insert, i, j, n);
    out.inserted += n, j += n;
    n = 0;
    while (i + n < a_changed.size() && j + n < b_changed.size() && a_changed[i + n] == 0 &&
           b_changed[j + n] == 0)
      ++n;
    push(EditKind::Equal, i, j, n);
    i += n, j += n;
  }
  return out;
}

}  // namespace

LineDiff diff_ids(std::span<const Id> a, std::span<const Id> b) {
  std::vector<char> a_changed(a.size(), 0);
  std::vector<char> b_changed(b.size(), 0);
  Id ids = 0;
  for (const Id id : a)
    ids = std::max(ids, id + 1);
  for (const Id id : b)
    ids = std::max(ids, id + 1);
  std::vector<std::size_t> a_index;
  std::vector<std::size_t> b_index;
  const std::vector<Id> a_kept = keep_shared(a, b, ids, a_changed, a_index);
  const std::vector<Id> b_kept = keep_shared(b, a, ids, b_changed, b_index);
  Work w{a_kept, b_kept, a_changed, b_changed, {}, {}};
  compare(w, a_index, b_index, 0, a_kept.size(), 0, b_kept.size());
  return script(a_changed, b_changed);
}

LineDiff diff_lines(std::span<const std::string_view> a, std::span<const std::string_view> b) {
  std::unordered_map<std::string_view, Id> ids;
  ids.reserve(a.size() + b.size());
  const auto intern = [&ids](std::span<const std::string_view> lines) {
    std::vector<Id> out;
    out.reserve(lines.size());
    for (const std::string_view l : lines)
      out.push_back(ids.try_emplace(l, static_cast<Id>(ids.size())).first->second);
    return out;
  };
  const std::vector<Id> a_ids = intern(a);
  const std::vector<Id> b_ids = intern(b);
  return diff_ids(a_ids, b_ids);
}

}  // namespace usina::dnc
