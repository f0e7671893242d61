// G12.1/G13.1 (G112/G113) polar coordinate interpolation in the fanuc
// front end (docs/fanuc.md §7): the mode's G codes and alarms, and each
// virtual line or arc handed to the interpreter as short G1 moves of the
// linear and rotary axes (fanuc/polar_interp.hpp does the geometry).
#include <array>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "gcode/fanuc/engine.hpp"

namespace usina::gcode::fanuc {
namespace {

int tenths_of(double v) {
  return static_cast<int>(std::lround(v * 10.0));
}

std::string g_text(int t) {
  return t % 10 == 0 ? fmt::format("G{:02}", t / 10) : fmt::format("G{}.{}", t / 10, t % 10);
}

// The G codes the manual allows in the mode: G01 G02 G03, G04, G09,
// G40 (G41/G42 are allowed by Fanuc, not implemented here), G65 G66 G67,
// G90 G91, G94 G95.
bool allowed_in_mode(int t) {
  switch (t) {
  case 10:
  case 20:
  case 30:
  case 40:
  case 90:
  case 400:
  case 650:
  case 660:
  case 670:
  case 900:
  case 910:
  case 940:
  case 950: return true;
  default: return false;
  }
}

}  // namespace

// The machine moves of a virtual line or arc, absolute (G90) whatever the
// program's mode; the axes outside the plane (X Y Z A B C order) at their
// share of the path; the programmed feed on the first.
bool Engine::polar_pieces(const TapeBlock& b, const std::vector<PolarPoint>& points,
                          const PolarOthers& others, std::optional<double> feed) {
  static constexpr std::string_view kLetters = "XYZABC";
  for (const PolarPoint& p : points) {
    handed_.clear();
    if (&p == &points.front()) handed_.push_back({'G', 90});
    handed_.push_back({'G', 1});
    handed_.push_back({polar_axes_.linear_letter(), p.linear});
    handed_.push_back({polar_axes_.rotary_letter(), p.rotary});
    for (std::size_t i = 0; i < others.size(); ++i) {
      if (!others[i]) continue;
      const auto [from, to] = *others[i];
      handed_.push_back({kLetters[i], from + (to - from) * p.t});
    }
    if (feed && &p == &points.front()) handed_.push_back({'F', *feed});
    if (!hand(b, handed_)) return false;
  }
  return true;
}

bool Engine::polar_interp_codes(const TapeBlock& b, Words& w) {
  const bool on = w.has_g(121) || w.has_g(1120);
  const bool off = w.has_g(131) || w.has_g(1130);
  if (on || off) return polar_interp_switch(b, w, on, off);
  if (!polar_interp_.active()) return true;
  for (const NcWord& g : w.list) {
    if (g.letter != 'G' || g.taken || g.vacant) continue;
    const int t = tenths_of(g.value);
    if (allowed_in_mode(t)) continue;
    if (t == 410 || t == 420) {
      return error(core::Code::Unsupported, b, g.pos,
                   fmt::format("{} in G12.1 mode: cutter compensation in the polar plane is not "
                               "implemented in the fanuc dialect yet",
                               g_text(t)));
    }
    return error(core::Code::NotAllowedInMode, b, g.pos,
                 fmt::format("{} is not allowed in polar coordinate interpolation (G12.1) mode "
                             "(Fanuc alarm PS0146); cancel it with G13.1 first",
                             g_text(t)));
  }
  return true;
}

// G12.1 and G13.1 stand in blocks of their own (the manual).
bool Engine::polar_interp_switch(const TapeBlock& b, Words& w, bool on, bool off) {
  for (const NcWord& word : w.list) {
    if (word.taken || word.vacant || word.letter == 'N') continue;
    const int t = tenths_of(word.value);
    if (word.letter == 'G' && (t == 121 || t == 1120 || t == 131 || t == 1130)) continue;
    const std::string name = word.letter == 'G' ? g_text(t) : std::string(1, word.letter);
    return error(
        core::Code::NotAllowedInMode, b, word.pos,
        fmt::format("G12.1/G13.1 stand in a block of their own: {} is not allowed here", name));
  }
  if (on && off) return error(core::Code::NotAllowedInMode, b, 0, "G12.1 and G13.1 in one block");
  w.take_g(121);
  w.take_g(1120);
  w.take_g(131);
  w.take_g(1130);
  if (interp_.state().comp != CompSideState::Off) {
    return error(core::Code::NotAllowedInMode, b, 0,
                 "G12.1/G13.1 in G41/G42 mode (Fanuc alarm PS0145); cancel with G40 first");
  }
  if (off) {
    polar_interp_.stop();
    return true;
  }
  if (polar_interp_.active())
    return error(core::Code::NotAllowedInMode, b, 0, "G12.1 in G12.1 mode: give G13.1 first");
  if (xf_.active() || polar_) {
    return error(core::Code::Unsupported, b, 0,
                 "G12.1 under G16/G51/G51.1/G68 is not implemented in the fanuc dialect");
  }
  if (cycle_ != 800 && cycle_ > 30)
    return error(core::Code::NotAllowedInMode, b, 0, "G12.1 in a canned cycle: give G80 first");
  const double per = core::mm_per(interp_.state().units);
  const auto& pos = interp_.state().pos;
  polar_interp_.start(pos[static_cast<std::size_t>(polar_axes_.linear)] / per,
                      pos[static_cast<std::size_t>(polar_axes_.rotary)]);
  return true;
}

// The centre of a G02/G03 in the virtual plane: I J (K) from the start, or R.
std::optional<core::Vec2> Engine::polar_interp_centre(const TapeBlock& b, Words& w, core::Vec2 from,
                                                      core::Vec2 to, bool ccw) {
  const double per = core::mm_per(interp_.state().units);
  const char first = polar_axes_.centre_first(), second = polar_axes_.centre_second();
  if (const NcWord* r = w.find('R')) {
    const core::Vec2 chord = to - from;
    const double d = std::hypot(chord.x, chord.y);
    if (d < 1e-12) {
      error(core::Code::ArcZeroLength, b, r->pos,
            "an arc by R needs an end point apart from its start");
      return std::nullopt;
    }
    const double radius = std::fabs(r->value), half = d / 2;
    if (radius < half - kPolarChordTolerance / per) {
      error(core::Code::ArcRadiusTooSmall, b, r->pos,
            fmt::format("R{} is less than half the chord ({})", word_number(r->value),
                        word_number(half)));
      return std::nullopt;
    }
    const double h = std::sqrt(std::max(0.0, radius * radius - half * half));
    const core::Vec2 left{-chord.y / d, chord.x / d};
    const double side = (ccw ? 1.0 : -1.0) * (r->value > 0 ? 1.0 : -1.0);
    return from + chord * 0.5 + left * (h * side);
  }
  if (!w.has(first) && !w.has(second)) {
    error(core::Code::ArcMissingCenter, b, 0,
          fmt::format("an arc in G12.1 mode needs {} and/or {} or R", first, second));
    return std::nullopt;
  }
  const core::Vec2 centre = from + core::Vec2{w.get(first, 0), w.get(second, 0)};
  const double r1 = std::hypot(from.x - centre.x, from.y - centre.y);
  const double r2 = std::hypot(to.x - centre.x, to.y - centre.y);
  if (r1 < 1e-9) {
    error(core::Code::ArcZeroLength, b, 0, "arc of zero radius: the centre is at the start point");
    return std::nullopt;
  }
  // The interpreter's spiral tolerance (motion_exec.cpp): 0.02·√2 mm or 0.1 %.
  const double abs_tol = 0.02 * std::sqrt(2.0) / per;
  if (std::fabs(r1 - r2) > abs_tol && std::fabs(r1 - r2) > 0.001 * std::max(r1, r2)) {
    error(core::Code::ArcRadiusMismatch, b, 0,
          fmt::format("arc end is {:.4f} off the circle of radius {:.4f} about ({:.4f}, {:.4f}) "
                      "in the G12.1 plane; use R, or correct {}/{}",
                      std::fabs(r1 - r2), r1, centre.x, centre.y, first, second));
    return std::nullopt;
  }
  return centre;
}

bool Engine::polar_interp_move(const TapeBlock& b, Words& w) {
  const char lin = polar_axes_.linear_letter(), rot = polar_axes_.rotary_letter();
  const int motion = motion_;
  const bool arc = motion == 20 || motion == 30;
  bool moves = w.has(lin) || w.has(rot) ||
               (arc && (w.has('R') || w.has(polar_axes_.centre_first()) ||
                        w.has(polar_axes_.centre_second())));
  static constexpr std::string_view kAxes = "XYZABC";
  for (char l : kAxes)
    moves = moves || w.has(l);
  const bool end = w.has_m(2) || w.has_m(30);
  if (!moves) {
    if (end) polar_interp_.stop();  // a reset ends the mode
    return true;
  }
  if (motion != 10 && !arc) {
    return error(core::Code::NotAllowedInMode, b, 0,
                 fmt::format("{} moves are not allowed in polar coordinate interpolation (G12.1) "
                             "mode (Fanuc alarm PS0146); program G01, G02 or G03",
                             g_text(motion)));
  }
  const double per = core::mm_per(interp_.state().units);
  const bool incremental = w.has_g(910) || (interp_.state().incremental && !w.has_g(900));
  const core::Vec2 from = polar_interp_.point();
  core::Vec2 to = from;
  if (const NcWord* x = w.find(lin)) to.x = incremental ? from.x + x->value : x->value;
  if (const NcWord* c = w.find(rot)) to.y = incremental ? from.y + c->value : c->value;
  VirtualPath path;
  path.start = from;
  path.end = to;
  if (arc) {
    const auto centre = polar_interp_centre(b, w, from, to, motion == 30);
    if (!centre) return false;
    path = virtual_arc(from, to, *centre, motion == 30);
  }
  // The axes outside the plane move along, in proportion.
  PolarOthers others{};
  for (std::size_t i = 0; i < kAxes.size(); ++i) {
    const char l = kAxes[i];
    const NcWord* word = w.find(l);
    if (l == lin || l == rot || word == nullptr) continue;
    const double now = interp_.state().pos[i] / (i < 3 ? per : 1.0);
    others[i] = std::make_pair(now, incremental ? now + word->value : word->value);
  }
  std::vector<PolarPoint> points;
  const PolarFollow followed = polar_interp_.follow(path, kPolarChordTolerance / per, points);
  if (followed == PolarFollow::TooManyPieces) {
    return error(core::Code::TooManyIterations, b, 0,
                 fmt::format("this G12.1 move would need more than {} machine moves to stay "
                             "within {} mm of the contour",
                             kMaxPolarPieces, kPolarChordTolerance));
  }
  if (followed == PolarFollow::NearCentre) {
    return error(core::Code::PolarThroughCentre, b, 0,
                 fmt::format("the path passes within {} mm of the polar centre, where the angle "
                             "is undefined and the rotary axis would turn at infinite speed "
                             "(Fanuc alarm OT0512; the manual's F < L·R·π/180 with L = 0)",
                             kPolarChordTolerance));
  }
  const NcWord* f = w.find('F');
  const std::optional<double> feed = f != nullptr ? std::optional<double>(f->value) : std::nullopt;
  for (char l : std::string_view("XYZABCIJKRF"))
    w.take(l);
  w.take_g(10);
  w.take_g(20);
  w.take_g(30);
  const bool was_incremental = interp_.state().incremental;
  if (!polar_pieces(b, points, others, feed)) return false;
  if (was_incremental && !hand(b, {{'G', 91}})) return false;
  if (end) polar_interp_.stop();
  return true;
}

}  // namespace usina::gcode::fanuc
