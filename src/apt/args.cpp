#include "apt/args.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "apt/patern.hpp"
#include "apt/vocabulary.hpp"

namespace usina::apt {
namespace {

// Minor words of geometry and motion that the code table of vocabulary.cpp
// does not list.
constexpr std::string_view kMoreMinorWords[] = {
    "XLARGE", "XSMALL", "YLARGE", "YSMALL", "ZLARGE", "ZSMALL", "XYPLAN", "YZPLAN",
    "ZXPLAN", "RTHETA", "THETAR", "INTERC", "SLOPE",  "DSTAN",  "TANTO",  "ADJUST",
    "FEDTO",  "RAPTO",  "RTRCTO", "SFM",    "SMM",    "THRU",   "NOPOST", "ZAXIS",
    "ARC",    "RANDOM", "AVOID",  "OMIT",   "RETAIN"};

}  // namespace

bool is_geometry_word(std::string_view w) {
  return w == "POINT" || w == "LINE" || w == "CIRCLE" || w == "PLANE" || w == "VECTOR" ||
         w == "PATERN";
}

bool is_minor_word(std::string_view w) {
  if (minor_word_code(w)) return true;
  for (std::string_view m : kMoreMinorWords)
    if (m == w) return true;
  return false;
}

bool ArgReader::fail(const Token& t, core::Code code, std::string message) {
  diags_.report({code, core::Severity::Error, t.loc, std::move(message)});
  return false;
}

std::optional<std::vector<Arg>> ArgReader::arguments(bool any_word) {
  any_word_ = any_word;
  std::vector<Arg> out;
  if (at().kind == TokKind::End) return out;
  for (;;) {
    auto a = argument();
    if (!a) return std::nullopt;
    out.push_back(std::move(*a));
    if (at().kind == TokKind::End || is(")")) return out;
    if (!is(",")) {
      fail(at(), core::Code::AptSyntax,
           "expected ',' between arguments, found '" + at().text + "'");
      return std::nullopt;
    }
    ++pos_;
  }
}

std::optional<Arg> ArgReader::argument() {
  const Token& t = at();
  Arg a;
  a.loc = t.loc;
  if (is("(")) {
    const Token& next = toks_[pos_ + 1];
    const bool def =
        next.kind == TokKind::Word && (is_geometry_word(next.text) || toks_[pos_ + 2].text == "=");
    if (def) return nested();
  }
  if (t.kind == TokKind::Word) {
    const bool call = toks_[pos_ + 1].text == "(";
    const auto sym = symbols_.find(t.text);
    if (!call && sym != symbols_.end() && !sym->second.scalar) {
      ++pos_;
      a.kind = Arg::Kind::Geom;
      a.geom = sym->second.geom;
      a.name = t.text;
      return a;
    }
    if (!call && sym == symbols_.end() && (is_minor_word(t.text) || any_word_)) {
      ++pos_;
      a.kind = Arg::Kind::Word;
      a.word = t.text;
      return a;
    }
  }
  auto v = expression();
  if (!v) return std::nullopt;
  a.num = *v;
  return a;
}

std::optional<Arg> ArgReader::nested() {
  if (!deeper(at())) return std::nullopt;
  ++depth_;
  auto a = nested_definition();
  --depth_;
  return a;
}

std::optional<Arg> ArgReader::nested_definition() {
  Arg a;
  a.loc = at().loc;
  ++pos_;  // (
  std::string name;
  if (toks_[pos_ + 1].text == "=") {
    name = at().text;
    pos_ += 2;
  }
  auto g = definition(true);
  if (!g) return std::nullopt;
  if (!is(")")) {
    fail(at(), core::Code::AptSyntax, "expected ')' to close the nested definition");
    return std::nullopt;
  }
  ++pos_;
  if (!name.empty()) {
    symbols_[name] = Symbol{false, 0.0, *g};
    defs_.push_back({name, *g, a.loc});
  }
  a.kind = Arg::Kind::Geom;
  a.geom = *g;
  a.name = name;
  return a;
}

std::optional<Geom> ArgReader::definition(bool nested_def) {
  const Token major = at();
  if (major.kind != TokKind::Word || !is_geometry_word(major.text) || toks_[pos_ + 1].text != "/") {
    fail(major, core::Code::AptSyntax,
         "expected a definition such as POINT/1,2 here, found '" + major.text + "'");
    return std::nullopt;
  }
  pos_ += 2;
  // Past the bound no pattern is computed (nor its arguments read).
  if (major.text == "PATERN" && pattern_points_ >= kMostProgramPatternPoints) {
    fail(major, core::Code::AptBadArgument,
         "PATERN: the program's patterns make and read more than " +
             std::to_string(kMostProgramPatternPoints) + " points");
    return std::nullopt;
  }
  auto args = arguments();
  if (!args) return std::nullopt;
  if (!nested_def && at().kind != TokKind::End) {
    fail(at(), core::Code::AptSyntax, "unexpected '" + at().text + "' after the definition");
    return std::nullopt;
  }
  // The patterns' budget is spent by what each definition does, failing or not.
  std::size_t left =
      kMostProgramPatternPoints - std::min(pattern_points_, kMostProgramPatternPoints);
  auto g = define(major.text, *args, zsurf_, &left);
  pattern_points_ = kMostProgramPatternPoints - left;
  if (!g) {
    fail(major, g.error().code, g.error().message);
    return std::nullopt;
  }
  return *g;
}

std::optional<double> ArgReader::whole_expression() {
  auto v = expression();
  if (!v) return std::nullopt;
  if (at().kind != TokKind::End) {
    fail(at(), core::Code::AptSyntax, "unexpected '" + at().text + "' after the expression");
    return std::nullopt;
  }
  return v;
}

// A bound on nesting, so that hostile input cannot exhaust the stack.
constexpr int kMaxDepth = 256;

bool ArgReader::deeper(const Token& t) {
  if (depth_ < kMaxDepth) return true;
  return fail(t, core::Code::AptSyntax,
              "expressions or definitions nested deeper than " + std::to_string(kMaxDepth) +
                  " levels; simplify the statement");
}

std::optional<double> ArgReader::expression() {
  if (!deeper(at())) return std::nullopt;
  ++depth_;
  auto v = sum();
  --depth_;
  return v;
}

std::optional<double> ArgReader::sum() {
  auto v = term();
  while (v && (is("+") || is("-"))) {
    const bool plus = is("+");
    ++pos_;
    auto r = term();
    if (!r) return std::nullopt;
    v = plus ? *v + *r : *v - *r;
  }
  return v;
}

std::optional<double> ArgReader::term() {
  auto v = factor();
  while (v && (is("*") || is("/"))) {
    const Token& op = at();
    ++pos_;
    auto r = factor();
    if (!r) return std::nullopt;
    if (op.text == "/" && *r == 0.0) {
      fail(op, core::Code::AptArithmetic, "division by zero");
      return std::nullopt;
    }
    v = op.text == "*" ? *v * *r : *v / *r;
    if (!finite(op, *v, "the product or quotient")) return std::nullopt;
  }
  return v;
}

std::optional<double> ArgReader::factor() {
  int sign = 1;
  while (is("-") || is("+")) {
    if (is("-")) sign = -sign;
    ++pos_;
  }
  auto v = primary();
  if (!v) return std::nullopt;
  if (is("**")) {
    const Token& op = at();
    ++pos_;
    if (!deeper(op)) return std::nullopt;
    ++depth_;
    auto e = factor();
    --depth_;
    if (!e) return std::nullopt;
    v = std::pow(*v, *e);
    if (!finite(op, *v, "the power")) return std::nullopt;
  }
  return sign * *v;
}

bool ArgReader::finite(const Token& t, double v, const char* what) {
  if (std::isfinite(v)) return true;
  return fail(t, core::Code::AptArithmetic,
              std::string(what) + " has no finite value (out of range or undefined)");
}

std::optional<double> ArgReader::primary() {
  const Token& t = at();
  if (t.kind == TokKind::Number) {
    ++pos_;
    if (!finite(t, t.value, ("the number " + t.text).c_str())) return std::nullopt;
    return t.value;
  }
  if (is("(")) {
    ++pos_;
    auto v = expression();
    if (!v) return std::nullopt;
    if (!is(")")) {
      fail(at(), core::Code::AptSyntax, "expected ')' to close the parenthesis");
      return std::nullopt;
    }
    ++pos_;
    return v;
  }
  if (t.kind != TokKind::Word) {
    fail(t, core::Code::AptSyntax,
         t.kind == TokKind::End ? "the statement ends where a value was expected"
                                : "expected a value, found '" + t.text + "'");
    return std::nullopt;
  }
  ++pos_;
  if (is("(")) return call(t);
  const auto sym = symbols_.find(t.text);
  if (sym != symbols_.end() && sym->second.scalar) return sym->second.value;
  if (sym != symbols_.end()) {
    fail(t, core::Code::AptBadArgument,
         t.text + " is a " + std::string(type_name(sym->second.geom.type)) +
             ", not a number; it cannot stand in an expression");
    return std::nullopt;
  }
  fail(t, core::Code::AptUndefinedSymbol,
       t.text +
           " is not defined (IBM error 101, undefined symbol); define it before this "
           "statement or check the spelling");
  return std::nullopt;
}

}  // namespace usina::apt
