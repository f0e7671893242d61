#include "apt/canon_out.hpp"

#include <optional>
#include <string>

#include <fmt/format.h>

#include "apt/vocabulary.hpp"

namespace usina::apt {
namespace {

constexpr int kClw = 60, kCclw = 59, kOn = 71, kOff = 72, kFlood = 89, kMist = 90, kIpr = 74,
              kMmpr = 172, kDrill = 163;

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

std::string text_of(const ClRecord& r) {
  std::string t;
  for (const ClWord& w : r.words)
    t += w.text;
  while (!t.empty() && t.back() == ' ')
    t.pop_back();
  while (!t.empty() && t.front() == ' ')
    t.erase(t.begin());
  return t;
}

// Walks the records in order; what post words set applies to the motions after.
class Converter {
 public:
  Converter(double scale, canon::Sink& sink) : scale_(scale), sink_(sink) {}

  void record(const ClRecord& r);

 private:
  void emit(canon::OpKind k, const ClRecord& r, canon::Origin o = canon::Origin::Program) {
    sink_.on(canon::Op{std::move(k), r.src, o});
  }

  void post(const ClRecord& r);
  void post_motion_words(const ClRecord& r);
  void motion(const ClRecord& r);
  void move(const canon::Vec3& p, const ClRecord& r);
  void drill(const canon::Vec3& p, const ClRecord& r);
  void spindle(const ClRecord& r);
  void cycle(const ClRecord& r);

  double scale_;
  canon::Sink& sink_;
  bool rapid_ = false;       // RAPID: the next motion statement traverses
  bool rapid_used_ = false;  // ... and it has begun
  std::optional<double> feed_;
  std::optional<canon::ProgrammedFeed> per_rev_;
  std::optional<double> diameter_;
  canon::Spindle spindle_{};
  // CYCLE/DRILL,depth,IPM,f,clearance: each GOTO point drills.
  bool cycle_ = false;
  double depth_ = 0.0;
  double clearance_ = 0.0;
};

void Converter::record(const ClRecord& r) {
  if (r.cls == cls::kSource && rapid_used_) rapid_ = rapid_used_ = false;
  if (r.cls == cls::kPost) post(r);
  if (r.cls == cls::kMotion) motion(r);
  if (r.cls == cls::kControl && r.sub == 6 && !r.words.empty())
    diameter_ = r.words[0].real * scale_;
}

void Converter::post(const ClRecord& r) {
  switch (r.sub) {
  case 1: emit(canon::ProgramEnd{}, r); return;
  case 2: emit(canon::MachineCode{'M', 0, {}, {}}, r); return;
  case 3: emit(canon::MachineCode{'M', 1, {}, {}}, r); return;
  case 5: rapid_ = true; return;
  case 1009: {
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
  case 1010: emit(canon::Dwell{first_number(r).value_or(0.0)}, r); return;
  case 1030:
    emit(canon::Coolant{has_code(r, kMist), has_code(r, kOn) || has_code(r, kFlood)}, r);
    return;
  case 1031: spindle(r); return;
  case 1054: cycle(r); return;
  case 1055:
    emit(canon::ToolChange{static_cast<int>(first_number(r).value_or(0.0)), diameter_}, r);
    return;
  default: post_motion_words(r);
  }
}

// The words that reach the stream as text: PARTNO, PPRINT, INSERT, and a
// post word the canon stream has no op for (MACHIN/..., SEQNO/...).
void Converter::post_motion_words(const ClRecord& r) {
  if (r.sub == 1044 || r.sub == 1045 || r.sub == 1046) {
    emit(canon::Comment{text_of(r)}, r);
    return;
  }
  std::string words;
  for (const ClWord& w : r.words) {
    words += words.empty() ? "/" : ",";
    if (w.kind == ClWord::Kind::Real) words += fmt_number(w.real);
    if (w.kind == ClWord::Kind::Code) words += std::string(minor_word_name(w.code));
    if (w.kind == ClWord::Kind::Text) words += w.text;
  }
  emit(canon::Comment{"APT " + std::string(post_word_name(r.sub)) + words}, r);
}

void Converter::spindle(const ClRecord& r) {
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

void Converter::cycle(const ClRecord& r) {
  if (has_code(r, kOff)) {
    cycle_ = false;
    return;
  }
  // CYCLE/DRILL,depth,IPM|MMPM,feed,clearance (the numbers in that order).
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
}

void Converter::motion(const ClRecord& r) {
  for (std::size_t i = 2; i + 2 < r.words.size(); i += 3) {
    const canon::Vec3 p{r.words[i].real * scale_, r.words[i + 1].real * scale_,
                        r.words[i + 2].real * scale_};
    if (cycle_ && r.sub == 5) {
      drill(p, r);
    } else {
      move(p, r);
    }
  }
}

void Converter::move(const canon::Vec3& p, const ClRecord& r) {
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

void Converter::drill(const canon::Vec3& p, const ClRecord& r) {
  const canon::Vec3 top{p.x, p.y, p.z + clearance_};
  const canon::Vec3 bottom{p.x, p.y, p.z - depth_};
  emit(canon::Traverse{top, {}}, r, canon::Origin::Cycle);
  emit(canon::Feed{bottom, feed_, {}, {}}, r, canon::Origin::Cycle);
  emit(canon::Traverse{top, {}}, r, canon::Origin::Cycle);
  emit(canon::Hole{p, diameter_.value_or(0.0), depth_}, r);
}

}  // namespace

void to_canon(const std::vector<ClRecord>& records, double scale, canon::Sink& sink) {
  Converter c(scale, sink);
  for (const ClRecord& r : records)
    c.record(r);
  sink.finish();
}

}  // namespace usina::apt
