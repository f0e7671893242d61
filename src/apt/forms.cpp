#include "apt/forms.hpp"

#include <cmath>

namespace usina::apt::forms {
namespace {

bool is_geom(const Arg& a, GeomType t) {
  return a.kind == Arg::Kind::Geom && a.geom.type == t;
}

bool is_word(const Arg& a, std::initializer_list<std::string_view> words) {
  if (a.kind != Arg::Kind::Word) return false;
  for (std::string_view w : words)
    if (a.word == w) return true;
  return false;
}

bool item_matches(const Arg& a, std::string_view item) {
  if (item == "n") return a.kind == Arg::Kind::Number;
  if (item == "p") return is_geom(a, GeomType::Point);
  if (item == "l") return is_geom(a, GeomType::Line);
  if (item == "c") return is_geom(a, GeomType::Circle);
  if (item == "pl") return is_geom(a, GeomType::Plane);
  if (item == "v") return is_geom(a, GeomType::Vector);
  if (item == "pat") return is_geom(a, GeomType::Pattern);
  if (item == "sel") return a.kind == Arg::Kind::Word && is_selector(a.word);
  if (item == "side") return is_word(a, {"LEFT", "RIGHT"});
  if (item == "io") return is_word(a, {"IN", "OUT"});
  if (item == "ls") return is_word(a, {"LARGE", "SMALL"});
  if (item == "ax") return is_word(a, {"XAXIS", "YAXIS"});
  return a.kind == Arg::Kind::Word && a.word == item;
}

}  // namespace

bool match(const std::vector<Arg>& args, std::initializer_list<std::string_view> pattern) {
  if (args.size() != pattern.size()) return false;
  std::size_t i = 0;
  for (std::string_view item : pattern)
    if (!item_matches(args[i++], item)) return false;
  return true;
}

GeomError no_solution(std::string message) {
  return {core::Code::AptNoSolution, std::move(message)};
}

GeomError not_built(std::string_view form) {
  return {core::Code::AptNotSupported,
          "usina's APT does not compute " + std::string(form) + " yet; define it another way"};
}

std::string describe(const std::vector<Arg>& args) {
  std::string s;
  for (const Arg& a : args) {
    if (!s.empty()) s += ", ";
    if (a.kind == Arg::Kind::Number) s += "number";
    if (a.kind == Arg::Kind::Word) s += a.word;
    if (a.kind == Arg::Kind::Geom) s += type_name(a.geom.type);
  }
  return s.empty() ? "nothing" : s;
}

}  // namespace usina::apt::forms

namespace usina::apt {

GeomResult define(std::string_view major, const std::vector<Arg>& args, double zsurf,
                  std::size_t* pattern_budget) {
  GeomResult r = tl::make_unexpected(GeomError{});
  if (major == "POINT") r = forms::point_form(args, zsurf);
  if (major == "LINE") r = forms::line_form(args);
  if (major == "CIRCLE") r = forms::circle_form(args, zsurf);
  if (major == "PLANE") r = forms::plane_form(args);
  if (major == "VECTOR") r = forms::vector_form(args);
  std::size_t none = 0;
  if (major == "PATERN") r = forms::pattern_form(args, pattern_budget ? *pattern_budget : none);
  if (!r && r.error().message.empty()) {
    r.error().message = std::string(major) + "/" + forms::describe(args) + ": no form of " +
                        std::string(major) +
                        " takes these arguments (IBM error 1000, method of definition unknown); "
                        "docs/apt.md lists the forms";
  }
  if (r) {
    for (double v : canonical(*r))
      if (!std::isfinite(v))
        return tl::make_unexpected(forms::no_solution(std::string(major) + " has no finite value"));
  }
  return r;
}

}  // namespace usina::apt
