// The range of every number a canon op carries (docs/rs274ngc.md, "Numbers"):
// finite, and within the bounds below. The front ends check it before an op
// leaves them (CanonMachine), so a back end never sees NaN, an infinity or a
// length its arithmetic cannot handle; a back end may check it again.
//
// Why 1e9: a coordinate of 1e9 mm (1,000 km) is beyond any machine, and a
// double still resolves 1.2e-7 mm there, finer than usina's 1e-6 mm geometry
// tolerance (at 1e10 mm the step is 1.9e-6 mm and equal points stop being
// equal). Squares of such lengths (1e18) and sums of many moves stay far
// from the double's 1.8e308. The smallest feed keeps a move's time finite:
// the longest move (a helix of 1e6 turns at 1e9 mm) takes at most ~4e23 s.
#pragma once

#include <cmath>
#include <optional>
#include <string>

#include <tl/expected.hpp>

#include "canon/op.hpp"

namespace usina::canon {

inline constexpr double kMaxLength = 1e9;    // mm: coordinates, centres, offsets, sizes
inline constexpr double kMaxAngle = 1e9;     // degrees: rotary axes A B C
inline constexpr double kMaxFeed = 1e9;      // mm/min, mm/rev, or 1/min under G93
inline constexpr double kMinFeed = 1e-6;     // the smallest feed rate that is not 0
inline constexpr double kMaxSpindle = 1e9;   // rev/min
inline constexpr double kMaxDwell = 1e9;     // s
inline constexpr int kMaxTurns = 1'000'001;  // of one arc or helix

// Whether a straight move's numbers are all in range, naming none (the
// bounds of check_range): every move of every program is asked, and nearly
// all are, so this part is inline and builds no message.
inline bool plainly_in_range(double v, double max) {
  return std::fabs(v) <= max;  // NaN fails the comparison
}

inline bool plainly_in_range(const Vec3& p, const Abc& a) {
  return plainly_in_range(p.x, kMaxLength) && plainly_in_range(p.y, kMaxLength) &&
         plainly_in_range(p.z, kMaxLength) && plainly_in_range(a[0], kMaxAngle) &&
         plainly_in_range(a[1], kMaxAngle) && plainly_in_range(a[2], kMaxAngle);
}

inline bool plainly_in_range(const Traverse& t) {
  return plainly_in_range(t.to, t.abc);
}

inline bool plainly_in_range_rate(double v) {
  return plainly_in_range(v, kMaxFeed) && v >= 0.0 && (v == 0.0 || v >= kMinFeed);
}

inline bool plainly_in_range(const Feed& f) {
  return plainly_in_range(f.to, f.abc) && (!f.f || plainly_in_range_rate(*f.f)) &&
         plainly_in_range_rate(f.programmed.value);
}

// What is wrong with the first number of `op` out of range, e.g. "the
// arc's centre Y (-inf) is not a finite number"; a value when there is none.
tl::expected<void, std::string> range_problem(const OpKind& op);
tl::expected<void, std::string> range_problem(const Traverse& move);
tl::expected<void, std::string> range_problem(const Feed& move);

// Every number of `op` in range; else what is wrong with the first that is
// not.
inline tl::expected<void, std::string> check_range(const OpKind& op) {
  if (const auto* f = std::get_if<Feed>(&op); f != nullptr && plainly_in_range(*f)) return {};
  if (const auto* t = std::get_if<Traverse>(&op); t != nullptr && plainly_in_range(*t)) return {};
  return range_problem(op);
}

// The same for a move not built into an op (Sink::reads_ops): the same
// message as for the op.
inline tl::expected<void, std::string> check_range(const Traverse& move) {
  if (plainly_in_range(move)) return {};
  return range_problem(move);
}

inline tl::expected<void, std::string> check_range(const Feed& move) {
  if (plainly_in_range(move)) return {};
  return range_problem(move);
}

// A bound as the docs write it: "1e9", "1e-6".
std::string limit_text(double bound);

// The same check for one value: `what` names it ("X", "the feed rate").
tl::expected<void, std::string> check_length(const char* what, double mm);
tl::expected<void, std::string> check_feed(const char* what, double rate);

}  // namespace usina::canon
