#include "canon/bare_hole.hpp"

#include <algorithm>

namespace usina::canon {

std::vector<Op> bare_hole_moves(const Op& hole, const Hole& h, const Vec3& from, const Abc& abc,
                                const Feed& feed) {
  std::vector<Op> moves;
  if (hole.origin != Origin::Program || !(h.depth > 0.0)) return moves;
  const double r = h.at.z;
  const double clear = std::max(from.z, r);
  const auto rapid = [&](Vec3 to) {
    moves.push_back({Traverse{to, abc}, hole.src, Origin::Cycle});
  };
  if (from.z < r) rapid({from.x, from.y, r});
  rapid({h.at.x, h.at.y, clear});
  if (clear > r) rapid({h.at.x, h.at.y, r});
  Feed down = feed;
  down.to = {h.at.x, h.at.y, r - h.depth};
  down.abc = abc;
  moves.push_back({down, hole.src, Origin::Cycle});
  if (h.cycle == HoleCycle::Bore) {
    // G85: fed back out to R, then (G98) up to where it started.
    Feed out = down;
    out.to.z = r;
    moves.push_back({out, hole.src, Origin::Cycle});
  }
  rapid({h.at.x, h.at.y, clear});
  return moves;
}

}  // namespace usina::canon
