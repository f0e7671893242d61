// GOUP and GODOWN in 2.5D (docs/apt.md, "Contouring"): the tool, standing
// at its offset from a vertical drive surface (a line, circle or vertical
// plane), moves along its axis (+Z up, -Z down) until its end lies on a
// horizontal check surface, which then becomes the part surface.
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "apt/statements.hpp"

namespace usina::apt {
namespace {

// As statements_contour.cpp: IBM's widening of the tolerance band.
constexpr double kIbmWiden = 0.00005;

ClWord name_of(const Arg& a) {
  return a.name.empty() ? ClWord::number(0.0) : symbol_word(a.name);
}

}  // namespace

bool StatementRunner::vertical(const Token& word, const std::vector<Arg>& args) {
  const std::string& w = word.text;
  std::size_t i = 1;
  const bool mod = i < args.size() && args[i].kind == Arg::Kind::Word;
  const std::string stop = mod ? args[i++].word : "TO";
  const bool cs = i < args.size() && args[i].kind == Arg::Kind::Geom;
  const bool feed = cs && i + 2 == args.size() && args[i + 1].kind == Arg::Kind::Number;
  const bool shape = !args.empty() && args[0].kind == Arg::Kind::Geom && cs &&
                     (i + 1 == args.size() || feed) && (stop == "TO" || stop == "ON");
  if (!shape)
    return fail(word.loc, stop == "PAST" ? core::Code::AptNotSupported : core::Code::AptBadArgument,
                w + " takes a drive surface, [TO|ON,] a horizontal check surface and a feed rate" +
                    std::string(stop == "PAST" ? " (PAST, the tool's height beyond the plane, is "
                                                 "not built)"
                                               : ""));
  const auto ds = curve_of(args[0].geom);
  const auto z = horizontal_z(args[i].geom);
  if (!ds || !z)
    return fail(word.loc, core::Code::AptNotSupported,
                w + " in usina's 2.5D APT: the drive surface is a line, circle or vertical plane, "
                    "the check surface a horizontal plane");
  if (!known_start(word)) return false;
  const double off = side_ == 0 ? 0.0 : cutter_radius_;
  const double tol = intol_ + outtol_ + kIbmWiden;
  if (std::fabs(distance_to(*ds, {at_.x, at_.y}) - off) > tol)
    return fail(word.loc, core::Code::AptNoSolution,
                w + ": the tool is not at the cutter offset of the drive surface; position it "
                    "first (GO/ or a motion along it)");
  const bool up = w == "GOUP";
  if (up ? *z <= at_.z : *z >= at_.z)
    return fail(word.loc, core::Code::AptNoSolution,
                w + ": the check surface (z " + std::to_string(*z) + ") is not " +
                    (up ? "above" : "below") + " the tool");
  if (feed) add(cls::kPost, 1009, {ClWord::number(args[i + 1].num)});
  at_.z = *z;
  ps_z_ = *z;
  add(cls::kMotion, 5,
      {name_of(args[0]), ClWord::number(0.0), ClWord::number(at_.x), ClWord::number(at_.y),
       ClWord::number(at_.z)});
  return true;
}

}  // namespace usina::apt
