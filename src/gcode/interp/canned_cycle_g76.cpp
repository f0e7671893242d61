// G76, the lathe threading cycle, move for move as LinuxCNC 2.10 makes it
// (src/emc/rs274ngc/interp_convert.cc: convert_threading_cycle and
// threading_pass), checked against its traces (shared/conformance/rs274ngc);
// the code is usina's own. The drilling cycles are in canned_cycles.cpp.
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "gcode/interp/canned_cycle_parts.hpp"
#include "gcode/interp/canned_cycles.hpp"

namespace usina::gcode {
namespace {

using namespace cycle_parts;
using core::Code;
using core::Plane;

constexpr long kMaxPasses = 100000;  // G76 passes (DESIGN.md, "Errors and bad input")

// G76 in program units, named as in LinuxCNC's convert_threading_cycle. The
// drive line is the X where the cycle starts; I is the thread peak's offset
// from it (negative: external thread), J the first cut's depth beyond the
// peak, K the full thread depth.
struct ThreadPlan {
  bool boring = false;  // I > 0: an internal thread
  double safe_x = 0, start_y = 0, start_z = 0;
  double full_dia_depth = 0, start_depth = 0, cut_increment = 0;
  double full_threadheight = 0, end_depth = 0;
  double angle = 0;  // compound slide angle, radians, signed by the direction along Z
  double taper = 0;  // E, signed like the angle
  double target_z = 0, degression = 1;
  long spring_passes = 0;
  bool entry_taper = false, exit_taper = false;
  Vec3 end;
};

InterpResult read_count(const std::optional<double>& w, char letter, const char* what, long& out) {
  out = 0;
  if (!w) return {};
  const std::optional<long> n = whole_number(*w);
  if (!n || *n < 0) {
    return error(Code::BadWordValue,
                 fmt::format("G76 {}{:g}: {} must be a whole number, 0 or more", letter, *w, what));
  }
  if (*n > kMaxPasses) {
    return error(Code::TooManyIterations,
                 fmt::format("G76 {}{:g}: more than {} {}", letter, *w, kMaxPasses, what));
  }
  out = *n;
  return {};
}

// In LinuxCNC's order: words as read, the block's checks, then the cycle's.
InterpResult check_thread_words(const CycleWords& w, const CycleModal& m, long& spring,
                                long& tapers) {
  const Units u{m.length_unit};
  if (auto e = read_count(w.h, 'H', "the number of spring passes", spring); !e) return e;
  if (auto e = read_count(w.l, 'L', "L (taper ends: 1 entry, 2 exit, 3 both)", tapers); !e)
    return e;
  if (!w.p) return error(Code::MissingWord, "G76 needs P, the thread pitch");
  if (!w.i || !w.j || !w.k) {
    return error(Code::MissingWord,
                 fmt::format("G76 needs I, J and K (peak offset, first cut depth, thread depth); "
                             "{} is missing",
                             !w.i ? 'I' : (!w.j ? 'J' : 'K')));
  }
  if (auto e = check_spindle(m.motion, m.spindle); !e) return e;
  if (*w.i == 0) {
    return error(Code::CycleBadValue,
                 "G76 I0: the thread peak offset from the drive line must not be 0 (negative for "
                 "an external thread, positive for an internal one)");
  }
  if (*w.j <= 0) {
    return error(Code::CycleBadValue,
                 fmt::format("G76 J{:g}: the first cut depth must be greater than 0", u.in(*w.j)));
  }
  if (*w.k <= *w.j) {
    return error(Code::CycleBadValue,
                 fmt::format("G76 K{:g}: the thread depth must be greater than J{:g}", u.in(*w.k),
                             u.in(*w.j)));
  }
  return {};
}

ThreadPlan plan_thread(const CycleWords& w, const CycleModal& m, Units u, const Vec3& start) {
  ThreadPlan t;
  const auto end_of = [&](const std::optional<double>& word, double from) {
    if (!word) return from;
    return m.incremental ? from + u.in(*word) : u.in(*word);
  };
  t.end = {end_of(w.x, start.x), end_of(w.y, start.y), end_of(w.z, start.z)};
  const double half = m.diameter_mode ? 2.0 : 1.0;  // G7: I, J, K are on the diameter
  const double i = u.in(*w.i) / half;
  const double j = u.in(*w.j) / half;
  const double k = u.in(*w.k) / half;
  t.boring = i > 0.0;
  t.safe_x = start.x;
  t.start_y = start.y;
  t.start_z = start.z;
  t.full_dia_depth = std::abs(i);
  t.start_depth = std::abs(i) + std::abs(j);
  t.cut_increment = std::abs(j);
  t.full_threadheight = std::abs(k);
  t.end_depth = std::abs(k) + std::abs(i);
  // LinuxCNC scales by M_PIl / 180 in long double.
  t.angle = static_cast<double>(static_cast<long double>(w.q.value_or(0.0)) *
                                (std::numbers::pi_v<long double> / 180.0L));
  t.taper = std::max(0.0, w.e ? u.in(*w.e) : 0.0);
  if (t.end.z > t.start_z) {  // cutting towards +Z: the angle and taper turn round
    t.angle = -t.angle;
    t.taper = -t.taper;
  }
  t.degression = (w.r && *w.r >= 1.0) ? *w.r : 1.0;
  t.target_z = t.end.z + std::abs(k) * std::tan(t.angle);
  return t;
}

// One pass (LinuxCNC threading_pass): back, in (straight or along the entry
// taper), over to the end (with the exit taper), out.
void thread_pass(Mover& m, const ThreadPlan& t, double depth, double zoff) {
  const double back = t.boring ? t.safe_x + depth - t.end_depth : t.safe_x - depth + t.end_depth;
  const double in = t.boring ? t.safe_x + depth : t.safe_x - depth;
  const double crest =
      t.boring ? t.safe_x + depth - t.full_threadheight : t.safe_x - depth + t.full_threadheight;
  const double y = t.start_y;
  m.traverse(back, y, t.start_z - zoff);
  if (t.taper != 0.0 && t.entry_taper) {
    m.feed(crest, y, t.start_z - zoff);
    m.feed(in, y, t.start_z - zoff - t.taper);
  } else {
    m.traverse(in, y, t.start_z - zoff);
  }
  if (t.taper != 0.0 && t.exit_taper) {
    m.feed(in, y, t.target_z - zoff + t.taper);
    m.feed(crest, y, t.target_z - zoff);
  } else {
    m.feed(in, y, t.target_z - zoff);
  }
  m.traverse(back, y, t.target_z - zoff);
}

// The depth of pass n + 1 after pass n: the cut area stays about the same
// when the degression R is 2 (depth ~ sqrt(n)), the depth step when R is 1.
double next_depth(const ThreadPlan& t, long& pass) {
  ++pass;
  return t.full_dia_depth +
         t.cut_increment * std::pow(static_cast<double>(pass), 1.0 / t.degression);
}

long count_thread_passes(const ThreadPlan& t) {
  long pass = 1;
  long n = 0;
  double depth = t.start_depth;
  while (depth < t.end_depth && n <= kMaxPasses) {
    ++n;
    depth = next_depth(t, pass);
  }
  return n + t.spring_passes + 1;
}

void cut_thread(Mover& m, const ThreadPlan& t) {
  const double tan_angle = std::tan(t.angle);
  long pass = 1;
  double depth = t.start_depth;
  while (depth < t.end_depth) {
    thread_pass(m, t, depth, (depth - t.full_dia_depth) * tan_angle);
    depth = next_depth(t, pass);
  }
  // The full depth, once and then once per spring pass.
  const double zoff = (t.end_depth - t.full_dia_depth) * tan_angle;
  for (long n = 0; n <= t.spring_passes; ++n)
    thread_pass(m, t, t.end_depth, zoff);
  m.traverse(t.end.x, t.end.y, t.end.z);
}

}  // namespace

// G76 (LinuxCNC convert_straight / convert_threading_cycle). Its moves are in
// X and Z whatever the plane; LinuxCNC runs it in G17 as well.
InterpResult CannedCycles::run_threading(const CycleWords& words, const CycleModal& modal,
                                         MotionTarget& target) {
  long spring = 0;
  long tapers = 0;
  if (auto e = check_thread_words(words, modal, spring, tapers); !e) return e;
  const Units u{modal.length_unit};
  const Vec3 pos = target.position();
  const Vec3 pos_u = unit_ == u.mm && pos == end_point_ ? end_point_u_ : u.in(pos);
  ThreadPlan t = plan_thread(words, modal, u, pos_u);
  t.spring_passes = spring;
  t.entry_taper = (tapers & 1) != 0;
  t.exit_taper = (tapers & 2) != 0;
  if (count_thread_passes(t) > kMaxPasses) {
    return error(Code::TooManyIterations,
                 fmt::format("G76 would cut more than {} passes (degression R{:g} is too large "
                             "for J and K)",
                             kMaxPasses, t.degression));
  }
  Mover m(target, Plane::XY, u);  // XY: (a, b, c) are (x, y, z)
  cut_thread(m, t);
  note_other_motion();  // G76 is not a canned cycle to LinuxCNC's convert_motion
  end_point_u_ = t.end;
  end_point_ = u.out(t.end);
  unit_ = u.mm;
  return {};
}

}  // namespace usina::gcode
