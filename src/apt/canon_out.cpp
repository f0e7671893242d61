#include "apt/canon_out.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "apt/vocabulary.hpp"

namespace usina::apt {
namespace {

constexpr int kClw = minor_code("CLW"), kCclw = minor_code("CCLW"), kOn = minor_code("ON"),
              kOff = minor_code("OFF"), kFlood = minor_code("FLOOD"), kMist = minor_code("MIST"),
              kIpr = minor_code("IPR"), kMmpr = minor_code("MMPR"), kDrill = minor_code("DRILL");

std::string fmt_number(double v) {
  return fmt::format("{}", v);
}

bool has_code(const ClRecord& r, int code) {
  for (const ClWord& w : r.words)
    if (w.kind == ClWord::Kind::Code && w.code == code) return true;
  return false;
}

std::optional<double> first_number(const ClRecord& r) {
  for (const ClWord& w : r.words)
    if (w.kind == ClWord::Kind::Real) return w.real;
  return std::nullopt;
}

// LOADTL's number as a tool number: a number no tool has (beyond 10^9, not
// finite: a binary file's) is tool 0, never an int out of range.
int tool_number(const ClRecord& r) {
  const double n = first_number(r).value_or(0.0);
  return std::isfinite(n) && std::fabs(n) < 1e9 ? static_cast<int>(n) : 0;
}

std::string trimmed(std::string t) {
  while (!t.empty() && t.back() == ' ')
    t.pop_back();
  while (!t.empty() && t.front() == ' ')
    t.erase(t.begin());
  return t;
}

std::string text_of(const ClRecord& r) {
  std::string t;
  for (const ClWord& w : r.words)
    t += w.text;
  return trimmed(std::move(t));
}

}  // namespace

void ClToCanon::record(const ClRecord& r) {
  if (r.cls == cls::kSource && rapid_used_) rapid_ = rapid_used_ = false;
  if (r.cls == cls::kPost) post(r);
  if (r.cls == cls::kSurface) surface(r);
  if (r.cls == cls::kMotion) motion(r);
  if (r.cls == cls::kControl && r.sub == 6 && !r.words.empty())
    diameter_ = r.words[0].real * scale_;
}

void ClToCanon::post(const ClRecord& r) {
  switch (r.sub) {
  case post_code("END"): emit(canon::ProgramEnd{}, r); return;
  case post_code("STOP"): emit(canon::MachineCode{'M', 0, {}, {}}, r); return;
  case post_code("OPSTOP"): emit(canon::MachineCode{'M', 1, {}, {}}, r); return;
  case post_code("RAPID"): rapid_ = true; return;
  case post_code("FEDRAT"): {
    const double f = first_number(r).value_or(0.0);
    if (has_code(r, kIpr) || has_code(r, kMmpr)) {
      per_rev_ = canon::ProgrammedFeed{canon::ProgrammedFeed::Mode::PerRevolution, f * scale_};
      feed_.reset();
    } else {
      feed_ = f * scale_;
      per_rev_.reset();
    }
    return;
  }
  case post_code("DELAY"): emit(canon::Dwell{first_number(r).value_or(0.0)}, r); return;
  case post_code("COOLNT"):
    emit(canon::Coolant{has_code(r, kMist), has_code(r, kOn) || has_code(r, kFlood)}, r);
    return;
  case post_code("SPINDL"): spindle(r); return;
  case post_code("CYCLE"): cycle(r); return;
  case post_code("LOADTL"): emit(canon::ToolChange{tool_number(r), diameter_}, r); return;
  default: post_motion_words(r);
  }
}

// The words that reach the stream as text: PARTNO, PPRINT, INSERT, and a
// post word the canon stream has no op for (MACHIN/..., SEQNO/...).
void ClToCanon::post_motion_words(const ClRecord& r) {
  if (r.sub == post_code("PPRINT") || r.sub == post_code("PARTNO") ||
      r.sub == post_code("INSERT")) {
    emit(canon::Comment{text_of(r)}, r);
    return;
  }
  std::string words;
  for (const ClWord& w : r.words) {
    words += words.empty() ? "/" : ",";
    if (w.kind == ClWord::Kind::Real) words += fmt_number(w.real);
    if (w.kind == ClWord::Kind::Code) words += std::string(minor_word_name(w.code));
    if (w.kind == ClWord::Kind::Text) words += trimmed(w.text);
  }
  emit(canon::Comment{"APT " + std::string(post_word_name(r.sub)) + words}, r);
}

void ClToCanon::spindle(const ClRecord& r) {
  if (const auto rpm = first_number(r)) spindle_.rpm = *rpm;
  if (has_code(r, kOff)) {
    emit(canon::Spindle{spindle_.rpm, canon::SpindleDir::Off}, r);
    return;
  }
  if (has_code(r, kCclw)) {
    spindle_.dir = canon::SpindleDir::Ccw;
  } else if (has_code(r, kClw) || spindle_.dir == canon::SpindleDir::Off) {
    spindle_.dir = canon::SpindleDir::Cw;  // CLW, or ON after OFF
  }
  emit(spindle_, r);
}

void ClToCanon::cycle(const ClRecord& r) {
  if (has_code(r, kOff)) {
    cycle_ = false;
    return;
  }
  // CYCLE/DRILL,depth,IPM|MMPM,feed,clearance[,retract] (the numbers in that order).
  std::vector<double> nums;
  for (const ClWord& w : r.words)
    if (w.kind == ClWord::Kind::Real) nums.push_back(w.real);
  cycle_ = has_code(r, kDrill) && nums.size() >= 3;
  if (!cycle_) {
    post_motion_words(r);
    return;
  }
  depth_ = nums[0] * scale_;
  feed_ = nums[1] * scale_;
  clearance_ = nums[2] * scale_;
  // A fourth number (usina's, docs/apt.md): the height above the point the
  // tool leaves the hole to, when not the clearance (G98's initial level).
  retract_ = nums.size() >= 4 ? nums[3] * scale_ : clearance_;
}

void ClToCanon::surface(const ClRecord& r) {
  arc_.reset();
  segmented_ = false;
  // 0, #4 (CIRCLE), #9, name, 0, then xc,yc,zc, i,j,k, r.
  if (r.sub != 2 || r.words.size() != 12) return;
  for (std::size_t i = 5; i < 12; ++i)
    if (r.words[i].kind != ClWord::Kind::Real) return;
  const canon::Vec3 axis{r.words[8].real, r.words[9].real, r.words[10].real};
  const double n = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
  if (!(n > 1e-9) || !std::isfinite(n)) return;
  arc_ = PendingArc{{r.words[5].real * scale_, r.words[6].real * scale_, r.words[7].real * scale_},
                    {axis.x / n, axis.y / n, axis.z / n}};
}

void ClToCanon::motion(const ClRecord& r) {
  if (segmented_ && r.sub != 6) {  // the segmented circle has ended
    arc_.reset();
    segmented_ = false;
  }
  if (segmented_arc(r)) return;
  const bool arc = arc_ && r.sub == 5 && r.words.size() == 5 && at_ && !cycle_;
  if (!arc) arc_.reset();
  for (std::size_t i = 2; i + 2 < r.words.size(); i += 3) {
    const canon::Vec3 p{r.words[i].real * scale_, r.words[i + 1].real * scale_,
                        r.words[i + 2].real * scale_};
    // A RAPID motion in a cycle positions: it drills nothing.
    if (cycle_ && r.sub == 5 && !rapid_) {
      drill(p, r);  // leaves the tool above the hole
      continue;
    }
    if (arc) {
      this->arc(p, r);
    } else {
      move(p, r);
    }
    at_ = p;
  }
}

// About the circle's axis, its centre moved into the plane of the start.
void ClToCanon::arc(const canon::Vec3& p, const ClRecord& r) {
  const PendingArc a = *arc_;
  arc_.reset();
  const canon::Vec3 s = *at_;
  const double along =
      (s.x - a.center.x) * a.axis.x + (s.y - a.center.y) * a.axis.y + (s.z - a.center.z) * a.axis.z;
  const canon::Vec3 c{a.center.x + a.axis.x * along, a.center.y + a.axis.y * along,
                      a.center.z + a.axis.z * along};
  canon::Arc op{p, c, a.axis, 1, feed_, {}, {}};
  if (per_rev_) op.programmed = *per_rev_;
  rapid_used_ = rapid_used_ || rapid_;
  emit(op, r);
}

// A segmented circle's record of points (5000 5, or its 5000 6
// continuation) as one arc: about the circle's centre in the start's plane,
// turning the way the points turn, to the record's last point brought to
// the start's radius (the chords' ends lie on the tolerance band's outer
// edge, the motion's last point on the circle; within OUTTOL). Points off
// the start's plane or its radius (by more than 1 %) stay chords.
bool ClToCanon::segmented_arc(const ClRecord& r) {
  const bool several = r.words.size() >= 8 && (r.words.size() - 2) % 3 == 0;
  const bool continued = segmented_ ? r.sub == 6 : r.sub == 5;
  if (circles_ != Circles::Arcs || !arc_ || !at_ || cycle_ || rapid_ || !several || !continued ||
      std::fabs(arc_->axis.z) < 1.0 - 1e-9)
    return false;
  const canon::Vec3 s = *at_;
  const canon::Vec3 c{arc_->center.x, arc_->center.y, s.z};
  const double rho = std::hypot(s.x - c.x, s.y - c.y);
  double sweep = 0.0;
  canon::Vec3 last = s;
  for (std::size_t i = 2; i + 2 < r.words.size(); i += 3) {
    const canon::Vec3 p{r.words[i].real * scale_, r.words[i + 1].real * scale_,
                        r.words[i + 2].real * scale_};
    const double d = std::hypot(p.x - c.x, p.y - c.y);
    if (std::fabs(p.z - s.z) > 1e-6 || std::fabs(d - rho) > 0.01 * rho + 1e-9 || !(rho > 0))
      return false;
    const double ax = last.x - c.x, ay = last.y - c.y, bx = p.x - c.x, by = p.y - c.y;
    sweep += std::atan2(ax * by - ay * bx, ax * bx + ay * by);
    last = p;
  }
  if (std::fabs(sweep) < 1e-9) return false;
  const double k = rho / std::hypot(last.x - c.x, last.y - c.y);
  const canon::Vec3 end{c.x + (last.x - c.x) * k, c.y + (last.y - c.y) * k, s.z};
  // More than a revolution is |turn| - 1 extra turns (docs/trace.md).
  const int extra =
      static_cast<int>(std::floor(std::fabs(sweep) / (2.0 * std::numbers::pi) - 1e-9));
  const int turn = (sweep > 0 ? 1 : -1) * (1 + std::max(extra, 0));
  canon::Arc op{end, c, {0.0, 0.0, 1.0}, turn, feed_, {}, {}};
  if (per_rev_) op.programmed = *per_rev_;
  emit(op, r);
  at_ = end;
  segmented_ = true;  // the circle stays pending for a continuation record
  return true;
}

void ClToCanon::move(const canon::Vec3& p, const ClRecord& r) {
  // FROM sets the start: a traverse there, as a post's first positioning.
  if (r.sub == 3 || rapid_) {
    rapid_used_ = rapid_used_ || rapid_;
    emit(canon::Traverse{p, {}}, r);
    return;
  }
  canon::Feed f{p, feed_, {}, {}};
  if (per_rev_) f.programmed = *per_rev_;
  emit(f, r);
}

void ClToCanon::drill(const canon::Vec3& p, const ClRecord& r) {
  const canon::Vec3 top{p.x, p.y, p.z + clearance_};
  const canon::Vec3 bottom{p.x, p.y, p.z - depth_};
  emit(canon::Traverse{top, {}}, r, canon::Origin::Cycle);
  emit(canon::Feed{bottom, feed_, {}, {}}, r, canon::Origin::Cycle);
  const canon::Vec3 out{p.x, p.y, p.z + retract_};
  emit(canon::Traverse{out, {}}, r, canon::Origin::Cycle);
  at_ = out;
  // The moves above drill it: the hole is their feature, not one more for a
  // post to drill (post/writer_hole.cpp).
  emit(canon::Hole{p, diameter_.value_or(0.0), depth_}, r, canon::Origin::Cycle);
}

void to_canon(const std::vector<ClRecord>& records, double scale, canon::Sink& sink,
              Circles circles) {
  ClToCanon c(scale, sink, circles);
  for (const ClRecord& r : records)
    c.record(r);
  sink.finish();
}

}  // namespace usina::apt
