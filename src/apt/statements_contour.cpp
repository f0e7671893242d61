// Contouring: the startup GO/ and the motions along a drive surface to a
// check surface (GOLFT, GORGT, GOFWD, GOBACK), the modal words that steer
// them (TLLFT, TLRGT, TLON, PSIS, NOPS, AUTOPS, INDIRV, INDIRP) and the
// implicit check surface, taken from the next motion's drive surface.
#include <algorithm>
#include <cmath>
#include <string>

#include "apt/statements.hpp"

namespace usina::apt {
namespace {

// At most this many points in one circular motion (a tolerance of 1e-9 on
// a large circle would otherwise write millions).
constexpr std::size_t kMostArcPoints = 100'000;
// ... and this many in a whole program (the CL model holds them all: a
// million points is about 150 MB).
constexpr std::size_t kMostProgramArcPoints = 1'000'000;
// IBM's processor widens the drive surface's tolerance band by 0.00005
// when the tool's place in the band computes outside 0-100 % (its ARLM2),
// and narrows it back for TANTO (its ASEGMT). On a concave circle with
// INTOL 0 the tool sits at the band's edge, and the IBM run shows the
// widening there (Ex 10.1's C2: 14 steps, not 15).
constexpr double kIbmWiden = 0.00005;
// Points in one motion record; more go to continuation records (5000 6).
constexpr std::size_t kPointsPerRecord = 80;

bool is_drive_word(std::string_view w) {
  return w == "GOLFT" || w == "GORGT" || w == "GOFWD" || w == "GOBACK";
}

Turn turn_of(std::string_view w) {
  if (w == "GOLFT") return Turn::Left;
  if (w == "GORGT") return Turn::Right;
  if (w == "GOBACK") return Turn::Back;
  return Turn::Forward;
}

std::optional<Stop> stop_of(const Arg& a) {
  if (a.kind != Arg::Kind::Word) return std::nullopt;
  if (a.word == "TO") return Stop::To;
  if (a.word == "ON") return Stop::On;
  if (a.word == "PAST") return Stop::Past;
  if (a.word == "TANTO" || a.word == "DSTAN") return Stop::Tanto;
  return std::nullopt;
}

bool is_geom(const std::vector<Arg>& args, std::size_t i) {
  return i < args.size() && args[i].kind == Arg::Kind::Geom;
}

// Whether every point is a finite number (huge coordinates, radii or
// cutters overflow in the offsets).
bool all_finite(const std::vector<Vec2>& points, double z) {
  for (const Vec2& p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  return std::isfinite(z);
}

ClWord name_word(const Arg& a) {
  return a.name.empty() ? ClWord::number(0.0) : symbol_word(a.name);
}

}  // namespace

bool StatementRunner::known_start(const Token& word) {
  if (lost_at_ == 0) return true;
  return fail(word.loc, core::Code::AptNotSupported,
              word.text + " moves from the end of the motion on line " + std::to_string(lost_at_) +
                  ", which usina's APT did not run; the start is unknown");
}

void StatementRunner::turned(core::Vec3 to) {
  const Vec2 d{to.x - at_.x, to.y - at_.y};
  if (core::norm(d) > 1e-9) fwd_ = d / core::norm(d);
  at_ = to;
  lost_at_ = 0;
}

void StatementRunner::write_points(const Arg& ds, const std::vector<Vec2>& points, double z) {
  for (std::size_t i = 0; i < points.size(); i += kPointsPerRecord) {
    std::vector<ClWord> w{name_word(ds), ClWord::number(0.0)};
    for (std::size_t k = i; k < points.size() && k < i + kPointsPerRecord; ++k) {
      w.push_back(ClWord::number(points[k].x));
      w.push_back(ClWord::number(points[k].y));
      w.push_back(ClWord::number(z));
    }
    add(cls::kMotion, i == 0 ? 5 : 6, std::move(w));
  }
}

// INDIRV/i,j,k (or a vector), INDIRP/point: the sense of direction the
// next GOLFT, GORGT, GOFWD or GOBACK turns from.
bool StatementRunner::direction(const std::string& w, const std::vector<Arg>& args,
                                const core::SourceLoc& at) {
  std::optional<Vec2> d;
  const bool geom = args.size() == 1 && args[0].kind == Arg::Kind::Geom;
  const bool numbers = (args.size() == 2 || args.size() == 3) &&
                       args[0].kind == Arg::Kind::Number && args[1].kind == Arg::Kind::Number;
  if (w == "INDIRV" && geom && args[0].geom.type == GeomType::Vector)
    d = Vec2{args[0].geom.c[0], args[0].geom.c[1]};
  if (w == "INDIRV" && numbers) d = Vec2{args[0].num, args[1].num};
  if (w == "INDIRP" && geom && args[0].geom.type == GeomType::Point)
    d = Vec2{args[0].geom.c[0] - at_.x, args[0].geom.c[1] - at_.y};
  if (w == "INDIRP" && numbers) d = Vec2{args[0].num - at_.x, args[1].num - at_.y};
  if (!d || core::norm(*d) < 1e-9)
    return fail(at, core::Code::AptBadArgument,
                w + (w == "INDIRV" ? " takes a vector (i,j,k) with an x or y part"
                                   : " takes a point other than the tool's"));
  fwd_ = *d / core::norm(*d);
  return true;
}

bool StatementRunner::modal(const std::string& w, const std::vector<Arg>& args,
                            const core::SourceLoc& at) {
  const bool none = args.empty();
  if (w == "TLLFT" || w == "TLRGT" || w == "TLON") {
    side_ = w == "TLLFT" ? 1 : (w == "TLRGT" ? -1 : 0);
  } else if (w == "NOPS") {
    nops_ = true;
  } else if (w == "AUTOPS") {
    ps_z_ = at_.z;
  } else if (w == "PSIS") {
    const auto z = args.size() == 1 && args[0].kind == Arg::Kind::Geom ? horizontal_z(args[0].geom)
                                                                       : std::nullopt;
    if (!z)
      return fail(at, core::Code::AptNotSupported,
                  "PSIS takes a horizontal plane (usina's APT is 2.5D: no other part surface)");
    ps_z_ = *z;
    return true;
  } else if (w == "INDIRV" || w == "INDIRP") {
    return direction(w, args, at);
  }
  return none || fail(at, core::Code::AptBadArgument, w + " takes no arguments");
}

// GO/[mod,]DS[,[mod,]PS[,[mod,]CS]][,feed]: the tool put against up to
// three surfaces, the drive and check surfaces in the plane, the part
// surface a horizontal plane that gives the tool end's z.
bool StatementRunner::startup(const Token& word, const std::vector<Arg>& args) {
  std::vector<std::pair<Stop, Arg>> surfaces;
  std::optional<double> feed;
  std::size_t i = 0;
  while (i < args.size() && surfaces.size() < 3) {
    const auto stop = stop_of(args[i]);
    if (stop) ++i;
    if (!is_geom(args, i)) break;
    surfaces.emplace_back(stop.value_or(Stop::To), args[i++]);
  }
  if (i + 1 == args.size() && args[i].kind == Arg::Kind::Number) feed = args[i++].num;
  if (surfaces.empty() || i != args.size())
    return fail(word.loc, core::Code::AptBadArgument,
                "GO takes [TO|ON|PAST,] a drive surface, then optionally the part surface and a "
                "check surface, each after its own TO, ON or PAST, and a feed rate");
  const auto ds = curve_of(surfaces[0].second.geom);
  const auto cs = surfaces.size() == 3 ? curve_of(surfaces[2].second.geom) : std::nullopt;
  const auto ps = surfaces.size() >= 2 ? horizontal_z(surfaces[1].second.geom) : std::nullopt;
  if (!ds || (surfaces.size() == 3 && !cs) || (surfaces.size() >= 2 && !ps))
    return fail(word.loc, core::Code::AptNotSupported,
                "usina's APT is 2.5D: drive and check surfaces are lines, circles or vertical "
                "planes, the part surface a horizontal plane");
  if (!known_start(word)) return false;
  std::string why;
  const Vec2 te{at_.x, at_.y};
  const auto xy =
      cs ? startup_two(*ds, surfaces[0].first, *cs, surfaces[2].first, te, cutter_radius_, why)
         : startup_one(*ds, te, surfaces[0].first, cutter_radius_, why);
  if (!xy) return fail(word.loc, core::Code::AptNoSolution, "GO: " + why);
  const double part_z = ps.value_or(ps_z_);
  const double z = nops_ ? at_.z : part_z;
  if (!all_finite({*xy}, z))
    return fail(word.loc, core::Code::AptNoSolution, "GO: the numbers overflow (out of range)");
  ps_z_ = part_z;
  nops_ = false;
  if (feed) add(cls::kPost, 1009, {ClWord::number(*feed)});
  write_points(surfaces[0].second, {*xy}, z);
  turned({xy->x, xy->y, z});
  return true;
}

std::optional<StatementRunner::Drive> StatementRunner::read_drive(const Token& word,
                                                                  const std::vector<Arg>& args) {
  Drive d;
  d.word = word;
  d.turn = turn_of(word.text);
  d.side = side_;
  std::size_t i = 1;
  const bool stop_given = i < args.size() && stop_of(args[i]);
  if (stop_given) d.stop = *stop_of(args[i++]);
  const bool nth = i + 1 < args.size() && args[i].kind == Arg::Kind::Number &&
                   args[i + 1].kind == Arg::Kind::Word && args[i + 1].word == "INTOF";
  if (nth) {
    if (args[i].num < 1.0 || args[i].num > 1000.0 || args[i].num != std::floor(args[i].num)) {
      fail(args[i].loc, core::Code::AptBadArgument, "n INTOF takes a whole number from 1");
      return std::nullopt;
    }
    d.nth = static_cast<int>(args[i].num);
    i += 2;
  }
  if (is_geom(args, i)) d.cs = args[i++];
  if (d.cs && i + 1 == args.size() && args[i].kind == Arg::Kind::Number) d.feed = args[i++].num;
  const bool ok = is_geom(args, 0) && i == args.size() && (d.cs || (!stop_given && !nth));
  if (!ok) {
    const bool several = d.cs && i < args.size();
    fail(word.loc, several ? core::Code::AptNotSupported : core::Code::AptBadArgument,
         several ? word.text + " with several check surfaces is not built (one check surface)"
                 : word.text +
                       " takes a drive surface, then [TO|ON|PAST|TANTO,] [n,INTOF,] a "
                       "check surface and a feed rate");
    return std::nullopt;
  }
  d.ds = args[0];
  if (d.stop == Stop::Tanto && d.nth != 1) {
    fail(word.loc, core::Code::AptBadArgument, "TANTO takes no n INTOF");
    return std::nullopt;
  }
  return d;
}

bool StatementRunner::run_drive(const Drive& d) {
  const Token& word = d.word;
  const auto ds = curve_of(d.ds.geom);
  const auto cs = curve_of(d.cs->geom);
  if (!ds || !cs)
    return fail(word.loc, core::Code::AptNotSupported,
                "usina's APT is 2.5D: drive and check surfaces are lines, circles or vertical "
                "planes");
  if (!known_start(word)) return false;
  if (!fwd_)
    return fail(word.loc, core::Code::AptBadArgument,
                word.text +
                    " has no direction of motion to turn from: start with GO/ or GOTO, "
                    "or give INDIRV");
  std::string why;
  const Vec2 te{at_.x, at_.y};
  const double tol = intol_ + outtol_ + kIbmWiden;
  const auto path = drive_path(*ds, te, *fwd_, d.turn, d.side, cutter_radius_, tol, why);
  const auto end =
      path ? stop_point(*path, *ds, *cs, d.stop, d.nth, cutter_radius_, why) : std::nullopt;
  if (!end) return fail(word.loc, core::Code::AptNoSolution, word.text + ": " + why);
  std::vector<Vec2> points;
  if (path->circle) {
    const bool convex = path->rho > ds->round.r;
    const double widen = !convex && intol_ == 0.0 && d.stop != Stop::Tanto ? kIbmWiden : 0.0;
    const std::size_t left = kMostProgramArcPoints - arc_points_;
    auto seg = segment_arc(*path, te, *end, intol_, outtol_, convex, widen,
                           std::min(kMostArcPoints, left), why);
    if (!seg)
      return fail(word.loc, core::Code::AptNoSolution,
                  word.text + ": " + why +
                      (left < kMostArcPoints
                           ? " (the program's circles have used " + std::to_string(arc_points_) +
                                 " of the " + std::to_string(kMostProgramArcPoints) +
                                 " points a program may write)"
                           : std::string()));
    arc_points_ += seg->size();
    points = std::move(*seg);
  }
  points.push_back(*end);
  if (!all_finite(points, ps_z_))
    return fail(word.loc, core::Code::AptNoSolution,
                word.text + ": the numbers overflow (out of range)");
  if (d.feed) add(cls::kPost, 1009, {ClWord::number(*d.feed)});
  if (path->circle) {
    std::vector<ClWord> w{ClWord::number(0.0), ClWord::vocabulary(4), ClWord::vocabulary(9),
                          name_word(d.ds), ClWord::number(0.0)};
    for (std::size_t k = 0; k < 7; ++k)
      w.push_back(ClWord::number(d.ds.geom.c[k]));
    add(cls::kSurface, 2, std::move(w));
  }
  const double z = ps_z_;
  write_points(d.ds, points, z);
  at_ = {end->x, end->y, z};
  fwd_ = tangent_at(*path, *end);
  return true;
}

bool StatementRunner::contour(const Token& word, const std::vector<Arg>& args) {
  const std::string& w = word.text;
  if (w == "GO") return startup(word, args);
  if (w == "GOUP" || w == "GODOWN") return vertical(word, args);
  if (w == "PSIS" || w == "INDIRV" || w == "INDIRP") return modal(w, args, word.loc);
  auto d = read_drive(word, args);
  if (!d) return false;
  if (!d->cs) {
    deferred_ = Deferred{*d, {}, 0, {}};
    defer_now_ = true;
    return true;
  }
  return run_drive(*d);
}

void StatementRunner::resolve_deferred(const Token& next, const std::vector<Arg>& args) {
  Deferred def = std::move(*deferred_);
  deferred_.reset();
  const core::SourceLoc& at = def.loc;
  if (!is_drive_word(next.text) || !is_geom(args, 0)) {
    fail(at, core::Code::AptBadArgument,
         def.drive.word.text + " has no check surface, and the next statement (line " +
             std::to_string(next.loc.line) +
             ") is not a motion along a drive surface to take it from: give the check surface");
    lost_at_ = static_cast<int>(at.line);
    return;
  }
  // The implied modifier: TO before GOLFT or GORGT, TANTO before GOFWD or GOBACK.
  def.drive.cs = args[0];
  const Turn t = turn_of(next.text);
  def.drive.stop = t == Turn::Left || t == Turn::Right ? Stop::To : Stop::Tanto;
  pending_ = std::move(def.records);
  writes_ = true;
  if (run_drive(def.drive)) {
    commit(def.isn, at);
  } else {
    lost_at_ = static_cast<int>(at.line);
  }
  pending_.clear();
  writes_ = false;
}

void StatementRunner::end_of_program() {
  if (!deferred_) return;
  const Deferred& def = *deferred_;
  fail(def.loc, core::Code::AptBadArgument,
       def.drive.word.text +
           " has no check surface and no motion follows to take it from: give "
           "the check surface");
  deferred_.reset();
}

}  // namespace usina::apt
