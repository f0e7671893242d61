#include "gcode/fanuc/macro.hpp"

#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "gcode/decimal.hpp"
#include "gcode/fanuc/tape.hpp"

namespace usina::gcode::fanuc {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;
constexpr int kMaxBrackets = 5;  // [16L]: alarm 118 past 5 levels

// ASCII, as a tape is: no locale asked per character.
bool is_letter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

char upper(char c) {
  return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}

bool is_operator_word(std::string_view l) {
  auto is = [&](std::string_view w) {
    if (l.size() != w.size()) return false;
    for (std::size_t k = 0; k < l.size(); ++k)
      if (upper(l[k]) != w[k]) return false;
    return true;
  };
  return is("OR") || is("XOR") || is("AND") || is("MOD");
}

// Rounded and kept within ±1e15, so a huge or NaN value never overflows
// the integer it is converted to.
long to_integer(double x) {
  const double r = round_half_away(x);
  if (!(r > -1e15)) return r > 0 ? 1'000'000'000'000'000L : -1'000'000'000'000'000L;
  if (r > 1e15) return 1'000'000'000'000'000L;
  return static_cast<long>(r);
}

}  // namespace

double fix(double x) {
  return std::trunc(x);
}

double fup(double x) {
  return x >= 0 ? std::ceil(x) : std::floor(x);
}

double round_half_away(double x) {
  return std::round(x);
}

double round_to_step(double x, double step) {
  // 1.2345 / 0.001 is 1234.4999..., so half a step is nudged by 1e-9 steps.
  const double n = x / step;
  return round_half_away(n + std::copysign(1e-9, n)) * step;
}

double atan2_deg(double a, double b) {
  double r = std::atan2(a, b) / kRad;
  if (r < 0) r += 360.0;
  if (r >= 360.0) r -= 360.0;
  return r;
}

double fanuc_mod(double a, double b) {
  const double j = round_half_away(a);
  const double k = round_half_away(b);
  return j - std::trunc(j / k) * k;
}

std::nullopt_t MacroReader::fail(core::Code code, std::string message) {
  if (err_.message.empty()) err_ = {code, i_, std::move(message)};
  return std::nullopt;
}

// A Fanuc control checks every operation's result (alarm 111): an infinity
// a comparison or a division would hide ("[EXP[720] GT 0]", "1/EXP[720]")
// is an error where it is made, not a silent 1 or 0.
std::optional<Value> MacroReader::calculated(double v) {
  if (std::isfinite(v)) return Value{v};
  return fail(core::Code::NumberOutOfRange,
              fmt::format("the value is {} (Fanuc alarm 111, calculated data overflow)", v));
}

// A comment reads as a blank where it stands (fanuc/tape.hpp).
void MacroReader::blanks() {
  while (i_ < text_.size() && (text_[i_] == ' ' || text_[i_] == '\t' || text_[i_] == '(')) {
    i_ = text_[i_] == '(' ? skip_comment(text_, i_) : i_ + 1;
  }
}

bool MacroReader::at_end() {
  blanks();
  return i_ >= text_.size();
}

char MacroReader::peek() {
  blanks();
  return i_ < text_.size() ? upper(text_[i_]) : '\0';
}

bool MacroReader::accept(char c) {
  if (peek() != c) return false;
  ++i_;
  return true;
}

std::string_view MacroReader::letters() {
  blanks();
  std::size_t j = i_;
  while (j < text_.size() && is_letter(text_[j]))
    ++j;
  return text_.substr(i_, j - i_);
}

bool MacroReader::keyword(std::string_view word) {
  const std::string_view l = letters();
  if (l.size() != word.size()) return false;
  for (std::size_t k = 0; k < l.size(); ++k) {
    if (upper(l[k]) != word[k]) return false;
  }
  i_ += l.size();
  return true;
}

// Aligned as gcode/parser.cpp's plain_number_at is (why there).
[[gnu::aligned(64)]] bool plain_digits(std::string_view text, std::size_t& i, double& v,
                                       bool& had_point) {
  const Decimal d = scan_decimal(text, i);
  if (d.digits == 0) return false;
  i = d.end;
  v = d.value;
  had_point = d.point;
  // Up to 15 digits the value is finite: no test waits for the division.
  return d.digits <= decimal_detail::kExactDigits || std::isfinite(v);
}

namespace {

// The digits and the point of a number that has blanks or comments inside
// ("1 2.(TENTHS)5"), from text[i] on, as one number without them; `i`
// ends at the first other character.
std::string number_characters(std::string_view text, std::size_t& i) {
  std::string out;
  bool point = false;
  for (; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(') {
      i = skip_comment(text, i) - 1;  // a blank inside the number
    } else if ((c >= '0' && c <= '9') || (c == '.' && !point)) {
      point = point || c == '.';
      out += c;
    } else if (c != ' ' && c != '\t') {
      break;
    }
  }
  return out;
}

}  // namespace

std::optional<double> MacroReader::number() {
  blanks();
  const std::size_t start = i_;
  Decimal d = scan_decimal(text_, i_);
  std::size_t end = d.end;
  const char after = end < text_.size() ? text_[end] : '\0';
  if (after == ' ' || after == '\t' || after == '(') {
    // Blanks or comments inside or after it: read them as nothing.
    end = start;
    const std::string chars = number_characters(text_, end);
    d = scan_decimal(chars, 0);
  }
  had_point_ = d.point;
  if (d.digits == 0 && !d.point) return std::nullopt;
  if (!std::isfinite(d.value)) {
    return fail(core::Code::NumberOutOfRange,
                "a number with more digits than any number holds (beyond 1.8e308)");
  }
  i_ = end;
  return d.value;
}

std::optional<long> MacroReader::variable_number() {
  if (!accept('#')) return fail(core::Code::ExpectedExpression, "expected '#'");
  if (peek() == '[') {
    auto v = bracket();
    if (!v) return std::nullopt;
    return to_integer(v->v);
  }
  if (peek() == '#' || peek() == '-') {
    return fail(core::Code::BadParameterName,
                "a variable number is digits or [expression] ('##1' and '#-1' are not Macro B)");
  }
  auto n = number();
  if (!n) return fail(core::Code::BadParameterName, "'#' needs a variable number");
  if (had_point_) return fail(core::Code::BadParameterName, "a variable number has no point");
  return to_integer(*n);
}

// The common word value, a signed number and nothing else ("X-1.25"),
// read without the descent through sum, product and unary; the same digits
// give the same value. nullopt (and the position back) for anything else.
std::optional<Value> MacroReader::plain_number() {
  const std::size_t start = i_;
  bool negative = false;
  for (char c = peek(); c == '-' || c == '+'; c = peek()) {
    ++i_;
    negative = negative != (c == '-');
  }
  const char c = i_ < text_.size() ? text_[i_] : '\0';
  if ((c >= '0' && c <= '9') || c == '.') {
    // A number too long for a double fails here as it would below.
    if (auto n = number()) {
      const char next = i_ < text_.size() ? text_[i_] : '\0';
      if (next == '\0' || (is_letter(next) && !is_operator_word(letters()))) {
        literal_ = true;
        return Value{negative ? -*n : *n};
      }
    }
  }
  i_ = start;
  return std::nullopt;
}

std::optional<Value> MacroReader::expression() {
  single_var_ = false;
  literal_ = false;
  relation_ = false;
  const std::size_t start = i_;
  if (auto plain = plain_number()) return plain;
  auto v = sum();
  if (!v) return std::nullopt;
  // One variable reference alone keeps its vacancy; anything else computed
  // from it has vacant read as 0 ([M700] p. 326).
  if (!std::isfinite(v->v)) {
    i_ = start;
    return fail(core::Code::NumberOutOfRange,
                fmt::format("the value is {} (Fanuc alarm 111, calculated data overflow)", v->v));
  }
  return v;
}

std::optional<Value> MacroReader::sum() {
  auto a = product();
  if (!a) return std::nullopt;
  for (;;) {
    const char c = peek();
    int op = 0;
    if (c == '+' || c == '-') {
      ++i_;
      op = c;
    } else if (keyword("OR")) {
      op = 'o';
    } else if (keyword("XOR")) {
      op = 'x';
    } else {
      return a;
    }
    auto b = product();
    if (!b) return std::nullopt;
    single_var_ = false;
    literal_ = false;
    const long x = to_integer(a->v), y = to_integer(b->v);
    switch (op) {
    case '+': a = calculated(a->v + b->v); break;
    case '-': a = calculated(a->v - b->v); break;
    case 'o': a = Value{static_cast<double>(x | y)}; break;
    default: a = Value{static_cast<double>(x ^ y)}; break;
    }
    if (!a) return std::nullopt;
  }
}

std::optional<Value> MacroReader::product() {
  auto a = unary();
  if (!a) return std::nullopt;
  for (;;) {
    const char c = peek();
    int op = 0;
    if (c == '*' || c == '/') {
      ++i_;
      op = c;
    } else if (keyword("AND")) {
      op = 'a';
    } else if (keyword("MOD")) {
      op = 'm';
    } else {
      return a;
    }
    auto b = unary();
    if (!b) return std::nullopt;
    single_var_ = false;
    literal_ = false;
    if ((op == '/' && b->v == 0.0) || (op == 'm' && round_half_away(b->v) == 0.0))
      return fail(core::Code::DivisionByZero, "division by zero (Fanuc alarm 112)");
    switch (op) {
    case '*': a = calculated(a->v * b->v); break;
    case '/': a = calculated(a->v / b->v); break;
    case 'a': a = Value{static_cast<double>(to_integer(a->v) & to_integer(b->v))}; break;
    default: a = calculated(fanuc_mod(a->v, b->v)); break;
    }
    if (!a) return std::nullopt;
  }
}

std::optional<Value> MacroReader::unary() {
  // Signs in a loop, not by recursion: '-----...' cannot exhaust the stack.
  bool negative = false, signed_ = false;
  for (char c = peek(); c == '-' || c == '+'; c = peek()) {
    ++i_;
    negative = negative != (c == '-');
    signed_ = true;
  }
  auto v = primary();
  if (!v || !signed_) return v;
  // '-#1' with #1 vacant stays vacant so its word is left out; in
  // arithmetic a vacant value is 0 anyway.
  return Value{negative ? -v->v : v->v, single_var_ && v->vacant};
}

std::optional<Value> MacroReader::primary() {
  const char c = peek();
  if (c == '#') {
    MacroError e;
    auto n = variable_number();
    if (!n) return std::nullopt;
    auto v = vars_.read(*n, e);
    if (!v) {
      err_ = e;
      err_.pos = i_;
      return std::nullopt;
    }
    single_var_ = true;
    literal_ = false;
    return v;
  }
  if (c == '[') return bracket();
  if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
    auto n = number();
    if (!n) return fail(core::Code::BadNumber, "bad number");
    single_var_ = false;
    literal_ = true;
    return Value{*n};
  }
  const std::string_view name = letters();
  if (!name.empty()) {
    std::string up;
    for (char l : name)
      up += upper(l);
    i_ += name.size();
    return function(up);
  }
  return fail(core::Code::ExpectedExpression, "expected a number, '#', '[' or a function");
}

std::optional<Value> MacroReader::bracket() {
  if (!accept('[')) return fail(core::Code::ExpectedExpression, "expected '['");
  if (++depth_ > kMaxBrackets)
    return fail(core::Code::UnclosedBracket, "brackets nest deeper than 5 (Fanuc alarm 118)");
  auto a = sum();
  if (!a) return std::nullopt;
  static constexpr std::string_view kRelations[] = {"EQ", "NE", "GT", "GE", "LT", "LE"};
  for (std::string_view r : kRelations) {
    if (!keyword(r)) continue;
    auto b = sum();
    if (!b) return std::nullopt;
    bool t = false;
    if (r == "EQ" || r == "NE") {
      // Vacant differs from 0 only here (§3.1).
      const bool same = (a->vacant && b->vacant) || (!a->vacant && !b->vacant && a->v == b->v);
      t = (r == "EQ") == same;
    } else if (r == "GT") {
      t = a->v > b->v;
    } else if (r == "GE") {
      t = a->v >= b->v;
    } else if (r == "LT") {
      t = a->v < b->v;
    } else {
      t = a->v <= b->v;
    }
    a = Value{t ? 1.0 : 0.0};
    relation_ = true;
    break;
  }
  if (!accept(']')) return fail(core::Code::UnclosedBracket, "expected ']'");
  --depth_;
  a->vacant = false;  // '[#1]' is an expression: vacant reads as 0
  single_var_ = false;
  literal_ = false;
  return a;
}

std::optional<bool> MacroReader::condition() {
  if (peek() != '[')
    return fail(core::Code::ExpectedExpression, "a condition is written in brackets: [#1 GT 0]");
  auto v = bracket();
  if (!v) return std::nullopt;
  return v->v != 0.0;
}

std::optional<Value> MacroReader::function(std::string_view name) {
  auto arg = bracket();
  if (!arg) return std::nullopt;
  const double x = arg->v;
  auto domain = [&](bool ok) -> bool {
    if (!ok)
      fail(core::Code::DomainError, fmt::format("{}[{}]: out of range (Fanuc alarm 119)", name, x));
    return ok;
  };
  double r = 0;
  if (name == "SIN")
    r = std::sin(x * kRad);
  else if (name == "COS")
    r = std::cos(x * kRad);
  else if (name == "TAN")
    r = std::tan(x * kRad);
  else if (name == "ASIN") {
    if (!domain(x >= -1 && x <= 1)) return std::nullopt;
    r = std::asin(x) / kRad;
    if (r < 0) r += 360.0;  // 270..90 without parameter NAT
  } else if (name == "ACOS") {
    if (!domain(x >= -1 && x <= 1)) return std::nullopt;
    r = std::acos(x) / kRad;
  } else if (name == "ATAN") {
    if (accept('/')) {
      auto b = bracket();
      if (!b) return std::nullopt;
      r = atan2_deg(x, b->v);
    } else {
      r = std::atan(x) / kRad;
    }
  } else if (name == "SQRT") {
    if (!domain(x >= 0)) return std::nullopt;
    r = std::sqrt(x);
  } else if (name == "ABS")
    r = std::fabs(x);
  else if (name == "ROUND")
    r = round_step_ > 0 ? round_to_step(x, round_step_) : round_half_away(x);
  else if (name == "FIX")
    r = fix(x);
  else if (name == "FUP")
    r = fup(x);
  else if (name == "LN") {
    if (!domain(x > 0)) return std::nullopt;
    r = std::log(x);
  } else if (name == "EXP")
    r = std::exp(x);
  else if (name == "BIN" || name == "BCD") {
    long v = to_integer(x);
    if (!domain(v >= 0 && v <= 99'999'999)) return std::nullopt;
    long out = 0, place = 1;
    for (; v > 0; v = name == "BIN" ? v / 16 : v / 10, place *= name == "BIN" ? 10 : 16)
      out += (name == "BIN" ? v % 16 : v % 10) * place;
    r = static_cast<double>(out);
  } else {
    return fail(core::Code::UnknownFunction, fmt::format("unknown function {}", name));
  }
  single_var_ = false;
  literal_ = false;
  return calculated(r);
}

}  // namespace usina::gcode::fanuc
