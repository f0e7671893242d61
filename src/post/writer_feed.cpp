// Feed words: F in mm/min under G94, and the moves a program fed otherwise.
// A G93 (inverse-time) move is written as the mm/min that takes the same
// time when only X Y Z move, which every control reads; with a rotary axis
// that rate means nothing, so it stays G93 where the control has it. A G95
// (per-revolution) feed stays G95 where the control has it, else becomes
// mm/min at the spindle speed in force.
#include <cmath>

#include <fmt/format.h>

#include "post/writer.hpp"

namespace usina::post {

using Mode = canon::ProgrammedFeed::Mode;

std::string Writer::feed_mode_word(int mode) {
  if (feed_mode_ == mode) return {};
  feed_mode_ = mode;
  feed_.reset();  // an F of another mode means another thing: write it again
  return code('G', mode);
}

std::string Writer::feed_word(std::optional<double> f, const canon::Op& op) {
  const RateWords r = per_minute(f, op);
  std::string w = r.mode;
  append(w, r.f);
  return w;
}

Writer::RateWords Writer::per_minute(std::optional<double> f, const canon::Op& op) {
  if (!f) {
    if (!feed_) unsupported(op, "a feed move without a feed rate");
    return {};
  }
  RateWords w{feed_mode_word(94), {}};
  last_feed_ = f;
  const double r = out_.rounded(*f);
  if (feed_ && *feed_ == r) return w;
  feed_ = r;
  out_.append_word(w.f, 'F', *f);
  return w;
}

bool Writer::moves_rotary(const canon::Abc& abc) const {
  for (std::size_t i = 0; i < 3; ++i) {
    const double r = out_.rounded(abc[i]);
    if (axes_[i + 3] ? *axes_[i + 3] != r : r != 0.0) return true;
  }
  return false;
}

Writer::RateWords Writer::inverse_time(const MoveRate& m, const canon::Op& op) {
  if (!m.rotary) {
    if (m.length <= 0.0) return {};  // nothing moves: no block is written
    return per_minute(m.length * m.programmed.value, op);
  }
  if (!control_.inverse_time) {
    unsupported(op, "an inverse-time (G93) move of a rotary axis");
    return {};
  }
  RateWords w{feed_mode_word(93), {}};
  out_.append_word(w.f, 'F', m.programmed.value);  // G93 wants F in every block
  return w;
}

Writer::RateWords Writer::per_revolution(const MoveRate& m, const canon::Op& op) {
  const double v = m.programmed.value;
  if (control_.per_revolution) {
    RateWords w{feed_mode_word(95), {}};
    const double r = out_.rounded(v);
    if (feed_ && *feed_ == r) return w;
    feed_ = r;
    out_.append_word(w.f, 'F', v);
    return w;
  }
  if (dir_ == canon::SpindleDir::Off || !speed_ || *speed_ <= 0) {
    unsupported(op, "a feed per revolution (G95) with the spindle stopped");
    return {};
  }
  return per_minute(v * static_cast<double>(*speed_), op);
}

Writer::RateWords Writer::rate_words(const MoveRate& m, const canon::Op& op) {
  if (m.f) return per_minute(m.f, op);
  switch (m.programmed.mode) {
  case Mode::InverseTime: return inverse_time(m, op);
  case Mode::PerRevolution: return per_revolution(m, op);
  case Mode::PerMinute: break;
  }
  return per_minute(m.f, op);
}

// A spline's points as straight feeds; under G93 the whole curve takes
// 1/F minutes, so each piece gets the curve's mm/min.
void Writer::spline(const canon::Spline& s, const canon::Op& op) {
  std::optional<double> f = s.f;
  canon::ProgrammedFeed programmed = s.programmed;
  if (!f && programmed.mode == Mode::InverseTime && pos_known_) {
    double length = 0.0;
    core::Vec3 at = pos_;
    for (const core::Vec3& p : s.points) {
      length += core::norm(p - at);
      at = p;
    }
    if (length > 0.0) f = length * programmed.value;
  }
  for (const core::Vec3& p : s.points)
    feed(p, f, canon::Abc{}, op, programmed);
}

}  // namespace usina::post
