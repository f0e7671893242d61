#include "apt/cl_from_canon.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <type_traits>

#include <fmt/format.h>

#include "apt/vocabulary.hpp"

namespace usina::apt {
namespace {

// Minor words' codes and post words' subclasses (apt/vocabulary.hpp).
constexpr int kClw = minor_code("CLW"), kCclw = minor_code("CCLW"), kOff = minor_code("OFF"),
              kFlood = minor_code("FLOOD"), kMist = minor_code("MIST"), kMmpm = minor_code("MMPM"),
              kMmpr = minor_code("MMPR");
constexpr int kEnd = post_code("END"), kStop = post_code("STOP"), kOpstop = post_code("OPSTOP"),
              kRapid = post_code("RAPID"), kFedrat = post_code("FEDRAT"),
              kDelay = post_code("DELAY"), kCoolnt = post_code("COOLNT"),
              kSpindl = post_code("SPINDL"), kPprint = post_code("PPRINT"),
              kInsert = post_code("INSERT"), kCycle = post_code("CYCLE"),
              kLoadtl = post_code("LOADTL");
// The circle of the 3000 surface record: its subclass and canonical type.
constexpr int kCircle = 4, kCircleType = 9;

// Positions that agree to this are one (the round trip holds to 1e-6).
constexpr double kSame = 1e-9;

using core::cross;
using core::dot;
using core::norm;

// p moved d along the axis.
canon::Vec3 along(const canon::Vec3& p, const canon::Vec3& axis, double d) {
  return p + axis * d;
}

bool same(const canon::Vec3& a, const canon::Vec3& b) {
  return std::fabs(a.x - b.x) <= kSame && std::fabs(a.y - b.y) <= kSame &&
         std::fabs(a.z - b.z) <= kSame;
}

// The angle from u to v about `axis`, counter-clockwise, in (0, 2π]: the
// canon's arc to where it began is a whole circle.
double sweep(const canon::Vec3& u, const canon::Vec3& v, const canon::Vec3& axis) {
  double a = std::atan2(dot(cross(u, v), axis), dot(u, v));
  if (a <= 1e-12) a += 2.0 * std::numbers::pi;
  return a;
}

}  // namespace

void CanonToCl::add(int cls, int sub, std::vector<ClWord> words, const core::SourceLoc& src) {
  records_.push_back(ClRecord{cls, sub, std::move(words), src});
}

// Each statement is numbered by its op's line, as the APT CL reader numbers
// its statements: ClToCanon ends a RAPID's reach at the next one.
void CanonToCl::statement(const core::SourceLoc& src) {
  add(cls::kSource, static_cast<int>(src.line), {ClWord::number(0.0), ClWord::chars("")}, src);
}

void CanonToCl::goto_point(const canon::Vec3& p, const core::SourceLoc& src) {
  add(cls::kMotion, 5,
      {ClWord::number(0.0), ClWord::number(0.0), ClWord::number(p.x), ClWord::number(p.y),
       ClWord::number(p.z)},
      src);
  at_ = p;
}

void CanonToCl::on(const canon::Op& op) {
  if (finished_) return;
  // Between two ops the records are final, but for a traverse a hole may
  // take back: flushed before any op but a hole.
  if (records_.size() >= kChunk && !pending_ && !std::holds_alternative<canon::Hole>(op.kind))
    flush();
  if (pending_) {
    hold(op);
    return;
  }
  if (std::holds_alternative<canon::Hole>(op.kind)) {
    hole(op);
    return;
  }
  write(op);
}

void CanonToCl::write(const canon::Op& op) {
  const core::SourceLoc& src = op.src;
  last_traverse_.reset();
  if (const auto* t = std::get_if<canon::Traverse>(&op.kind)) {
    LastTraverse last{records_.size(), at_, op};
    traverse(t->to, src);
    last_traverse_ = std::move(last);
    return;
  }
  std::visit(
      [&](const auto& k) {
        using K = std::decay_t<decltype(k)>;
        if constexpr (std::is_same_v<K, canon::Feed>) {
          feed_to(k, src);
        } else if constexpr (std::is_same_v<K, canon::Arc>) {
          arc(k, src);
        } else if constexpr (std::is_same_v<K, canon::Spline>) {
          // Its chords, within the interpreter's tolerance: CL has no spline.
          for (const canon::Vec3& p : k.points)
            feed_to(canon::Feed{p, k.f, {}, k.programmed}, src);
          if (k.points.empty() || !same(k.points.back(), k.to))
            feed_to(canon::Feed{k.to, k.f, {}, k.programmed}, src);
        } else if constexpr (std::is_same_v<K, canon::Probe>) {
          text(kPprint, "PROBE", src);
          feed_to(canon::Feed{k.to, feed_, {}, {}}, src);
        } else if constexpr (std::is_same_v<K, canon::Dwell>) {
          statement(src);
          add(cls::kPost, kDelay, {ClWord::number(k.s)}, src);
        } else if constexpr (std::is_same_v<K, canon::ToolChange>) {
          tool(k, src);
        } else if constexpr (std::is_same_v<K, canon::Spindle>) {
          spindle(k, src);
        } else if constexpr (std::is_same_v<K, canon::Coolant>) {
          coolant(k, src);
        } else if constexpr (std::is_same_v<K, canon::Comment>) {
          text(kPprint, k.text, src);
        } else if constexpr (std::is_same_v<K, canon::ProgramEnd>) {
          cycle_off(src);
          statement(src);
          add(cls::kPost, kEnd, {}, src);
        } else if constexpr (std::is_same_v<K, canon::MachineCode>) {
          machine_code(k, src);
        } else if constexpr (std::is_same_v<K, canon::Hole>) {
          // Released with its moves when it was not a plain drilling: the
          // moves are the path, and CL has no record for the hole alone.
        }
        // Pocket: a feature whose moves come as moves. PathMode: CL has
        // no record for it (docs/apt.md).
      },
      op.kind);
}

// RAPID, then GOTO; within an open CYCLE/DRILL a RAPID motion positions.
void CanonToCl::traverse(const canon::Vec3& p, const core::SourceLoc& src) {
  statement(src);
  add(cls::kPost, kRapid, {}, src);
  goto_point(p, src);
}

void CanonToCl::feed_to(const canon::Feed& f, const core::SourceLoc& src) {
  cycle_off(src);
  const double length = at_ ? norm(f.to - *at_) : 0.0;
  feed_rate(f.f, f.programmed, length, src);
  statement(src);
  goto_point(f.to, src);
}

// FEDRAT when the rate changes. Inverse time (G93: the move takes 1/value
// minutes) has no CL form: the move's own rate in mm/min, which takes it
// the same time.
void CanonToCl::feed_rate(std::optional<double> f, const canon::ProgrammedFeed& p, double length,
                          const core::SourceLoc& src) {
  using Mode = canon::ProgrammedFeed::Mode;
  const bool rev = p.mode == Mode::PerRevolution;
  if (p.mode == Mode::InverseTime)
    f = length > 0.0 ? std::optional(length * p.value) : std::nullopt;
  if (rev) f = p.value;
  if (!f || (feed_ == f && per_rev_ == rev)) return;
  statement(src);
  std::vector<ClWord> words{ClWord::number(*f)};
  if (rev) words.push_back(ClWord::vocabulary(kMmpr));
  add(cls::kPost, kFedrat, std::move(words), src);
  feed_ = f;
  per_rev_ = rev;
}

// IBM's form: the circle's canonical numbers (centre, axis turning
// counter-clockwise, radius) in a 3000 2 record, then the GOTO of the end.
// An arc of more than a turn is one circle a turn, then the rest.
void CanonToCl::arc(const canon::Arc& a, const core::SourceLoc& src) {
  const double n = norm(a.normal);
  if (!at_ || !(n > 0.0) || a.turn == 0) {
    feed_to(canon::Feed{a.to, a.f, a.abc, a.programmed}, src);
    return;
  }
  cycle_off(src);
  const double sense = a.turn > 0 ? 1.0 : -1.0;
  const canon::Vec3 axis{sense * a.normal.x / n, sense * a.normal.y / n, sense * a.normal.z / n};
  const canon::Vec3 start = *at_;
  const canon::Vec3 u = start - a.center;
  const canon::Vec3 radial = along(u, axis, -dot(u, axis));
  const double h = dot(a.to - start, axis);
  const canon::Vec3 v = a.to - a.center;
  const canon::Vec3 end_radial = along(v, axis, -dot(v, axis));
  const int turns = std::abs(a.turn);
  const double total = sweep(radial, end_radial, axis) + 2.0 * std::numbers::pi * (turns - 1);
  const double r = norm(radial);
  feed_rate(a.f, a.programmed, std::hypot(r * total, h), src);
  for (int k = 1; k < turns; ++k) {
    const double rise = h * (2.0 * std::numbers::pi * k) / total;
    arc_piece(along(start, axis, rise), a.center, axis, src);
  }
  arc_piece(a.to, a.center, axis, src);
}

void CanonToCl::arc_piece(const canon::Vec3& to, const canon::Vec3& center, const canon::Vec3& axis,
                          const core::SourceLoc& src) {
  const canon::Vec3 u = *at_ - center;
  const canon::Vec3 radial = along(u, axis, -dot(u, axis));
  statement(src);
  add(cls::kSurface, 2,
      {ClWord::number(0.0), ClWord::vocabulary(kCircle), ClWord::vocabulary(kCircleType),
       ClWord::chars(""), ClWord::number(0.0), ClWord::number(center.x), ClWord::number(center.y),
       ClWord::number(center.z), ClWord::number(axis.x), ClWord::number(axis.y),
       ClWord::number(axis.z), ClWord::number(norm(radial))},
      src);
  goto_point(to, src);
}

void CanonToCl::spindle(const canon::Spindle& s, const core::SourceLoc& src) {
  statement(src);
  if (s.dir == canon::SpindleDir::Off) {
    add(cls::kPost, kSpindl, {ClWord::vocabulary(kOff)}, src);
    return;
  }
  add(cls::kPost, kSpindl,
      {ClWord::number(s.rpm), ClWord::vocabulary(s.dir == canon::SpindleDir::Cw ? kClw : kCclw)},
      src);
}

void CanonToCl::coolant(const canon::Coolant& c, const core::SourceLoc& src) {
  std::vector<ClWord> words;
  if (c.mist) words.push_back(ClWord::vocabulary(kMist));
  if (c.flood) words.push_back(ClWord::vocabulary(kFlood));
  if (words.empty()) words.push_back(ClWord::vocabulary(kOff));
  statement(src);
  add(cls::kPost, kCoolnt, std::move(words), src);
}

// CUTTER first: ClToCanon gives the tool change the diameter it knows then.
void CanonToCl::tool(const canon::ToolChange& t, const core::SourceLoc& src) {
  statement(src);
  if (t.diameter) add(cls::kControl, 6, {ClWord::number(*t.diameter)}, src);
  add(cls::kPost, kLoadtl, {ClWord::number(t.tool)}, src);
}

void CanonToCl::text(int code, const std::string& t, const core::SourceLoc& src) {
  statement(src);
  add(cls::kPost, code, text_words(t, std::max<std::size_t>(11, (t.size() + 5) / 6)), src);
}

// M0 and M1 are STOP and OPSTOP; another machine code goes to the post as
// INSERT/ text (it comes back as a comment).
void CanonToCl::machine_code(const canon::MachineCode& m, const core::SourceLoc& src) {
  if (m.letter == 'M' && (m.code == 0 || m.code == 1) && !m.p && !m.q) {
    statement(src);
    add(cls::kPost, m.code == 0 ? kStop : kOpstop, {}, src);
    return;
  }
  std::string t = fmt::format("{}{}", m.letter, m.code);
  if (m.p) t += fmt::format(" P{}", *m.p);
  if (m.q) t += fmt::format(" Q{}", *m.q);
  text(kInsert, t, src);
}

void CanonToCl::cycle_off(const core::SourceLoc& src) {
  if (!cycle_) return;
  statement(src);
  add(cls::kPost, kCycle, {ClWord::vocabulary(kOff)}, src);
  cycle_.reset();
}

void CanonToCl::finish() {
  if (finished_) return;
  finished_ = true;
  const core::SourceLoc src = records_.empty() ? core::SourceLoc{} : records_.back().src;
  while (pending_)
    release();
  cycle_off(src);
  add(cls::kFini, 0, {}, src);
  flush();
}

void CanonToCl::flush() {
  if (!flush_ || records_.empty()) return;
  flush_(std::move(records_));
  records_.clear();
  last_traverse_.reset();
}

std::vector<ClRecord> canon_to_cl(const std::vector<canon::Op>& ops) {
  CanonToCl cl;
  for (const canon::Op& op : ops)
    cl.on(op);
  cl.finish();
  return cl.records();
}

}  // namespace usina::apt
