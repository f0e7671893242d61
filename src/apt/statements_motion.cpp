// FROM, GOTO, GODLTA, CUTTER, INTOL/OUTTOL, ZSURF and the post-processor
// words: their CL records.
#include <algorithm>
#include <cmath>
#include <string>

#include "apt/patern.hpp"
#include "apt/statements.hpp"
#include "apt/vocabulary.hpp"

namespace usina::apt {
namespace {

bool all_numbers(const std::vector<Arg>& args) {
  return std::all_of(args.begin(), args.end(),
                     [](const Arg& a) { return a.kind == Arg::Kind::Number; });
}

}  // namespace

bool StatementRunner::motion(const Token& word, const std::vector<Arg>& args) {
  if (!args.empty() && args[0].kind == Arg::Kind::Geom && args[0].geom.type == GeomType::Pattern) {
    if (word.text == "GOTO") return goto_pattern(word, args);
    return fail(word.loc, core::Code::AptBadArgument,
                "FROM takes a point; GOTO/pattern goes to a pattern's points");
  }
  const bool point =
      args.size() == 1 && args[0].kind == Arg::Kind::Geom && args[0].geom.type == GeomType::Point;
  const bool numbers = (args.size() == 2 || args.size() == 3) && all_numbers(args);
  if (!point && !numbers) {
    // GOTO/point,f or GOTO/x,y,z,f: the feed rate IBM's form allows after the point.
    const bool feed = (args.size() == 2 && args[0].kind == Arg::Kind::Geom) ||
                      (args.size() == 4 && all_numbers(args));
    return fail(word.loc, feed ? core::Code::AptNotSupported : core::Code::AptBadArgument,
                word.text + " takes a point or x,y[,z]" +
                    (feed ? std::string(" (usina's APT does not take a feed rate after the "
                                        "point yet; give FEDRAT/f before it)")
                          : std::string()));
  }
  core::Vec3 p;
  if (point) {
    p = {args[0].geom.c[0], args[0].geom.c[1], args[0].geom.c[2]};
  } else {
    p = {args[0].num, args[1].num, args.size() == 3 ? args[2].num : zsurf_};
  }
  const bool named = point && !args[0].name.empty();
  if (word.text == "FROM") {
    at_ = p;
    lost_at_ = 0;
  } else {
    turned(p);
  }
  add(cls::kMotion, word.text == "FROM" ? 3 : 5,
      {named ? symbol_word(args[0].name) : ClWord::number(0.0), ClWord::number(0.0),
       ClWord::number(p.x), ClWord::number(p.y), ClWord::number(p.z)});
  return true;
}

// The points as 5000 5 records (80 points a record, more in 5000 6 ones),
// named by the pattern, as a contour's points.
void StatementRunner::write_run(const ClWord& name, const std::vector<core::Vec3>& points) {
  constexpr std::size_t kPerRecord = 80;
  for (std::size_t i = 0; i < points.size(); i += kPerRecord) {
    std::vector<ClWord> w{name, ClWord::number(0.0)};
    for (std::size_t k = i; k < points.size() && k < i + kPerRecord; ++k) {
      w.push_back(ClWord::number(points[k].x));
      w.push_back(ClWord::number(points[k].y));
      w.push_back(ClWord::number(points[k].z));
    }
    add(cls::kMotion, i == 0 ? 5 : 6, std::move(w));
  }
}

// GOTO/pattern: each point a GOTO (under CYCLE/DRILL each is drilled). A
// point with AVOID,h is reached over the rise: up h where the tool is,
// across at that height and down, the two moves a RAPID and its own ISN
// record after them so that the point itself is a GOTO again.
bool StatementRunner::goto_pattern(const Token& word, const std::vector<Arg>& args) {
  // The work of a GOTO/pattern is its pattern's size, whatever it visits:
  // bounded before it is done.
  visited_ += args[0].geom.points.size();
  if (visited_ > kMostProgramPatternPoints)
    return fail(word.loc, core::Code::AptBadArgument,
                "the program's GOTO/pattern statements go through more than " +
                    std::to_string(kMostProgramPatternPoints) + " points of patterns");
  const auto visits = pattern_visits(args[0].geom, {args.begin() + 1, args.end()});
  if (!visits) return fail(word.loc, visits.error().code, visits.error().message);
  const ClWord name = args[0].name.empty() ? ClWord::number(0.0) : symbol_word(args[0].name);
  std::vector<core::Vec3> run;
  for (const PatternVisit& v : *visits) {
    if (v.avoid > 0.0) {
      write_run(name, run);
      run.clear();
      const core::Vec3 up{0.0, 0.0, v.avoid};
      add(cls::kPost, 5, {});
      write_run(name, lost_at_ == 0 ? std::vector{at_ + up, v.p + up} : std::vector{v.p + up});
      add(cls::kSource, isn_, {ClWord::number(0.0), ClWord::chars("")});
    }
    run.push_back(v.p);
    turned(v.p);
  }
  write_run(name, run);
  return true;
}

bool StatementRunner::godlta(const Token& word, const std::vector<Arg>& args) {
  if (!all_numbers(args) || (args.size() != 1 && args.size() != 3))
    return fail(word.loc, core::Code::AptBadArgument,
                "GODLTA takes dz (along the tool axis, +Z) or dx,dy,dz");
  if (lost_at_ != 0)
    return fail(word.loc, core::Code::AptNotSupported,
                "GODLTA moves from the end of the motion on line " + std::to_string(lost_at_) +
                    ", which usina's APT did not run; the start is unknown");
  // One number moves along the tool axis; IBM names the record TLAXIS.
  const bool axial = args.size() == 1;
  turned(axial ? at_ + core::Vec3{0.0, 0.0, args[0].num}
               : at_ + core::Vec3{args[0].num, args[1].num, args[2].num});
  add(cls::kMotion, 5,
      {axial ? symbol_word("TLAXIS") : ClWord::number(0.0), ClWord::number(0.0),
       ClWord::number(at_.x), ClWord::number(at_.y), ClWord::number(at_.z)});
  return true;
}

bool StatementRunner::control(const Token& word, const std::vector<Arg>& args) {
  const std::string& w = word.text;
  if (w == "ZSURF") {
    writes_ = false;
    if (args.size() == 1 && args[0].kind == Arg::Kind::Number) {
      zsurf_ = args[0].num;
      return true;
    }
    const bool horizontal = args.size() == 1 && args[0].kind == Arg::Kind::Geom &&
                            args[0].geom.type == GeomType::Plane && args[0].geom.c[2] != 0.0;
    if (!horizontal)
      return fail(word.loc, core::Code::AptBadArgument,
                  "ZSURF takes a number or a plane that is not vertical");
    const auto& c = args[0].geom.c;
    zsurf_ = c[3] / c[2];  // the plane's z at x = y = 0
    return true;
  }
  const std::size_t most = w == "CUTTER" ? 7 : 4;
  if (args.empty() || args.size() > most || !all_numbers(args))
    return fail(word.loc, core::Code::AptBadArgument,
                w + " takes 1 to " + std::to_string(most) + " numbers");
  std::vector<ClWord> out;
  for (const Arg& a : args)
    out.push_back(ClWord::number(a.num));
  // A tolerance is given for PS, DS, CS1, CS2: the last one given stands for the rest.
  while (w != "CUTTER" && out.size() < 4)
    out.push_back(out.back());
  // The drive surface's values steer contouring: the radius of the
  // cutter, the tolerances' second value (PS, DS, CS1, CS2).
  if (w == "CUTTER") cutter_radius_ = std::fabs(args[0].num) / 2.0;
  if (w == "INTOL") intol_ = std::fabs(out[1].real);
  if (w == "OUTTOL") outtol_ = std::fabs(out[1].real);
  add(cls::kControl, w == "CUTTER" ? 6 : (w == "INTOL" ? 4 : 5), std::move(out));
  return true;
}

bool StatementRunner::post(const Token& word, int code, const std::vector<Arg>& args) {
  std::vector<ClWord> out;
  for (const Arg& a : args) {
    if (a.kind == Arg::Kind::Geom)
      return fail(
          a.loc, core::Code::AptBadArgument,
          word.text + " takes numbers and words, not a " + std::string(type_name(a.geom.type)));
    if (a.kind == Arg::Kind::Number) {
      out.push_back(ClWord::number(a.num));
    } else if (const auto c = minor_word_code(a.word)) {
      out.push_back(ClWord::vocabulary(*c));
    } else {
      out.push_back(ClWord::chars(a.word.substr(0, 6)));
    }
  }
  add(cls::kPost, code, std::move(out));
  return true;
}

}  // namespace usina::apt
