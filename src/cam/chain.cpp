#include "cam/chain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace usina::cam {
namespace {

// The entity ends in a grid of cells one tolerance wide, so the ends within
// the tolerance of a point are in its cell or the eight around it: chaining
// 10,000 entities is then linear, not quadratic.
class EndIndex {
 public:
  EndIndex(const std::vector<Path>& entities, double tolerance)
      : cell_(std::max(tolerance, 1e-9)), tolerance_(tolerance) {
    for (std::size_t i = 0; i < entities.size(); ++i) {
      add(entities[i].start, i, false);
      add(end_point(entities[i]), i, true);
    }
  }

  struct Match {
    std::size_t entity = std::numeric_limits<std::size_t>::max();
    bool at_end = false;

    bool found() const { return entity != std::numeric_limits<std::size_t>::max(); }
  };

  // The first unused entity (in drawing order) with an end within the
  // tolerance of `p`; its start wins over its end.
  Match nearest(Vec2 p, const std::vector<Path>& entities, const std::vector<bool>& used) const {
    Match best;
    const auto [cx, cy] = cell_of(p);
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find(key(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (const End& e : it->second)
          consider(e, p, entities, used, best);
      }
    }
    return best;
  }

 private:
  struct End {
    std::size_t entity;
    bool at_end;
  };

  // Takes `e` as the best match when it is nearer in drawing order.
  void consider(const End& e, Vec2 p, const std::vector<Path>& entities,
                const std::vector<bool>& used, Match& best) const {
    if (used[e.entity] || e.entity > best.entity) return;
    const Vec2 q = e.at_end ? end_point(entities[e.entity]) : entities[e.entity].start;
    if (core::distance(p, q) > tolerance_) return;
    if (e.entity < best.entity || (!e.at_end && best.at_end)) best = {e.entity, e.at_end};
  }

  std::pair<std::int64_t, std::int64_t> cell_of(Vec2 p) const {
    // Clamped so a huge or non-finite coordinate still has a cell.
    auto index = [&](double v) {
      const double c = std::floor(v / cell_);
      if (!(c > -1e15)) return std::int64_t{-1'000'000'000'000'000};
      if (c > 1e15) return std::int64_t{1'000'000'000'000'000};
      return static_cast<std::int64_t>(c);
    };
    return {index(p.x), index(p.y)};
  }

  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    return static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint64_t>(y);
  }

  void add(Vec2 p, std::size_t entity, bool at_end) {
    const auto [cx, cy] = cell_of(p);
    cells_[key(cx, cy)].push_back({entity, at_end});
  }

  double cell_;
  double tolerance_;
  std::unordered_map<std::uint64_t, std::vector<End>> cells_;
};

void append(Path& path, const Path& e) {
  path.segs.insert(path.segs.end(), e.segs.begin(), e.segs.end());
}

void prepend(Path& path, Path e) {
  e.segs.back().to = path.start;  // the joined point is the path's own
  e.segs.insert(e.segs.end(), path.segs.begin(), path.segs.end());
  path.start = e.start;
  path.segs = std::move(e.segs);
}

}  // namespace

std::vector<Path> chain(std::vector<Path> entities, double tolerance) {
  std::vector<bool> used(entities.size(), false);
  for (std::size_t i = 0; i < entities.size(); ++i) {
    if (entities[i].segs.empty() || entities[i].closed) used[i] = true;
  }
  const EndIndex index(entities, tolerance);
  std::vector<Path> paths;
  for (std::size_t i = 0; i < entities.size(); ++i) {
    if (entities[i].closed && !entities[i].segs.empty()) paths.push_back(entities[i]);
    if (used[i]) continue;
    used[i] = true;
    Path path = entities[i];
    for (auto m = index.nearest(end_point(path), entities, used); m.found();
         m = index.nearest(end_point(path), entities, used)) {
      used[m.entity] = true;
      append(path, m.at_end ? reversed(entities[m.entity]) : entities[m.entity]);
    }
    for (auto m = index.nearest(path.start, entities, used); m.found();
         m = index.nearest(path.start, entities, used)) {
      used[m.entity] = true;
      prepend(path, m.at_end ? entities[m.entity] : reversed(entities[m.entity]));
    }
    if (core::distance(path.start, end_point(path)) <= tolerance) {
      path.segs.back().to = path.start;
      path.closed = true;
    }
    paths.push_back(std::move(path));
  }
  return paths;
}

}  // namespace usina::cam
