// The holes of the canon stream as CL: a plain drilling (down at feed to
// the bottom, out at rapid, as G81 does) is CYCLE/DRILL and the GOTO of the
// hole's top; any other hole (pecked, dwelt, bored, tapped) is its moves.
#include <cmath>

#include "apt/cl_from_canon.hpp"
#include "apt/vocabulary.hpp"

namespace usina::apt {
namespace {

constexpr int kMmpm = minor_code("MMPM"), kDrill = minor_code("DRILL"), kCycle = post_code("CYCLE");
constexpr double kSame = 1e-9;

bool same(const canon::Vec3& a, const canon::Vec3& b) {
  return std::fabs(a.x - b.x) <= kSame && std::fabs(a.y - b.y) <= kSame &&
         std::fabs(a.z - b.z) <= kSame;
}

// Over the hole's top, at or above it.
bool over(const canon::Vec3& p, const canon::Vec3& top) {
  return std::fabs(p.x - top.x) <= kSame && std::fabs(p.y - top.y) <= kSame && p.z >= top.z - kSame;
}

}  // namespace

// The hole comes after the moves over it and before those that drill it:
// the traverse to where it is drilled from (the interpreter's R plane, the
// hole's top; romi's clearance above the top) is taken back (CYCLE/DRILL's
// GOTO makes it) and the moves after it held until they show what they are.
void CanonToCl::hole(const canon::Op& op) {
  PendingHole p{std::get<canon::Hole>(op.kind), op.src, {}, {}};
  if (last_traverse_ && at_ && over(*at_, p.hole.at)) {
    p.approach = last_traverse_->op;
    records_.resize(last_traverse_->first);
    at_ = last_traverse_->from;
  }
  last_traverse_.reset();
  pending_ = std::move(p);
}

void CanonToCl::hold(const canon::Op& op) {
  pending_->held.push_back(op);
  const std::vector<canon::Op>& held = pending_->held;
  if (held.size() == 1 &&
      (!std::holds_alternative<canon::Feed>(op.kind) || op.origin != canon::Origin::Cycle)) {
    release();
    return;
  }
  if (held.size() < 2) return;
  if (!drilled(*pending_)) {
    release();
    return;
  }
  const PendingHole h = std::move(*pending_);
  pending_.reset();
  write_drilled(h);
}

bool CanonToCl::drilled(const PendingHole& h) const {
  const auto* down = std::get_if<canon::Feed>(&h.held[0].kind);
  const auto* out = std::get_if<canon::Traverse>(&h.held[1].kind);
  const canon::Vec3 top = h.hole.at;
  return h.approach && down && out && h.held[1].origin == canon::Origin::Cycle &&
         h.hole.cycle == canon::HoleCycle::Drill && h.hole.depth > 0.0 && down->f &&
         down->programmed.mode == canon::ProgrammedFeed::Mode::PerMinute &&
         same(down->to, {top.x, top.y, top.z - h.hole.depth}) && over(out->to, top);
}

// CYCLE/DRILL,depth,MMPM,feed,clearance[,retract]: the GOTO is the hole's
// top, the clearance the approach's height above it, `retract` where the
// tool leaves to when not the clearance (G98's initial level); kept open
// while the holes after it drill alike.
void CanonToCl::write_drilled(const PendingHole& h) {
  const canon::Vec3 top = h.hole.at;
  const canon::Vec3 out = std::get<canon::Traverse>(h.held[1].kind).to;
  const double clearance = std::get<canon::Traverse>(h.approach->kind).to.z - top.z;
  const Cycle c{h.hole.depth, *std::get<canon::Feed>(h.held[0].kind).f, clearance, out.z - top.z};
  if (cycle_ && (cycle_->depth != c.depth || cycle_->feed != c.feed ||
                 cycle_->clearance != c.clearance || cycle_->retract != c.retract))
    cycle_off(h.src);
  if (!cycle_) {
    std::vector<ClWord> words{ClWord::vocabulary(kDrill), ClWord::number(c.depth),
                              ClWord::vocabulary(kMmpm), ClWord::number(c.feed),
                              ClWord::number(c.clearance)};
    if (std::fabs(c.retract - c.clearance) > kSame) words.push_back(ClWord::number(c.retract));
    statement(h.src);
    add(cls::kPost, kCycle, std::move(words), h.src);
    cycle_ = c;
    feed_ = c.feed;  // ClToCanon's feed after the cycle
    per_rev_ = false;
  }
  statement(h.src);
  goto_point(top, h.src);
  at_ = out;
}

// Not a plain drilling: its moves as they came, the hole itself lost.
void CanonToCl::release() {
  if (!pending_) return;
  const PendingHole h = std::move(*pending_);
  pending_.reset();
  if (h.approach) write(*h.approach);
  for (const canon::Op& op : h.held)
    on(op);
}

}  // namespace usina::apt
