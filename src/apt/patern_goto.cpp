// GOTO/pattern's modifiers (docs/apt.md, "Patterns"; the APT360 manual
// §4.6): which points are visited, in which order, over which rise. The work is the pattern's size
// plus the lists', never their product (a hostile list of ranges stays
// linear).
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "apt/patern.hpp"

namespace usina::apt {
namespace {

tl::unexpected<GeomError> bad(std::string message) {
  return tl::make_unexpected(GeomError{core::Code::AptBadArgument, std::move(message)});
}

bool is_word(const Arg& a, std::string_view w) {
  return a.kind == Arg::Kind::Word && a.word == w;
}

using Range = std::pair<std::size_t, std::size_t>;  // first, last (from 0)

// i[,THRU,j],... from a[k] on, while numbers come: the ranges of the points
// named (numbered from 1 in `n`); k ends past them.
tl::expected<std::vector<Range>, GeomError> point_list(const std::vector<Arg>& a, std::size_t& k,
                                                       std::size_t n, const std::string& what) {
  const auto number = [&](const Arg& x) -> tl::expected<std::size_t, GeomError> {
    if (x.kind != Arg::Kind::Number || !(x.num >= 1) || x.num > static_cast<double>(n) ||
        x.num != std::floor(x.num))
      return bad("GOTO/pattern," + what + ": a point's number is whole, 1 to " + std::to_string(n));
    return static_cast<std::size_t>(x.num) - 1;
  };
  std::vector<Range> out;
  while (k < a.size() && a[k].kind == Arg::Kind::Number) {
    const auto from = number(a[k++]);
    if (!from) return tl::make_unexpected(from.error());
    std::size_t to = *from;
    if (k < a.size() && is_word(a[k], "THRU")) {
      if (++k == a.size()) return bad("GOTO/pattern," + what + ": THRU takes a point's number");
      const auto last = number(a[k++]);
      if (!last) return tl::make_unexpected(last.error());
      to = *last;
    }
    out.push_back({std::min(*from, to), std::max(*from, to)});
  }
  if (out.empty()) return bad("GOTO/pattern," + what + " takes the numbers of points");
  return out;
}

// Adds 1 to `hits` over the union of `ranges` (through a difference array:
// the work is the pattern's size plus the ranges', never their product).
void count_once(std::vector<Range> ranges, std::vector<int>& delta) {
  std::sort(ranges.begin(), ranges.end());
  std::size_t i = 0;
  while (i < ranges.size()) {
    Range r = ranges[i++];
    while (i < ranges.size() && ranges[i].first <= r.second + 1)
      r.second = std::max(r.second, ranges[i++].second);
    ++delta[r.first];
    --delta[r.second + 1];
  }
}

struct Modifiers {
  bool invers = false;
  bool constant = false;          // CONST: the numbers are the definition's, not the output's
  std::vector<int> omit, retain;  // difference arrays of the points named
  int retains = 0;                // RETAIN groups
  std::vector<std::pair<Range, double>> avoid;
};

tl::expected<Modifiers, GeomError> read_modifiers(const std::vector<Arg>& mods, std::size_t n) {
  Modifiers m;
  m.omit.assign(n + 1, 0);
  m.retain.assign(n + 1, 0);
  // INVERS and CONST say how every list's numbers read, wherever they stand.
  for (const Arg& a : mods) {
    m.invers = m.invers || is_word(a, "INVERS");
    m.constant = m.constant || is_word(a, "CONST");
  }
  for (std::size_t k = 0; k < mods.size();) {
    const std::string w = mods[k].kind == Arg::Kind::Word ? mods[k].word : std::string();
    ++k;
    if (w == "INVERS" || w == "CONST") continue;
    double rise = 0.0;
    if (w == "AVOID") {
      if (k == mods.size() || mods[k].kind != Arg::Kind::Number || !(mods[k].num > 0))
        return bad("GOTO/pattern,AVOID takes the rise (more than 0), then the points' numbers");
      rise = mods[k++].num;
    }
    if (w != "OMIT" && w != "RETAIN" && w != "AVOID")
      return bad("GOTO/pattern takes INVERS, CONST, OMIT, RETAIN and AVOID after the pattern" +
                 std::string(w.empty() ? " (a feed rate is a FEDRAT statement of its own)"
                                       : ", not " + w));
    auto ranges = point_list(mods, k, n, w);
    if (!ranges) return tl::make_unexpected(ranges.error());
    // The manual's numbers follow the output order (INVERS: 1 is the last
    // point defined) unless CONST says the definition's.
    if (m.invers && !m.constant)
      for (Range& r : *ranges)
        r = {n - 1 - r.second, n - 1 - r.first};
    if (w == "OMIT") count_once(std::move(*ranges), m.omit);
    if (w == "RETAIN") {
      count_once(std::move(*ranges), m.retain);
      ++m.retains;
    }
    for (const Range& r : w == "AVOID" ? *ranges : std::vector<Range>{})
      m.avoid.push_back({r, rise});
  }
  return m;
}

// The rise of each point: the largest AVOID naming it (a sweep over the
// ranges' ends).
std::vector<double> rises(std::vector<std::pair<Range, double>> avoid, std::size_t n) {
  std::vector<double> out(n, 0.0);
  std::sort(avoid.begin(), avoid.end());
  std::multiset<std::pair<std::size_t, double>> open;  // (last, rise)
  std::multiset<double> heights;
  std::size_t next = 0;
  for (std::size_t i = 0; i < n; ++i) {
    while (next < avoid.size() && avoid[next].first.first == i) {
      open.insert({avoid[next].first.second, avoid[next].second});
      heights.insert(avoid[next].second);
      ++next;
    }
    while (!open.empty() && open.begin()->first < i) {
      heights.erase(heights.find(open.begin()->second));
      open.erase(open.begin());
    }
    if (!heights.empty()) out[i] = *heights.rbegin();
  }
  return out;
}

}  // namespace

tl::expected<std::vector<PatternVisit>, GeomError> pattern_visits(const Geom& pattern,
                                                                  const std::vector<Arg>& mods) {
  const std::size_t n = pattern.points.size();
  auto m = read_modifiers(mods, n);
  if (!m) return tl::make_unexpected(m.error());
  const std::vector<double> rise = rises(std::move(m->avoid), n);
  std::vector<bool> keep(n);
  int omitted = 0, retained = 0;
  for (std::size_t i = 0; i < n; ++i) {
    omitted += m->omit[i];
    retained += m->retain[i];
    keep[i] = omitted == 0 && retained == m->retains;  // each OMIT and RETAIN narrows
  }
  std::vector<PatternVisit> out;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = m->invers ? n - 1 - k : k;
    if (keep[i]) out.push_back({pattern.points[i], rise[i]});
  }
  if (out.empty()) return bad("GOTO/pattern: OMIT and RETAIN leave no point to go to");
  return out;
}

}  // namespace usina::apt
