// The motions of a CL text file: GOTO, FROM, GODLTA, CIRCLE and its end
// point, CYCLE (docs/apt.md, "CL files of other CAM systems").
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "apt/cl_text_reader.hpp"
#include "apt/vocabulary.hpp"

namespace usina::apt::detail {
namespace {

Vec minus(Vec a, Vec b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

double dot(Vec a, Vec b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// The distance of `p` from the axis through `c` along unit `n`.
double off_axis(Vec p, Vec c, Vec n) {
  const Vec d = minus(p, c);
  const double a = dot(d, n);
  return std::sqrt(std::max(0.0, dot(d, d) - a * a));
}

bool all_numbers(const ClStatement& st) {
  return std::all_of(st.args.begin(), st.args.end(),
                     [](const ClArg& a) { return a.kind == ClArg::Kind::Number; });
}

// The number after the word `w` in the arguments.
std::optional<double> after(const ClStatement& st, std::string_view w) {
  for (std::size_t i = 0; i + 1 < st.args.size(); ++i)
    if (st.args[i].kind == ClArg::Kind::Word && st.args[i].text == w &&
        st.args[i + 1].kind == ClArg::Kind::Number)
      return st.args[i + 1].value;
  return std::nullopt;
}

std::string at_text(Vec p) {
  return fmt::format("({:g}, {:g}, {:g})", p.x, p.y, p.z);
}

}  // namespace

// GOTO/x,y,z[,i,j,k] and FROM/...: a tool axis other than +Z (5-axis) is
// not read; NX leaves i,j,k out while they do not change.
bool ClTextReader::point(const ClStatement& st, int sub) {
  const std::size_t n = st.args.size();
  if (!all_numbers(st) || (n != 3 && n != 6))
    return fail(core::Code::ClBadArgument, st.loc,
                fmt::format("{}/ takes x,y,z or x,y,z,i,j,k ({} argument(s) given)", st.major, n));
  const Vec p{st.args[0].value, st.args[1].value, st.args[2].value};
  if (n == 6) {
    const Vec k{st.args[3].value, st.args[4].value, st.args[5].value};
    const double len = std::sqrt(dot(k, k));
    tilted_ =
        !(len > 0.0) || std::fabs(k.x / len) > 1e-6 || std::fabs(k.y / len) > 1e-6 || k.z < 0.0;
  }
  const std::optional<Vec> from = at_;
  at_ = p;
  if (tilted_) {
    circle_.reset();
    return fail(core::Code::ClNotSupported, st.loc,
                "a tool axis other than +Z (a multi-axis motion) is not read: usina's canon "
                "stream is the tool tip of a 3-axis machine");
  }
  if (circle_ && sub == 5) return arc_to(st, p, from);
  return add(cls::kMotion, sub,
             {ClWord::number(0.0), ClWord::number(0.0), ClWord::number(p.x), ClWord::number(p.y),
              ClWord::number(p.z)},
             st.loc);
}

// GODLTA/dz (along the tool axis) or dx,dy,dz: a GOTO from where the tool is.
bool ClTextReader::godlta(const ClStatement& st) {
  const std::size_t n = st.args.size();
  if (!all_numbers(st) || (n != 1 && n != 3))
    return fail(core::Code::ClBadArgument, st.loc, "GODLTA/ takes dz or dx,dy,dz");
  if (!at_)
    return fail(core::Code::ClBadArgument, st.loc,
                "GODLTA/ moves from where the tool is, and no motion has said it yet");
  const Vec d = n == 1 ? Vec{0, 0, st.args[0].value}
                       : Vec{st.args[0].value, st.args[1].value, st.args[2].value};
  const Vec to{at_->x + d.x, at_->y + d.y, at_->z + d.z};
  if (std::max({std::fabs(to.x), std::fabs(to.y), std::fabs(to.z)}) > kLargestClNumber)
    return fail(core::Code::ClTooLarge, st.loc,
                fmt::format("GODLTA/ goes to {}, beyond {:g}", at_text(to), kLargestClNumber));
  at_ = to;
  return add(cls::kMotion, 5,
             {ClWord::number(0.0), ClWord::number(0.0), ClWord::number(at_->x),
              ClWord::number(at_->y), ClWord::number(at_->z)},
             st.loc);
}

// CIRCLE/xc,yc,zc,i,j,k[,r,...]: the arc to the next GOTO's point. NX's
// axis runs clockwise, the others' counter-clockwise (research/apt.md §0).
bool ClTextReader::circle(const ClStatement& st) {
  const auto number = [&st](std::size_t i) {
    return i < st.args.size() && st.args[i].kind == ClArg::Kind::Number;
  };
  for (std::size_t i = 0; i < 6; ++i)
    if (!number(i))
      return fail(core::Code::ClBadArgument, st.loc,
                  "CIRCLE/ takes xc,yc,zc,i,j,k[,r,...]: the centre, the axis and the radius");
  Vec axis{st.args[3].value, st.args[4].value, st.args[5].value};
  const double len = std::sqrt(dot(axis, axis));
  if (!(len > 1e-9)) return fail(core::Code::ClBadArgument, st.loc, "CIRCLE/'s axis i,j,k is 0");
  const double sense = dialect_ == ClDialect::Clsf ? -1.0 : 1.0;
  axis = Vec{sense * axis.x / len, sense * axis.y / len, sense * axis.z / len};
  PendingCircle c{{st.args[0].value, st.args[1].value, st.args[2].value}, axis, {}, st.loc};
  if (number(6)) c.radius = st.args[6].value;
  circle_ = c;
  return false;  // its records go with the GOTO of its end
}

// The GOTO after a CIRCLE: the circle's record, then the end point. Its
// start and end must lie on the circle (within 0.002 or 0.1 % of the
// radius); an end off it is an error and the move is taken straight.
bool ClTextReader::arc_to(const ClStatement& st, Vec p, std::optional<Vec> from) {
  const PendingCircle c = *circle_;
  circle_.reset();
  const std::vector<ClWord> end{ClWord::number(0.0), ClWord::number(0.0), ClWord::number(p.x),
                                ClWord::number(p.y), ClWord::number(p.z)};
  if (!from) {
    fail(core::Code::ClBadArc, c.loc,
         "CIRCLE/ before any motion: the arc has no start; its end is taken as a straight move");
    return add(cls::kMotion, 5, end, st.loc);
  }
  const double r0 = off_axis(*from, c.center, c.axis);
  const double r = c.radius.value_or(r0);
  const double r1 = off_axis(p, c.center, c.axis);
  const double tol = std::max(0.002, 0.001 * r);
  if (!(r > tol) || r > kLargestClNumber || std::fabs(r0 - r) > tol || std::fabs(r1 - r) > tol) {
    fail(core::Code::ClBadArc, st.loc,
         fmt::format("the arc of CIRCLE/ (line {}) does not fit: radius {:g} about {}, its start "
                     "{} at {:g}, its end {} at {:g}; the move is taken straight",
                     c.loc.line, r, at_text(c.center), at_text(*from), r0, at_text(p), r1));
    return add(cls::kMotion, 5, end, st.loc);
  }
  add(cls::kSurface, 2,
      {ClWord::number(0.0), ClWord::vocabulary(4), ClWord::vocabulary(9), ClWord::chars(""),
       ClWord::number(0.0), ClWord::number(c.center.x), ClWord::number(c.center.y),
       ClWord::number(c.center.z), ClWord::number(c.axis.x), ClWord::number(c.axis.y),
       ClWord::number(c.axis.z), ClWord::number(r)},
      c.loc);
  return add(cls::kMotion, 5, end, st.loc);
}

bool ClTextReader::circle_left_out(const char* why) {
  const core::SourceLoc at = circle_->loc;
  circle_.reset();
  return fail(core::Code::ClBadArc, at, fmt::format("CIRCLE/ is left out: {}", why));
}

// CYCLE/type,...,FEDTO,d,...,RAPTO,r,...,MMPM,f (NX, SolidWorks): the
// drilling cycle of the canon stream, depth |d| below each point (NX writes
// it negative, SolidWorks positive), clearance r above it. Other cycles
// (CYCLE/OFF, IBM's CYCLE/DRILL,depth,IPM,f,clearance) are post words.
bool ClTextReader::cycle(const ClStatement& st) {
  const std::optional<double> fedto = after(st, "FEDTO");
  cycle_on_ = false;
  if (!fedto) return post_word(st, post_code("CYCLE"));
  std::optional<double> f = feed_;
  int unit = feed_unit_;
  for (const char* u : {"MMPM", "IPM"}) {
    if (const auto v = after(st, u)) {
      f = v;
      unit = std::string_view(u) == "IPM" ? kIpm : kMmpm;
    }
  }
  if (!f)
    return fail(core::Code::ClBadArgument, st.loc,
                "CYCLE/ gives no feed rate (MMPM or IPM) and no FEDRAT came before it");
  cycle_on_ = true;
  return add(
      cls::kPost, 1054,
      {ClWord::vocabulary(kDrill), ClWord::number(std::fabs(*fedto)), ClWord::vocabulary(unit),
       ClWord::number(*f), ClWord::number(after(st, "RAPTO").value_or(0.0))},
      st.loc);
}

void ClTextReader::end() {
  if (circle_ && !stop_) circle_left_out("the file ends before the GOTO/ of its end");
}

}  // namespace usina::apt::detail
