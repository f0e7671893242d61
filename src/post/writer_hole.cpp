// Holes. The interpreter emits a Hole feature together with the moves of
// the cycle that drilled it, all with Origin::Cycle: those moves are written
// as plain blocks (a conversion expands cycles) and the feature adds nothing.
// A Hole with Origin::Program is a bare feature from a generator: the post
// drills it, as G81 (G83 with a peck) where the control has canned cycles,
// else as the moves LinuxCNC's G81/G83 would make. Either way the hole is
// drilled from its top (the R plane) to top − depth at the hole's feed rate
// (a generator's holes carry theirs; else the last feed move's), and the
// tool returns to where it was, or to R if that was lower (G98).
// Bored holes are never pecked:
// - HoleCycle::Bore is G85 where the control has cycles: fed in and fed back
//   out to R at that rate, then up as a drilled one;
// - HoleCycle::BoreDwell is G89, the same with a dwell at the bottom. A
//   LinuxCNC G89 feeds out to the clear level (in G98 the level it came
//   from: a slow second feed up to the safe Z), a Fanuc's to R: in G99 both
//   stop at R, and the post rapids up from there;
// - HoleCycle::BoreStop is G86: the spindle stopped at the bottom, out at
//   rapid to where it came from, the spindle started again.
// grbl and romi get the moves of each (romi no G89: it has no dwell but
// G81's).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "post/writer.hpp"

namespace usina::post {

void Writer::hole(const canon::Hole& h, const canon::Op& op) {
  if (op.origin == canon::Origin::Cycle) return;
  if (!pos_known_) return unsupported(op, "a hole before the first positioning move");
  const std::optional<double> f = h.f ? h.f : last_feed_;
  if (!f) return unsupported(op, "a hole before any feed rate is known");
  if (h.depth <= 0) return unsupported(op, "a hole of no depth");
  if (h.cycle == canon::HoleCycle::BoreStop && dir_ == canon::SpindleDir::Off)
    return unsupported(op, "a bore that stops the spindle (G86) with the spindle stopped");
  if (h.cycle == canon::HoleCycle::BoreDwell && !control_.canned_cycles &&
      !control_.standalone_dwell)
    return unsupported(op,
                       "a bore's dwell at the bottom (G89): its only dwell is G81's, which "
                       "rapids out of the hole");
  if (control_.canned_cycles) {
    cycle_hole(h, f);
  } else {
    expanded_hole(h, f);
  }
}

const std::string& Writer::cycle_code(const canon::Hole& h) const {
  switch (h.cycle) {
  case canon::HoleCycle::Bore: return g85_;
  case canon::HoleCycle::BoreDwell: return g89_;
  case canon::HoleCycle::BoreStop: return g86_;
  case canon::HoleCycle::Drill: break;
  }
  return options_.peck > 0 ? g83_ : g81_;
}

// G89's P (the dwell) in every block, since each G89 starts its cycle again
// (the rapid up ends it); G86's P0 where the control wants a P.
std::string Writer::cycle_dwell_word(const canon::Hole& h) const {
  if (h.cycle == canon::HoleCycle::BoreStop) return control_.cycle_dwell_ms ? "" : "P0";
  if (h.cycle != canon::HoleCycle::BoreDwell) return {};
  if (control_.cycle_dwell_ms) return fmt::format("P{}", std::lround(h.dwell * 1000.0));
  return "P" + out_.number(h.dwell);
}

void Writer::cycle_hole(const canon::Hole& h, std::optional<double> f) {
  const std::string& g = cycle_code(h);
  const bool peck = &g == &g83_;
  const bool dwells = h.cycle == canon::HoleCycle::BoreDwell;
  if (motion_ != g) {
    // Another cycle: its Z and R are written again rather than trusted to
    // carry over from the last one.
    cycle_z_.reset();
    cycle_r_.reset();
  }
  const int retract = dwells ? 99 : 98;
  std::string w = retract_mode_ != retract ? code('G', retract) : std::string();
  retract_mode_ = retract;
  append(w, motion_word(g.c_str()));
  const double r = out_.rounded(h.at.z);
  const double bottom = out_.rounded(h.at.z - h.depth);
  append(w, fmt::format("X{} Y{}", out_.number(h.at.x), out_.number(h.at.y)));
  if (cycle_z_ != bottom) append(w, "Z" + out_.number(bottom));
  if (cycle_r_ != r) append(w, "R" + out_.number(r));
  if (peck && cycle_q_ != out_.rounded(options_.peck)) append(w, "Q" + out_.number(options_.peck));
  append(w, cycle_dwell_word(h));
  append(w, feed_word(f, canon::Op{}));
  cycle_z_ = bottom;
  cycle_r_ = r;
  if (peck) cycle_q_ = out_.rounded(options_.peck);
  out_.block(w);
  const double clear = std::max(pos_.z, h.at.z);
  pos_ = {h.at.x, h.at.y, dwells ? h.at.z : clear};
  axes_[0] = out_.rounded(h.at.x);
  axes_[1] = out_.rounded(h.at.y);
  axes_[2] = out_.rounded(pos_.z);
  // G99 left the tool at R: up to where it came from, as G98 would.
  if (dwells && clear > h.at.z) traverse(canon::Traverse{{h.at.x, h.at.y, clear}}, canon::Op{});
}

void Writer::expanded_hole(const canon::Hole& h, std::optional<double> f) {
  const canon::Op none;
  const double r = h.at.z;
  const double bottom = h.at.z - h.depth;
  const double clear = std::max(pos_.z, r);
  auto rapid = [&](double x, double y, double z) { traverse(canon::Traverse{{x, y, z}}, none); };
  auto down = [&](double z) { feed({h.at.x, h.at.y, z}, f, canon::Abc{}, none); };
  if (pos_.z < r) rapid(pos_.x, pos_.y, r);
  rapid(h.at.x, h.at.y, clear);
  rapid(h.at.x, h.at.y, r);
  if (h.cycle == canon::HoleCycle::Drill && options_.peck > 0) {
    // G83: out to R after each peck, rapid back to just above the last one.
    for (double d = r - options_.peck; d > bottom; d -= options_.peck) {
      down(d);
      rapid(h.at.x, h.at.y, r);
      rapid(h.at.x, h.at.y, d + options_.peck_clearance);
    }
  }
  down(bottom);
  switch (h.cycle) {
  case canon::HoleCycle::BoreStop: return expanded_bore_stop(h, clear);
  case canon::HoleCycle::BoreDwell:
    dwell(h.dwell);
    down(r);  // G89: fed back out to R after the dwell
    break;
  case canon::HoleCycle::Bore: down(r); break;  // G85: fed back out to R
  case canon::HoleCycle::Drill: break;
  }
  rapid(h.at.x, h.at.y, clear);
}

// G86's moves: the spindle stopped at the bottom, out at rapid to the clear
// level, started again as it was.
void Writer::expanded_bore_stop(const canon::Hole& h, double clear) {
  const canon::Spindle running{speed_ ? static_cast<double>(*speed_) : 0.0, dir_};
  spindle(canon::Spindle{0.0, canon::SpindleDir::Off});
  traverse(canon::Traverse{{h.at.x, h.at.y, clear}}, canon::Op{});
  spindle(running);
}

}  // namespace usina::post
