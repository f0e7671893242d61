// Moves of the romi dialect: Cartesian and polar end points of straight
// moves, the polar and tangent arc forms, the R-only blend (which waits for
// the next block), and the path from program coordinates through the
// transformation and cutter compensation to the canonical machine.
#include <cmath>

#include <fmt/format.h>

#include "gcode/romi/translate.hpp"

namespace usina::gcode::romi {
namespace {

constexpr double kOnCircle = 0.01;  // mm: an end point this far off its circle is an error

double deg(double rad) {
  return core::rad_to_deg(rad);
}

}  // namespace

std::optional<double> Heading::degrees() const {
  if (!known_) return std::nullopt;
  return angle_ ? *angle_ : deg(std::atan2(step_.y, step_.x));
}

namespace {

double rad(double degrees) {
  return core::deg_to_rad(degrees);
}

Vec2 polar(Vec2 origin, double r, double angle_deg) {
  return {origin.x + r * std::cos(rad(angle_deg)), origin.y + r * std::sin(rad(angle_deg))};
}

Vec2 xy(const Vec3& p) {
  return {p.x, p.y};
}

// An angle in (0, 360].
double positive_sweep(double a) {
  double s = std::fmod(a, 360.0);
  if (s <= 1e-9) s += 360.0;
  return s;
}

}  // namespace

Vec3 Translator::cartesian_end(const Vec3& start) const {
  Vec3 end = start;
  for (int a = 0; a < 3; ++a) {
    const char letter = "XYZ"[a];
    if (!words_.has(letter)) continue;
    const double v = mm(words_.get(letter));
    end[a] = incremental(letter) ? start[a] + v : v;
  }
  return end;
}

// The end of a straight move (G00, G01, a drilling position) from `start`.
std::optional<Vec3> Translator::line_end(const Vec3& start, Fail& fail) const {
  const bool polar_words = words_.has('R') || words_.has('A') || words_.has('C');
  if (!polar_words) {
    if (words_.has('I') || words_.has('J')) {
      const char c = words_.has('I') ? 'I' : 'J';
      fail = {core::Code::MissingWord, words_.col(c),
              "a polar centre (I J) with no R or C: the move has no end point"};
      return std::nullopt;
    }
    return cartesian_end(start);
  }
  if (words_.has('X') || words_.has('Y')) {
    const char c = words_.has('X') ? 'X' : 'Y';
    fail = {core::Code::PolarWithXy, words_.col(c),
            "polar words (R, A, C) and X/Y in one straight move: give the end point one way"};
    return std::nullopt;
  }
  const auto q = polar_end(xy(start), fail);
  if (!q) return std::nullopt;
  Vec3 end = cartesian_end(start);  // Z may accompany any form
  end.x = q->x;
  end.y = q->y;
  return end;
}

// The end of a polar straight move from p0: R A, R C, R or C, about the
// polar centre I J (program zero when absent).
std::optional<Vec2> Translator::polar_end(Vec2 p0, Fail& fail) const {
  const Vec2 o{words_.has('I') ? mm(words_.get('I')) : 0.0,
               words_.has('J') ? mm(words_.get('J')) : 0.0};
  const Vec2 d{p0.x - o.x, p0.y - o.y};
  const double r0 = std::hypot(d.x, d.y);
  const double t0 = deg(std::atan2(d.y, d.x));
  const double c = incremental('C') ? t0 + words_.get('C') : words_.get('C');
  if (words_.has('A')) {
    if (!words_.has('R') || words_.has('C')) {
      fail = {core::Code::MissingWord, words_.col('A'),
              words_.has('C') ? "R A C is an arc form; a straight move takes R A or R C"
                              : "A (the direction of the move) needs R (its length)"};
      return std::nullopt;
    }
    return polar(p0, mm(words_.get('R')), words_.get('A'));
  }
  if (!words_.has('R')) return polar(o, r0, c);
  const double r = incremental('R') ? r0 + mm(words_.get('R')) : mm(words_.get('R'));
  if (words_.has('C')) return polar(o, r, c);
  if (r0 < 1e-9) {
    fail = {core::Code::BadWordValue, words_.col('R'),
            "R alone moves along the line from the polar centre through the current point, "
            "and the current point is the centre"};
    return std::nullopt;
  }
  return Vec2{o.x + r * d.x / r0, o.y + r * d.y / r0};
}

bool Translator::require_feed(const char* what) {
  if (work_.machine.feed > 0.0) return true;
  return error(core::Code::NoFeedRate, 0, fmt::format("{} with no feed rate: give F", what));
}

bool Translator::move() {
  if (moved_by_handler_) return true;
  words_.forget_taken();  // G81's R and Z, G31's X Y...: not a position
  bool position = false;
  for (const char c : {'X', 'Y', 'Z', 'R', 'A', 'C', 'I', 'J'}) {
    if (!words_.open(c)) continue;
    words_.take(c);
    position = true;
  }
  if (work_.blend) {
    if (!position || work_.motion() > 1 || work_.drill.active) {
      run_.at(work_.blend->loc);
      return error(core::Code::BlendNeedsMove, 0,
                   "an arc with only R blends into the next move, and the next block is not a "
                   "straight move");
    }
  }
  if (!position) return true;
  if (work_.drill.active) {
    if (work_.motion() > 1) {
      return error(core::Code::NotAllowedInMode, 0,
                   "an arc while the drilling cycle G81 is on: G80 first");
    }
    Fail fail;
    auto end = line_end(work_.pos, fail);
    if (!end) return error(fail);
    return drill_at(xy(*end));
  }
  if (work_.motion() >= 2) return arc_block();
  Fail fail;
  auto end = line_end(work_.pos, fail);
  if (!end) return error(fail);
  if (work_.blend) {
    // The end must not depend on where the blend arc ends.
    Vec3 other = work_.blend->start;
    other.x += 1.0;
    other.y += 1.0;
    auto check = line_end(other, fail);
    if (!check || core::distance(xy(*check), xy(*end)) > 1e-9) {
      run_.at(work_.blend->loc);
      return error(core::Code::BlendNeedsMove, 0,
                   "an arc with only R blends into the next move, whose end point must not "
                   "depend on its start: give absolute X and Y");
    }
    if (!blend(*end)) return false;
  }
  if (work_.motion() == 1 && !require_feed("G01")) return false;
  return emit_line(*end, work_.motion() == 0);
}

bool Translator::arc_block() {
  if (!require_feed(work_.motion() == 2 ? "G02" : "G03")) return false;
  if (words_.has('X') || words_.has('Y')) return arc_cartesian();
  return arc_polar();
}

// X Y I J (absolute centre) and X Y R (shorter arc; R < 0 the longer).
bool Translator::arc_cartesian() {
  const bool ccw = work_.motion() == 3;
  const Vec2 p0 = xy(work_.pos);
  const Vec3 end = cartesian_end(work_.pos);
  Vec2 center;
  if (words_.has('A') || words_.has('C')) {
    return error(core::Code::PolarWithXy, words_.col(words_.has('A') ? 'A' : 'C'),
                 "an arc with X/Y takes I J or R, not A or C");
  }
  if (words_.has('R')) {
    if (words_.has('I') || words_.has('J')) {
      return error(core::Code::ArcMissingCenter, words_.col('R'),
                   "an arc takes R or I J, not both");
    }
    const double r = mm(words_.get('R'));
    if (core::distance(p0, xy(end)) < 1e-9) {
      return error(core::Code::ArcZeroLength, words_.col('R'),
                   "an X Y R arc with its end at its start: use C 360 or I J");
    }
    auto c = core::arc_center_from_radius(p0, xy(end), r, ccw, kOnCircle);
    if (!c) {
      return error(core::Code::ArcRadiusTooSmall, words_.col('R'),
                   fmt::format("arc radius {:.4f} mm is smaller than half the chord {:.4f} mm",
                               std::fabs(r), core::distance(p0, xy(end)) / 2));
    }
    center = *c;
  } else if (words_.has('I') || words_.has('J')) {
    center = {words_.has('I') ? mm(words_.get('I')) : 0.0,
              words_.has('J') ? mm(words_.get('J')) : 0.0};
    const double r1 = core::distance(p0, center);
    const double r2 = core::distance(xy(end), center);
    if (std::fabs(r1 - r2) > kOnCircle) {
      return error(core::Code::ArcRadiusMismatch, 0,
                   fmt::format("arc end ({:.4f}, {:.4f}) is {:.4f} mm off the circle of radius "
                               "{:.4f} about ({:.4f}, {:.4f})",
                               end.x, end.y, std::fabs(r1 - r2), r1, center.x, center.y));
    }
    if (r1 < 1e-9) return error(core::Code::ArcZeroLength, 0, "arc of zero radius");
  } else {
    return error(core::Code::ArcMissingCenter, 0, "an arc with X/Y needs I J or R");
  }
  return emit_arc(end, center, ccw, 1);
}

// The polar forms: C I J, C, R C, R A, R A C, and R alone (a blend).
bool Translator::arc_polar() {
  const bool ccw = work_.motion() == 3;
  const Vec2 p0 = xy(work_.pos);
  if (words_.has('R')) return tangent_arc(p0, ccw);
  if (!words_.has('C')) {
    return error(core::Code::ArcMissingCenter, 0,
                 "an arc needs X Y with I J or R, or the polar words C, R C, R A, R A C or R");
  }
  if (words_.has('A')) {
    return error(core::Code::MissingWord, words_.col('A'), "A in an arc needs R");
  }
  const Vec2 center{words_.has('I') ? mm(words_.get('I')) : 0.0,
                    words_.has('J') ? mm(words_.get('J')) : 0.0};
  return swept_arc(p0, center, words_.get('C'), ccw);
}

// R C, R A, R A C and R alone: radius R, tangent at p0 to the direction of
// travel (R A C: to A). R alone holds a blend arc for the next block.
bool Translator::tangent_arc(Vec2 p0, bool ccw) {
  const double r = mm(words_.get('R'));
  if (!(r > 0.0)) {
    return error(core::Code::BadWordValue, words_.col('R'), "arc radius must be positive");
  }
  double dir = 0.0;
  if (words_.has('A') && words_.has('C')) {
    dir = words_.get('A');
  } else if (const auto heading = work_.direction.degrees()) {
    dir = *heading;
  } else {
    return error(core::Code::NoTangentDirection, words_.col('R'),
                 "a tangent arc with no previous move to be tangent to");
  }
  const Vec2 n = ccw ? Vec2{-std::sin(rad(dir)), std::cos(rad(dir))}
                     : Vec2{std::sin(rad(dir)), -std::cos(rad(dir))};
  const Vec2 center{p0.x + r * n.x, p0.y + r * n.y};
  if (words_.has('C')) return swept_arc(p0, center, words_.get('C'), ccw);
  if (words_.has('A')) {
    const double sweep = positive_sweep(ccw ? words_.get('A') - dir : dir - words_.get('A'));
    if (sweep >= 360.0 - 1e-9) {
      return error(core::Code::ArcZeroLength, words_.col('A'),
                   "the arc would end in the direction it starts: A equals the direction "
                   "of travel");
    }
    return swept_arc(p0, center, sweep, ccw);
  }
  if (words_.has('I') || words_.has('J') || words_.has('Z')) {
    return error(core::Code::UnusedWord, 0, "a blend arc (R alone) takes no I, J or Z");
  }
  work_.blend = PendingBlend{run_.loc(), center, r, ccw, work_.pos};
  return true;
}

// An arc from p0 about `center` through `sweep` degrees (more than 360:
// whole turns and the rest) in the G02/G03 sense.
bool Translator::swept_arc(Vec2 p0, Vec2 center, double sweep, bool ccw) {
  if (!(sweep > 0.0) || sweep > 360.0 * 1000) {
    return error(core::Code::BadWordValue, words_.col('C'),
                 "the sweep C must be positive (G02 or G03 gives the direction)");
  }
  const double r = core::distance(p0, center);
  if (r < 1e-9) {
    return error(core::Code::ArcZeroLength, 0, "arc of zero radius: the centre is the start point");
  }
  const double a0 = deg(std::atan2(p0.y - center.y, p0.x - center.x));
  const double turns_exact = sweep / 360.0;
  const int turns = std::max(1, static_cast<int>(std::ceil(turns_exact - 1e-9)));
  const bool whole = std::fabs(turns_exact - std::round(turns_exact)) < 1e-9;
  const Vec2 q = whole ? p0 : polar(center, r, ccw ? a0 + sweep : a0 - sweep);
  Vec3 end = cartesian_end(work_.pos);
  end.x = q.x;
  end.y = q.y;
  return emit_arc(end, center, ccw, turns);
}

// The R-only arc held from the previous block, now that the next move's end
// is known: it runs on to where its tangent passes through that end.
bool Translator::blend(const Vec3& next_end) {
  const PendingBlend b = *work_.blend;
  work_.blend.reset();
  const Vec2 q = xy(next_end);
  const double dq = core::distance(q, b.center);
  if (dq <= b.radius + 1e-9) {
    run_.at(b.loc);
    return error(core::Code::BlendNeedsMove, 0,
                 "the next move ends inside the blend arc's circle: no tangent reaches it");
  }
  const double phi = std::atan2(q.y - b.center.y, q.x - b.center.x);
  const double alpha = std::acos(b.radius / dq);
  // Of the two tangent points, the one where the arc's direction of travel
  // points to the end.
  double t = 0.0;
  for (const double cand : {phi + alpha, phi - alpha}) {
    const Vec2 tp{b.center.x + b.radius * std::cos(cand), b.center.y + b.radius * std::sin(cand)};
    const Vec2 dir =
        b.ccw ? Vec2{-std::sin(cand), std::cos(cand)} : Vec2{std::sin(cand), -std::cos(cand)};
    if ((q.x - tp.x) * dir.x + (q.y - tp.y) * dir.y > 0) t = cand;
  }
  if (!hand()) return false;  // the words before the move, at their own block
  const core::SourceLoc here = run_.loc();
  at(b.loc);
  const Vec3 end{b.center.x + b.radius * std::cos(t), b.center.y + b.radius * std::sin(t),
                 b.start.z};
  const bool ok = emit_arc(end, b.center, b.ccw, 1);
  at(here);
  return ok;
}

bool Translator::emit_line(const Vec3& end, bool rapid) {
  if (!hand_move(rapid ? 0 : 1, work_.tf.apply(end))) return false;
  const Vec2 d{end.x - work_.pos.x, end.y - work_.pos.y};
  // hypot is at least the larger component: most moves are told by it.
  if (std::fabs(d.x) > 1e-9 || std::fabs(d.y) > 1e-9 || std::hypot(d.x, d.y) > 1e-9)
    work_.direction.set_step(d);
  work_.pos = end;
  return true;
}

bool Translator::emit_arc(const Vec3& end, Vec2 center, bool ccw, int turns) {
  if (!work_.tf.uniform()) {
    return error(core::Code::UnequalScaleArc, 0,
                 fmt::format("an arc under G72 with unequal factors (X {}, Y {}): it would be "
                             "an ellipse",
                             work_.tf.scale_x, work_.tf.scale_y));
  }
  const Vec3 m = work_.tf.apply(end);
  const Vec2 mc = work_.tf.apply(center);
  // The arc starts where the last move left the tool: after a new mirror,
  // scale or rotation that is not the programmed point transformed.
  const Vec2 from = xy(work_.machine_at);
  const double off = std::fabs(core::distance(from, mc) - core::distance(xy(m), mc));
  if (off > kOnCircle) {
    return error(core::Code::ArcRadiusMismatch, 0,
                 fmt::format("the arc starts where the last move left the tool, ({:.4f}, "
                             "{:.4f}), {:.4f} mm off its circle: the mirror, scale or rotation "
                             "changed since that move; move to a point first",
                             from.x, from.y, off));
  }
  const bool machine_ccw = ccw != work_.tf.flips();
  if (!hand_arc(m, mc, machine_ccw, turns)) return false;
  const double ae = std::atan2(end.y - center.y, end.x - center.x);
  work_.direction.set_degrees(deg(ae) + (ccw ? 90.0 : -90.0));
  work_.pos = end;
  return true;
}

}  // namespace usina::gcode::romi
