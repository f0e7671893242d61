#include "gcode/romi/syntax.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "gcode/decimal.hpp"
#include "gcode/number_form.hpp"
#include "gcode/program_text.hpp"

namespace usina::gcode::romi {
namespace {

constexpr int kMaxDepth = 64;
constexpr std::size_t kMaxNodes = kMaxBlockLength;  // one a character at most

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

bool is_letter(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}

char upper(char c) {
  return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

struct FuncName {
  std::string_view spelling;
  Func func;
};

// Longer spellings first where one starts another (ASIN before SIN is not
// needed: names are read whole).
constexpr std::array kFuncs = {
    FuncName{"SIN", Func::Sin},     FuncName{"COS", Func::Cos},   FuncName{"TAN", Func::Tan},
    FuncName{"ASIN", Func::Asin},   FuncName{"ACOS", Func::Acos}, FuncName{"ATAN", Func::Atan},
    FuncName{"SQRT", Func::Sqrt},   FuncName{"ABS", Func::Abs},   FuncName{"LN", Func::Ln},
    FuncName{"LOG", Func::Log10},   FuncName{"EXP", Func::Exp},   FuncName{"INT", Func::Trunc},
    FuncName{"ROUND", Func::Round},
};

struct CmpName {
  std::string_view spelling;
  BinOp op;
};

constexpr std::array kComparisons = {CmpName{"EQ", BinOp::Eq}, CmpName{"NE", BinOp::Ne},
                                     CmpName{"GT", BinOp::Gt}, CmpName{"GE", BinOp::Ge},
                                     CmpName{"LT", BinOp::Lt}, CmpName{"LE", BinOp::Le}};

class Parser {
 public:
  Parser(std::string_view text, std::uint32_t first_col, RomiBlock& b)
      : s_(text), base_(first_col), b_(b) {}

  void parse();

  struct Error {
    core::Code code;
    std::size_t pos;
    std::string message;
  };

  std::optional<Error> error;

 private:
  bool fail(core::Code code, std::size_t pos, std::string message) {
    if (!error) error = Error{code, pos, std::move(message)};
    return false;
  }

  std::uint32_t col(std::size_t pos) const { return base_ + static_cast<std::uint32_t>(pos); }

  void skip() {
    while (i_ < end_ && is_blank(s_[i_]))
      ++i_;
  }

  char peek() {
    skip();
    return i_ < end_ ? upper(s_[i_]) : '\0';
  }

  bool keyword(std::string_view k);
  std::optional<std::size_t> dash_length(std::size_t at) const;
  std::optional<double> number();
  ExprRef number_node(double value, std::uint32_t at_col);
  std::optional<int> param_index();
  ExprRef node(ExprNode n);
  ExprRef word_value();
  void item();
  void parenthesis();
  bool statement(std::size_t close);
  bool assignment(Statement& st);
  bool control_statement(Statement& st);
  void repeat_statement(Statement& st);
  std::optional<double> label(char letter);

  ExprRef expr(int depth);
  ExprRef conjunction(int depth);
  ExprRef comparison(int depth);
  ExprRef sum(int depth);
  ExprRef product(int depth);
  ExprRef power(int depth);
  ExprRef unary(int depth);
  ExprRef primary(int depth);

  ExprRef binary(BinOp op, ExprRef a, ExprRef b, std::size_t at) {
    if (a == kNoExpr || b == kNoExpr) return kNoExpr;
    // Every operation's value finite, as a control's overflow alarm:
    // "1 / EXP[720]" is an error, not 0.
    ExprNode n{ExprKind::Binary, static_cast<std::uint8_t>(op), a, b, 0.0, {}, col(at)};
    n.checked = true;
    return node(n);
  }

  std::string_view s_;
  std::uint32_t base_;
  RomiBlock& b_;
  std::size_t i_ = 0;
  std::size_t end_ = 0;
  friend bool parse_romi_block(std::string_view, const LinePos&, std::uint32_t, RomiBlock&,
                               core::DiagnosticSink&);
};

// A plain number's node, built where it is stored: a node built apart and
// copied in is read back before all its fields are written (a stalled
// store per value; rs274ngc's Parser::number_node, issue 19).
ExprRef Parser::number_node(double value, std::uint32_t at_col) {
  if (b_.base.exprs.size() >= kMaxNodes) return node({});
  ExprNode& n = b_.base.exprs.emplace_back();
  n.value = value;
  n.col = at_col;
  return static_cast<ExprRef>(b_.base.exprs.size() - 1);
}

ExprRef Parser::node(ExprNode n) {
  if (b_.base.exprs.size() >= kMaxNodes) {
    fail(core::Code::BlockTooLong, i_,
         fmt::format("a block with more than {} values and operators", kMaxNodes));
    return kNoExpr;
  }
  b_.base.exprs.push_back(n);
  return static_cast<ExprRef>(b_.base.exprs.size() - 1);
}

// A keyword, case-insensitive, not followed by another letter.
bool Parser::keyword(std::string_view k) {
  skip();
  if (end_ - i_ < k.size()) return false;
  for (std::size_t j = 0; j < k.size(); ++j) {
    if (upper(s_[i_ + j]) != k[j]) return false;
  }
  if (i_ + k.size() < end_ && is_letter(s_[i_ + k.size()])) return false;
  i_ += k.size();
  return true;
}

// U+2013 EN DASH, U+2014 EM DASH, U+2212 MINUS SIGN in UTF-8.
std::optional<std::size_t> Parser::dash_length(std::size_t at) const {
  if (end_ - at < 3) return std::nullopt;
  const auto b0 = static_cast<unsigned char>(s_[at]);
  const auto b1 = static_cast<unsigned char>(s_[at + 1]);
  const auto b2 = static_cast<unsigned char>(s_[at + 2]);
  if (b0 == 0xE2 && b1 == 0x80 && (b2 == 0x93 || b2 == 0x94)) return 3;
  if (b0 == 0xE2 && b1 == 0x88 && b2 == 0x92) return 3;
  return std::nullopt;
}

// Digits with at most one point (mm or degrees, never least increments),
// read as every dialect reads them (gcode/decimal.hpp).
std::optional<double> Parser::number() {
  skip();
  const std::size_t start = i_;
  const Decimal d = scan_decimal(s_.substr(0, end_), start);
  if (d.digits == 0) return std::nullopt;
  i_ = d.end;
  // Asked only when an E follows the digits (the call builds a result).
  if (i_ < end_ && (s_[i_] == 'e' || s_[i_] == 'E')) {
    if (const auto ok = exponent_out_of_range(s_.substr(0, end_), start, i_); !ok) {
      fail(core::Code::NumberOutOfRange, start, ok.error());
      return std::nullopt;
    }
  }
  // Up to 15 digits the value is finite: no test waits for the division.
  if (d.digits > decimal_detail::kExactDigits && !std::isfinite(d.value)) {
    fail(core::Code::BadNumber, start, "number out of range");
    return std::nullopt;
  }
  return d.value;
}

// P followed by digits: a parameter number 0..999.
std::optional<int> Parser::param_index() {
  const std::size_t at = i_;
  ++i_;  // 'P'
  const std::size_t digits = i_;
  while (i_ < end_ && is_digit(s_[i_]))
    ++i_;
  int n = 0;
  const auto r = std::from_chars(s_.data() + digits, s_.data() + i_, n);
  if (r.ec != std::errc() || n < 0 || n > kMaxParam) {
    fail(core::Code::ParameterOutOfRange, at, "a parameter is P0 to P999");
    return std::nullopt;
  }
  return n;
}

// The value of a word: a signed number, a parameter (X P1), or nothing (0).
ExprRef Parser::word_value() {
  skip();
  const std::size_t at = i_;
  bool negative = false;
  bool sign = false;
  if (i_ < end_ && (s_[i_] == '-' || s_[i_] == '+')) {
    negative = s_[i_] == '-';
    sign = true;
    ++i_;
  } else if (auto n = dash_length(i_)) {
    b_.dashes.push_back(col(i_));
    negative = sign = true;
    i_ += *n;
  }
  skip();
  if (auto v = number()) return number_node(negative ? -*v : *v, col(at));
  if (error) return kNoExpr;
  if (i_ + 1 < end_ && upper(s_[i_]) == 'P' && is_digit(s_[i_ + 1])) {
    const std::size_t p = i_;
    if (!param_index()) return kNoExpr;
    const ExprRef r =
        node({ExprKind::NamedParam, 0, kNoExpr, kNoExpr, 0.0, s_.substr(p, i_ - p), col(p)});
    if (!negative || r == kNoExpr) return r;
    return node({ExprKind::Negate, 0, r, kNoExpr, 0.0, {}, col(at)});
  }
  if (sign) {
    fail(core::Code::BadNumber, at, "a sign with no number after it");
    return kNoExpr;
  }
  return node({ExprKind::Number, 0, kNoExpr, kNoExpr, 0.0, {}, col(at)});
}

ExprRef Parser::expr(int depth) {
  if (depth > kMaxDepth) {
    fail(core::Code::ExpectedExpression, i_, "expression nested more than 64 deep");
    return kNoExpr;
  }
  ExprRef a = conjunction(depth);
  for (;;) {
    const std::size_t at = i_;
    if (!keyword("OR")) return a;
    a = binary(BinOp::Or, a, conjunction(depth), at);
  }
}

ExprRef Parser::conjunction(int depth) {
  ExprRef a = comparison(depth);
  for (;;) {
    const std::size_t at = i_;
    if (!keyword("AND")) return a;
    a = binary(BinOp::And, a, comparison(depth), at);
  }
}

ExprRef Parser::comparison(int depth) {
  ExprRef a = sum(depth);
  const std::size_t at = i_;
  for (const CmpName& c : kComparisons) {
    if (keyword(c.spelling)) return binary(c.op, a, sum(depth), at);
  }
  return a;
}

ExprRef Parser::sum(int depth) {
  ExprRef a = product(depth);
  for (;;) {
    const char c = peek();
    const std::size_t at = i_;
    if (c != '+' && c != '-') return a;
    ++i_;
    a = binary(c == '+' ? BinOp::Add : BinOp::Sub, a, product(depth), at);
  }
}

ExprRef Parser::product(int depth) {
  ExprRef a = power(depth);
  for (;;) {
    const char c = peek();
    const std::size_t at = i_;
    if (c == '*' || c == '/') {
      ++i_;
      a = binary(c == '*' ? BinOp::Mul : BinOp::Div, a, power(depth), at);
    } else if (keyword("MOD")) {
      a = binary(BinOp::Mod, a, power(depth), at);
    } else {
      return a;
    }
  }
}

ExprRef Parser::power(int depth) {
  ExprRef a = unary(depth);
  for (;;) {
    const std::size_t at = i_;
    if (peek() != '^') return a;
    ++i_;
    a = binary(BinOp::Pow, a, unary(depth), at);
  }
}

ExprRef Parser::unary(int depth) {
  if (depth > kMaxDepth) {
    fail(core::Code::ExpectedExpression, i_, "expression nested more than 64 deep");
    return kNoExpr;
  }
  const char c = peek();
  const std::size_t at = i_;
  const auto dash = dash_length(i_);
  if (c == '-' || c == '+' || dash) {
    if (dash) b_.dashes.push_back(col(i_));
    i_ += dash ? *dash : 1;
    const ExprRef a = unary(depth + 1);
    if ((c == '+' && !dash) || a == kNoExpr) return a;
    return node({ExprKind::Negate, 0, a, kNoExpr, 0.0, {}, col(at)});
  }
  if (keyword("NOT")) {
    const ExprRef a = unary(depth + 1);
    const ExprRef zero = node({ExprKind::Number, 0, kNoExpr, kNoExpr, 0.0, {}, col(at)});
    return binary(BinOp::Eq, a, zero, at);
  }
  return primary(depth);
}

ExprRef Parser::primary(int depth) {
  const char c = peek();
  const std::size_t at = i_;
  if (c == '(') {
    ++i_;
    const ExprRef e = expr(depth + 1);
    if (e == kNoExpr) return kNoExpr;
    if (peek() != ')') {
      fail(core::Code::UnclosedBracket, i_, "expected ')'");
      return kNoExpr;
    }
    ++i_;
    return e;
  }
  if (auto v = number()) return number_node(*v, col(at));
  if (error) return kNoExpr;
  if (c == 'P' && i_ + 1 < end_ && is_digit(s_[i_ + 1])) {
    if (!param_index()) return kNoExpr;
    return node({ExprKind::NamedParam, 0, kNoExpr, kNoExpr, 0.0, s_.substr(at, i_ - at), col(at)});
  }
  for (const FuncName& f : kFuncs) {
    if (!keyword(f.spelling)) continue;
    if (peek() != '(') {
      fail(core::Code::ExpectedExpression, i_, fmt::format("{} needs ( )", f.spelling));
      return kNoExpr;
    }
    const ExprRef a = primary(depth + 1);
    if (a == kNoExpr) return kNoExpr;
    return node({ExprKind::Func, static_cast<std::uint8_t>(f.func), a, kNoExpr, 0.0, {}, col(at)});
  }
  if (c == '\0') {
    fail(core::Code::ExpectedExpression, at, "missing value");
  } else if (is_letter(c)) {
    fail(core::Code::UnknownFunction, at, "unknown function or operator");
  } else {
    fail(core::Code::ExpectedExpression, at, fmt::format("expected a value, found '{}'", c));
  }
  return kNoExpr;
}

// N followed by a number (GOTO N200), or a plain number (CALL 5).
std::optional<double> Parser::label(char letter) {
  const std::size_t at = i_;
  if (letter != 0) {
    if (peek() != letter) {
      fail(core::Code::ExpectedExpression, at, fmt::format("expected {} and a number", letter));
      return std::nullopt;
    }
    ++i_;
  }
  auto n = number();
  if (!n) fail(core::Code::BadNumber, i_, "expected a block or subroutine number");
  return n;
}

// A Fagor statement filling the parentheses up to `close`; false when the
// text is a comment instead.
bool Parser::statement(std::size_t close) {
  const std::size_t saved_end = end_;
  end_ = close;
  Statement st;
  st.col = col(i_);
  skip();
  const std::size_t start = i_;
  if (peek() == 'P' && i_ + 1 < end_ && is_digit(s_[i_ + 1])) {
    if (!assignment(st)) {
      // "(P1 is the radius)": a comment that starts with a parameter's name.
      error.reset();
      i_ = start;
      end_ = saved_end;
      return false;
    }
  } else if (!control_statement(st)) {
    i_ = start;
    end_ = saved_end;
    return false;
  }
  if (!error && peek() != '\0')
    fail(core::Code::UnexpectedCharacter, i_, "text after the statement");
  end_ = saved_end;
  i_ = close + 1;
  // A statement with an error is reported, not run.
  if (!error) b_.statements.push_back(st);
  return true;
}

// "P<n> = <expression>"; false when no '=' follows the parameter (the text is
// a comment).
bool Parser::assignment(Statement& st) {
  auto p = param_index();
  if (!p) return true;
  if (peek() != '=') return false;
  ++i_;
  st.kind = StmtKind::Assign;
  st.param = *p;
  st.expr = expr(0);
  return true;
}

// IF .. GOTO, GOTO, RPT, CALL, SUB and RET; false when no keyword of theirs
// starts the text.
bool Parser::control_statement(Statement& st) {
  if (keyword("IF")) {
    st.kind = StmtKind::IfGoto;
    st.expr = expr(0);
    if (!error && !keyword("GOTO")) fail(core::Code::ExpectedExpression, i_, "IF needs GOTO N..");
    if (!error) {
      if (auto n = label('N')) st.label = *n;
    }
    return true;
  }
  if (keyword("GOTO")) {
    st.kind = StmtKind::Goto;
    if (auto n = label('N')) st.label = *n;
    return true;
  }
  if (keyword("RPT")) {
    repeat_statement(st);
    return true;
  }
  for (auto [word, kind] : {std::pair{std::string_view("CALL"), StmtKind::Call},
                            std::pair{std::string_view("SUB"), StmtKind::Sub}}) {
    if (keyword(word)) {
      st.kind = kind;
      if (auto n = label(0)) st.label = *n;
      return true;
    }
  }
  if (keyword("RET")) {
    st.kind = StmtKind::Return;
    return true;
  }
  return false;
}

// "RPT N<first>, N<last>[, count]": the blocks first..last run again.
void Parser::repeat_statement(Statement& st) {
  st.kind = StmtKind::Repeat;
  auto first = label('N');
  if (first && peek() == ',') {
    ++i_;
    auto last = label('N');
    if (last) {
      st.label = *first;
      st.label_end = *last;
      if (peek() == ',') {
        ++i_;
        st.expr = expr(0);
      }
    }
  } else if (first) {
    fail(core::Code::ExpectedExpression, i_, "RPT needs N<first>, N<last>[, count]");
  }
}

void Parser::parenthesis() {
  const std::size_t open = i_;
  // The matching ')': a statement has parentheses of its own.
  std::size_t close = open;
  for (int depth = 0; close < end_; ++close) {
    if (s_[close] == '(') ++depth;
    if (s_[close] == ')' && --depth == 0) break;
  }
  if (close >= end_) {
    fail(core::Code::UnclosedComment, open, "'(' not closed with ')' before the end of the block");
    return;
  }
  ++i_;
  if (statement(close)) return;
  b_.base.comments.push_back({s_.substr(open + 1, close - open - 1), col(open)});
  i_ = close + 1;
}

void Parser::item() {
  const std::size_t at = i_;
  const char raw = s_[i_];
  if (raw == ';') {
    b_.base.comments.push_back({s_.substr(i_ + 1, end_ - i_ - 1), col(at)});
    i_ = end_;
    return;
  }
  if (raw == '(') {
    parenthesis();
    return;
  }
  if (is_letter(raw)) {
    const char letter = upper(raw);
    if (letter == 'P') {
      fail(core::Code::UnknownWord, at,
           "a parameter outside a statement: use it as a word's value (X P1) or in (P1 = ..)");
      return;
    }
    if (letter == 'N') {
      fail(core::Code::UnknownWord, at, "a block number (N) must start the block");
      return;
    }
    ++i_;
    const ExprRef v = word_value();
    if (v == kNoExpr) return;
    b_.words.push_back({letter, raw != letter, v, col(at)});
    return;
  }
  const auto byte = static_cast<unsigned char>(raw);
  fail(core::Code::UnexpectedCharacter, at,
       byte >= 0x20 && byte < 0x7f ? fmt::format("unexpected character '{}'", raw)
                                   : fmt::format("unexpected byte 0x{:02x}", byte));
}

void Parser::parse() {
  end_ = s_.size();
  skip();
  if (i_ < end_ && s_[i_] == '%') {
    b_.base.percent = true;
    return;
  }
  if (i_ + 1 < end_ && upper(s_[i_]) == 'N' && is_digit(s_[i_ + 1])) {
    ++i_;
    b_.base.line_number = number();
  }
  for (skip(); !error && i_ < end_; skip())
    item();
}

// A word's letter the shortcut reads: upper case, not N or P (errors
// there) and not lower case (an increment, read the whole way).
constexpr std::array<bool, 256> kPlainLetter = [] {
  std::array<bool, 256> t{};
  for (int c = 'A'; c <= 'Z'; ++c)
    t[static_cast<std::size_t>(c)] = c != 'N' && c != 'P';
  return t;
}();

// The unsigned number right at text[i] and the blanks after it: where the
// next word starts (or the block ends), or 0 for what the parser reads
// otherwise or refuses: no digit (a word of no value is 0), an E after it
// (an exponent, refused), more than 15 digits, a character after it that
// starts no word.
// Aligned as gcode/parser.cpp's plain_number_at is (why there).
[[gnu::aligned(64)]] std::size_t plain_number_at(std::string_view text, std::size_t i,
                                                 double& value) {
  const Decimal d = scan_decimal(text, i);
  if (d.digits == 0 || d.digits > decimal_detail::kExactDigits) return 0;
  if (d.end < text.size() && text[d.end] == 'E') return 0;
  std::size_t next = d.end;
  while (next < text.size() && is_blank(text[next]))
    ++next;
  if (next < text.size() && !kPlainLetter[static_cast<unsigned char>(text[next])]) return 0;
  value = d.value;
  return next;
}

}  // namespace

bool parse_plain_romi_block(std::string_view text, std::uint32_t first_col, std::size_t i,
                            RomiBlock& block) {
  while (i < text.size() && is_blank(text[i]))
    ++i;
  if (i + 1 < text.size() && text[i] == 'N' && is_digit(text[i + 1])) {
    double n = 0.0;
    i = plain_number_at(text, i + 1, n);
    if (i == 0) return false;
    block.base.line_number = n;
  }
  while (i < text.size()) {
    const char letter = text[i];
    // As many words as the whole parser's nodes would hold (one a word).
    if (!kPlainLetter[static_cast<unsigned char>(letter)] || block.words.size() >= kMaxNodes) {
      return false;
    }
    const std::size_t at = i++;
    const bool minus = i < text.size() && text[i] == '-';
    if (minus || (i < text.size() && text[i] == '+')) ++i;
    double v = 0.0;
    i = plain_number_at(text, i, v);
    if (i == 0) return false;
    block.words.push_back(
        {letter, false, kPlainNumber, first_col + static_cast<std::uint32_t>(at), minus ? -v : v});
  }
  return !block.words.empty();
}

void RomiBlock::clear() {
  base.clear();
  words.clear();
  statements.clear();
  dashes.clear();
}

BlockText block_at(std::string_view text, std::uint64_t offset, LineEnd& known) {
  if (offset >= text.size()) return {{}, text.size(), true};
  // The line's end once a line (memchr), then a '#' before it: a line of
  // several blocks is not scanned again for each (issue 19).
  const char* start = text.data() + offset;
  if (!known.known || offset < known.from || offset > known.end || known.end > text.size()) {
    const auto* nl = static_cast<const char*>(std::memchr(start, '\n', text.size() - offset));
    known = {offset, nl != nullptr ? static_cast<std::uint64_t>(nl - text.data()) : text.size(),
             true};
  }
  const std::size_t line = known.end - offset;
  const auto* hash = static_cast<const char*>(std::memchr(start, '#', line));
  const std::size_t end =
      offset + (hash != nullptr ? static_cast<std::size_t>(hash - start) : line);
  std::string_view t = text.substr(offset, end - offset);
  if (!t.empty() && t.back() == '\r') t.remove_suffix(1);
  if (hash == nullptr) return {t, std::min<std::uint64_t>(end + 1, text.size()), true};
  // Nothing but the newline after the '#' (how romi lines end, "G01 X10#"):
  // the next block starts on the next line, and no empty block is cut
  // between (one step in five of a program of four blocks a line).
  const std::uint64_t rest = known.end - (end + 1);
  if (known.end < text.size() && (rest == 0 || (rest == 1 && text[end + 1] == '\r')))
    return {t, known.end + 1, true};
  return {t, end + 1, false};
}

bool parse_romi_block(std::string_view text, const LinePos& where, std::uint32_t first_col,
                      RomiBlock& block, core::DiagnosticSink& diags) {
  block.clear();
  std::size_t first = 0;
  while (first < text.size() && is_blank(text[first]))
    ++first;
  block.base.loc = {where.file, where.line, static_cast<std::uint32_t>(first_col + first), 0,
                    where.offset};
  if (parse_plain_romi_block(text, first_col, first, block)) return true;
  block.words.clear();
  block.base.exprs.clear();
  block.base.line_number.reset();
  Parser p(text, first_col, block);
  p.parse();
  if (!p.error) return true;
  core::SourceLoc loc = block.base.loc;
  loc.col = first_col + static_cast<std::uint32_t>(p.error->pos);
  loc.length = 1;
  diags.report({p.error->code, core::Severity::Error, loc, p.error->message});
  return false;
}

}  // namespace usina::gcode::romi
