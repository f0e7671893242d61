// Holes. The interpreter emits a Hole feature together with the moves of
// the cycle that drilled it, all with Origin::Cycle: those moves are written
// as plain blocks (a conversion expands cycles) and the feature adds nothing.
// A Hole with Origin::Program is a bare feature from a generator: the post
// drills it, as G81 (G83 with a peck) where the control has canned cycles,
// else as the moves LinuxCNC's G81/G83 would make. Either way the hole is
// drilled from its top (the R plane) to top − depth at the last feed rate,
// and the tool returns to where it was, or to R if that was lower (G98).
// A bored hole (HoleCycle::Bore) is G85 where the control has cycles: fed
// in and fed back out to R at that rate, then up as a drilled one; never
// pecked.
#include <algorithm>

#include <fmt/format.h>

#include "post/writer.hpp"

namespace usina::post {

void Writer::hole(const canon::Hole& h, const canon::Op& op) {
  if (op.origin == canon::Origin::Cycle) return;
  if (!pos_known_) return unsupported(op, "a hole before the first positioning move");
  if (!last_feed_) return unsupported(op, "a hole before any feed rate is known");
  if (h.depth <= 0) return unsupported(op, "a hole of no depth");
  if (control_.canned_cycles) {
    cycle_hole(h);
  } else {
    expanded_hole(h);
  }
}

void Writer::cycle_hole(const canon::Hole& h) {
  const bool bore = h.cycle == canon::HoleCycle::Bore;
  const bool peck = !bore && options_.peck > 0;
  const std::string& g = bore ? g85_ : peck ? g83_ : g81_;
  if (motion_ != g) {
    // Another cycle: its Z and R are written again rather than trusted to
    // carry over from the last one.
    cycle_z_.reset();
    cycle_r_.reset();
  }
  std::string w = motion_word(g.c_str());
  const double r = out_.rounded(h.at.z);
  const double bottom = out_.rounded(h.at.z - h.depth);
  append(w, fmt::format("X{} Y{}", out_.number(h.at.x), out_.number(h.at.y)));
  if (cycle_z_ != bottom) append(w, "Z" + out_.number(bottom));
  if (cycle_r_ != r) append(w, "R" + out_.number(r));
  if (peck && cycle_q_ != out_.rounded(options_.peck)) append(w, "Q" + out_.number(options_.peck));
  append(w, feed_word(last_feed_, canon::Op{}));
  cycle_z_ = bottom;
  cycle_r_ = r;
  if (peck) cycle_q_ = out_.rounded(options_.peck);
  out_.block(w);
  const double clear = std::max(pos_.z, h.at.z);
  pos_ = {h.at.x, h.at.y, clear};
  axes_[0] = out_.rounded(h.at.x);
  axes_[1] = out_.rounded(h.at.y);
  axes_[2] = out_.rounded(clear);
}

void Writer::expanded_hole(const canon::Hole& h) {
  const canon::Op none;
  const double r = h.at.z;
  const double bottom = h.at.z - h.depth;
  const double clear = std::max(pos_.z, r);
  auto rapid = [&](double x, double y, double z) { traverse(canon::Traverse{{x, y, z}}, none); };
  auto down = [&](double z) { feed({h.at.x, h.at.y, z}, last_feed_, canon::Abc{}, none); };
  if (pos_.z < r) rapid(pos_.x, pos_.y, r);
  rapid(h.at.x, h.at.y, clear);
  rapid(h.at.x, h.at.y, r);
  const bool bore = h.cycle == canon::HoleCycle::Bore;
  if (!bore && options_.peck > 0) {
    // G83: out to R after each peck, rapid back to just above the last one.
    for (double d = r - options_.peck; d > bottom; d -= options_.peck) {
      down(d);
      rapid(h.at.x, h.at.y, r);
      rapid(h.at.x, h.at.y, d + options_.peck_clearance);
    }
  }
  down(bottom);
  if (bore) down(r);  // G85: fed back out to R
  rapid(h.at.x, h.at.y, clear);
}

}  // namespace usina::post
