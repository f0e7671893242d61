#include "canon/bare_hole.hpp"

#include <algorithm>

namespace usina::canon {

std::vector<Op> bare_hole_moves(const Op& hole, const Hole& h, const Vec3& from, const Abc& abc,
                                const Feed& feed, const Spindle& spindle) {
  std::vector<Op> moves;
  if (hole.origin != Origin::Program || !(h.depth > 0.0)) return moves;
  const double r = h.at.z;
  const double clear = std::max(from.z, r);
  const auto add = [&](OpKind k) { moves.push_back({std::move(k), hole.src, Origin::Cycle}); };
  const auto rapid = [&](Vec3 to) { add(Traverse{to, abc}); };
  if (from.z < r) rapid({from.x, from.y, r});
  rapid({h.at.x, h.at.y, clear});
  if (clear > r) rapid({h.at.x, h.at.y, r});
  Feed down = feed;
  if (h.f) down = Feed{{}, h.f};  // the hole's own rate, per minute
  down.to = {h.at.x, h.at.y, r - h.depth};
  down.abc = abc;
  add(down);
  Feed out = down;
  out.to.z = r;
  switch (h.cycle) {
  case HoleCycle::BoreDwell:  // G89: the dwell, then fed out as G85
    add(Dwell{h.dwell});
    add(out);
    break;
  case HoleCycle::Bore: add(out); break;  // G85: fed back out to R
  case HoleCycle::BoreStop:
    // G86: out at rapid with the spindle stopped, started again above.
    add(Spindle{0.0, SpindleDir::Off});
    rapid({h.at.x, h.at.y, clear});
    if (spindle.dir != SpindleDir::Off) add(spindle);
    return moves;
  case HoleCycle::Drill: break;
  }
  rapid({h.at.x, h.at.y, clear});  // then (G98) up to where it started
  return moves;
}

}  // namespace usina::canon
