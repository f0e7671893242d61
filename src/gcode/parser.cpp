#include "gcode/parser.hpp"

#include <array>
#include <cctype>
#include <utility>

#include <fmt/format.h>

#include "gcode/lexer.hpp"
#include "gcode/number_form.hpp"
#include "gcode/program_text.hpp"

namespace usina::gcode {
namespace {

// Nested brackets beyond this are an error, not a stack overflow.
constexpr int kMaxDepth = 64;
// A value or an operator takes at least one character: a block within the
// length limit stays within this.
constexpr std::size_t kMaxExprNodes = kMaxBlockLength;

struct SyntaxError {
  core::Code code;
  std::size_t pos;
  std::string message;
};

class Parser {
 public:
  Parser(std::string_view line, Block& block) : lex_(line), block_(block) {}

  void parse_line();
  std::optional<SyntaxError> error;

 private:
  bool fail(core::Code code, std::size_t pos, std::string message);
  ExprRef node(const ExprNode& n);
  // A plain number's node (ExprKind::Number), the value of nearly every word.
  ExprRef number_node(double value, std::size_t at);
  [[gnu::noinline]] ExprRef too_many_nodes(std::uint32_t at_col);
  ExprRef real_value(int depth);
  bool word_value(Word& word);
  bool exponent_in_range(std::size_t start);

  // Whether the number just read is followed by an E: nearly every number
  // is not, and then there is no exponent to ask about.
  bool at_exponent() {
    const std::string_view text = lex_.text();
    const std::size_t end = lex_.offset();
    return end < text.size() && (text[end] == 'e' || text[end] == 'E');
  }

  ExprRef expression(int depth);
  ExprRef function(std::size_t pos, int depth);
  ExprRef bracketed(int depth);
  ExprRef parameter(int depth);
  std::optional<std::string_view> angle_name();
  void o_word();
  void item();
  void comment_paren();

  std::uint32_t col(std::size_t pos) const { return static_cast<std::uint32_t>(pos + 1); }

  Lexer lex_;
  Block& block_;
};

bool Parser::fail(core::Code code, std::size_t pos, std::string message) {
  if (!error) error = SyntaxError{code, pos, std::move(message)};
  return false;
}

ExprRef Parser::node(const ExprNode& n) {
  // The evaluator recurses once per operator: a limit keeps a hostile line
  // from exhausting the stack (LinuxCNC's whole line is 255 characters).
  if (block_.exprs.size() >= kMaxExprNodes) return too_many_nodes(n.col);
  block_.exprs.push_back(n);
  return static_cast<ExprRef>(block_.exprs.size() - 1);
}

// Built in place: a node built apart and copied in was read back before its
// fields had all been written (a stalled store-to-load forward per value).
ExprRef Parser::number_node(double value, std::size_t at) {
  if (block_.exprs.size() >= kMaxExprNodes) return too_many_nodes(col(at));
  ExprNode& n = block_.exprs.emplace_back();
  n.value = value;
  n.col = col(at);
  return static_cast<ExprRef>(block_.exprs.size() - 1);
}

ExprRef Parser::too_many_nodes(std::uint32_t at_col) {
  fail(core::Code::BlockTooLong, at_col > 0 ? at_col - 1 : 0,
       fmt::format("a block with more than {} values and operators", kMaxExprNodes));
  return kNoExpr;
}

struct OpInfo {
  std::string_view spelling;
  BinOp op;
  int precedence;  // LinuxCNC interp_read.cc precedence()
};

constexpr std::array kBinaryOps = {
    OpInfo{"**", BinOp::Pow, 6},  OpInfo{"*", BinOp::Mul, 5}, OpInfo{"/", BinOp::Div, 5},
    OpInfo{"MOD", BinOp::Mod, 5}, OpInfo{"+", BinOp::Add, 4}, OpInfo{"-", BinOp::Sub, 4},
    OpInfo{"EQ", BinOp::Eq, 3},   OpInfo{"NE", BinOp::Ne, 3}, OpInfo{"GT", BinOp::Gt, 3},
    OpInfo{"GE", BinOp::Ge, 3},   OpInfo{"LT", BinOp::Lt, 3}, OpInfo{"LE", BinOp::Le, 3},
    OpInfo{"AND", BinOp::And, 2}, OpInfo{"OR", BinOp::Or, 2}, OpInfo{"XOR", BinOp::Xor, 2},
};

// Inside brackets: value (op value)*, left-associative, by precedence.
ExprRef Parser::expression(int depth) {
  struct Pending {
    ExprRef lhs;
    OpInfo op;
    std::size_t at;  // the operator's position, for its diagnostics
  };

  std::array<Pending, 8> stack{};
  std::size_t n = 0;
  ExprRef rhs = real_value(depth);
  if (rhs == kNoExpr) return kNoExpr;
  for (;;) {
    const std::size_t at = lex_.pos();
    const OpInfo* found = nullptr;
    for (const OpInfo& o : kBinaryOps) {
      if (lex_.accept_keyword(o.spelling)) {
        found = &o;
        break;
      }
    }
    // Reduce while the stacked operator binds at least as tightly.
    const int prec = found != nullptr ? found->precedence : 0;
    while (n > 0 && stack[n - 1].op.precedence >= prec) {
      --n;
      rhs = node({ExprKind::Binary,
                  static_cast<std::uint8_t>(stack[n].op.op),
                  stack[n].lhs,
                  rhs,
                  0.0,
                  {},
                  col(stack[n].at)});
    }
    if (found == nullptr) return rhs;
    if (n == stack.size()) {
      fail(core::Code::ExpectedExpression, at, "expression too deeply nested");
      return kNoExpr;
    }
    stack[n++] = {rhs, *found, at};
    rhs = real_value(depth);
    if (rhs == kNoExpr) return kNoExpr;
  }
}

ExprRef Parser::bracketed(int depth) {
  const std::size_t open = lex_.pos();
  if (!lex_.accept('[')) {
    fail(core::Code::ExpectedExpression, open, "expected '['");
    return kNoExpr;
  }
  if (depth > kMaxDepth) {
    fail(core::Code::ExpectedExpression, open, "brackets nested more than 64 deep");
    return kNoExpr;
  }
  const ExprRef e = expression(depth + 1);
  if (e == kNoExpr) return kNoExpr;
  if (!lex_.accept(']')) {
    fail(core::Code::UnclosedBracket, lex_.pos(),
         lex_.at_end() ? "missing ']' at end of block" : "expected ']' or an operator");
    return kNoExpr;
  }
  return e;
}

std::optional<std::string_view> Parser::angle_name() {
  const std::size_t at = lex_.pos();
  lex_.advance();  // '<'
  auto name = lex_.until('>');
  if (!name) {
    fail(core::Code::BadParameterName, at, "missing '>' after parameter name");
    return std::nullopt;
  }
  bool any = false;
  for (const char c : *name) {
    if (c == '(' || c == '<' || c == '#') {
      fail(core::Code::BadParameterName, at, fmt::format("'{}' in a name", c));
      return std::nullopt;
    }
    if (c != ' ' && c != '\t') any = true;
  }
  if (!any) {
    fail(core::Code::BadParameterName, at, "empty name in '<>'");
    return std::nullopt;
  }
  return name;
}

ExprRef Parser::parameter(int depth) {
  const std::size_t at = lex_.pos();
  lex_.advance();  // '#'
  if (lex_.peek() == '<') {
    auto name = angle_name();
    if (!name) return kNoExpr;
    return node({ExprKind::NamedParam, 0, kNoExpr, kNoExpr, 0.0, *name, col(at)});
  }
  const ExprRef index = real_value(depth + 1);
  if (index == kNoExpr) return kNoExpr;
  return node({ExprKind::Param, 0, index, kNoExpr, 0.0, {}, col(at)});
}

struct FuncInfo {
  std::string_view spelling;
  Func func;
};

constexpr std::array kFunctions = {
    FuncInfo{"ABS", Func::Abs},     FuncInfo{"ACOS", Func::Acos}, FuncInfo{"ASIN", Func::Asin},
    FuncInfo{"ATAN", Func::Atan},   FuncInfo{"COS", Func::Cos},   FuncInfo{"EXP", Func::Exp},
    FuncInfo{"FIX", Func::Fix},     FuncInfo{"FUP", Func::Fup},   FuncInfo{"LN", Func::Ln},
    FuncInfo{"ROUND", Func::Round}, FuncInfo{"SIN", Func::Sin},   FuncInfo{"SQRT", Func::Sqrt},
    FuncInfo{"TAN", Func::Tan},
};

ExprRef Parser::function(std::size_t pos, int depth) {
  if (lex_.accept_keyword("EXISTS")) {
    const std::size_t open = lex_.pos();
    if (!lex_.accept('[') || !lex_.accept('#')) {
      fail(core::Code::ExpectedExpression, open, "EXISTS takes [#<name>] or [#number]");
      return kNoExpr;
    }
    if (lex_.peek() != '<') {
      // EXISTS[#n]: whether n is a parameter number.
      const ExprRef index = real_value(depth + 1);
      if (index == kNoExpr) return kNoExpr;
      if (!lex_.accept(']')) {
        fail(core::Code::UnclosedBracket, lex_.pos(), "expected ']' after EXISTS[#number");
        return kNoExpr;
      }
      return node({ExprKind::Exists, 0, index, kNoExpr, 0.0, {}, col(pos)});
    }
    auto name = angle_name();
    if (!name) return kNoExpr;
    if (!lex_.accept(']')) {
      fail(core::Code::UnclosedBracket, lex_.pos(), "expected ']' after EXISTS[#<name>");
      return kNoExpr;
    }
    return node({ExprKind::Exists, 0, kNoExpr, kNoExpr, 0.0, *name, col(pos)});
  }
  for (const FuncInfo& f : kFunctions) {
    if (!lex_.accept_keyword(f.spelling)) continue;
    const ExprRef arg = bracketed(depth);
    if (arg == kNoExpr) return kNoExpr;
    // RS274NGC: ATAN[y]/[x] is the two-argument arc tangent.
    if (f.func == Func::Atan) {
      if (!lex_.accept('/')) {
        fail(core::Code::ExpectedExpression, lex_.pos(), "ATAN needs the form ATAN[y]/[x]");
        return kNoExpr;
      }
      const ExprRef x = bracketed(depth);
      if (x == kNoExpr) return kNoExpr;
      return node({ExprKind::Atan2, 0, arg, x, 0.0, {}, col(pos)});
    }
    return node(
        {ExprKind::Func, static_cast<std::uint8_t>(f.func), arg, kNoExpr, 0.0, {}, col(pos)});
  }
  fail(core::Code::UnknownFunction, pos, "unknown function or missing value");
  return kNoExpr;
}

// "1e400": no dialect has exponents, so it is 1 and a word E400, but the
// number the user meant is out of any range: say so (a legal "1e3" stays
// X1 E3, as the control reads it).
bool Parser::exponent_in_range(std::size_t start) {
  if (const auto ok = exponent_out_of_range(lex_.text(), start, lex_.offset()); !ok) {
    return fail(core::Code::NumberOutOfRange, start, ok.error());
  }
  return true;
}

ExprRef Parser::real_value(int depth) {
  const std::size_t at = lex_.pos();
  if (depth > kMaxDepth) {
    fail(core::Code::ExpectedExpression, at, "expression nested more than 64 deep");
    return kNoExpr;
  }
  const char c = lex_.peek();
  if (c == '[') {
    const ExprRef e = bracketed(depth);
    if (e != kNoExpr) block_.exprs[e].checked = true;
    return e;
  }
  if (c == '#') return parameter(depth);
  if (c == '-' || c == '+') {
    lex_.advance();
    const std::size_t digits = lex_.pos();
    if (auto v = lex_.number()) {
      if (at_exponent() && !exponent_in_range(digits)) return kNoExpr;
      return number_node(c == '-' ? -*v : *v, at);
    }
    const ExprRef inner = real_value(depth + 1);
    if (inner == kNoExpr || c == '+') return inner;
    return node({ExprKind::Negate, 0, inner, kNoExpr, 0.0, {}, col(at)});
  }
  if (auto v = lex_.number()) {
    if (at_exponent() && !exponent_in_range(at)) return kNoExpr;
    return number_node(*v, at);
  }
  if (c >= 'A' && c <= 'Z') return function(at, depth + 1);
  if (c >= '0' && c <= '9') {
    fail(core::Code::BadNumber, at, "number with more than 64 characters");
    return kNoExpr;
  }
  if (c == '.') {
    fail(core::Code::BadNumber, at, "a number needs at least one digit");
  } else if (c == '\0') {
    fail(core::Code::ExpectedExpression, at, "missing value at end of block");
  } else {
    fail(core::Code::ExpectedExpression, at, fmt::format("expected a value, found '{}'", c));
  }
  return kNoExpr;
}

// A word's value: a plain number kept in the word itself (nearly every
// word), else an expression in the block's arena, read by real_value.
bool Parser::word_value(Word& word) {
  const char c = lex_.peek();
  const bool sign = c == '-' || c == '+';
  if (sign || (c >= '0' && c <= '9') || c == '.') {
    const Lexer start = lex_;
    if (sign) lex_.advance();
    const std::size_t digits = lex_.pos();
    double v = 0.0;
    if (lex_.number(v)) {
      if (at_exponent() && !exponent_in_range(digits)) return false;
      word.value = kPlainNumber;
      word.number = c == '-' ? -v : v;
      return true;
    }
    lex_ = start;  // "-[...]", "-#1", a number too long: real_value says
  }
  word.value = real_value(0);
  return word.value != kNoExpr;
}

struct OKeyword {
  std::string_view spelling;
  OKind kind;
};

// Longer spellings first where one is a prefix of another.
constexpr std::array kOKeywords = {
    OKeyword{"SUB", OKind::Sub},
    OKeyword{"ENDSUB", OKind::EndSub},
    OKeyword{"CALL", OKind::Call},
    OKeyword{"RETURN", OKind::Return},
    OKeyword{"IF", OKind::If},
    OKeyword{"ELSEIF", OKind::ElseIf},
    OKeyword{"ELSE", OKind::Else},
    OKeyword{"ENDIF", OKind::EndIf},
    OKeyword{"WHILE", OKind::While},
    OKeyword{"ENDWHILE", OKind::EndWhile},
    OKeyword{"DO", OKind::Do},
    OKeyword{"REPEAT", OKind::Repeat},
    OKeyword{"ENDREPEAT", OKind::EndRepeat},
    OKeyword{"BREAK", OKind::Break},
    OKeyword{"CONTINUE", OKind::Continue},
};

std::string normalise_label(std::string_view raw) {
  std::string out;
  out.reserve(raw.size());
  for (const char c : raw) {
    if (c == ' ' || c == '\t') continue;
    out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return out;
}

const OKeyword* match_okeyword(Lexer& lex) {
  // Try the longest spelling that matches: ENDSUB before END..., ELSEIF before ELSE.
  const OKeyword* best = nullptr;
  std::size_t best_len = 0;
  for (const OKeyword& k : kOKeywords) {
    Lexer probe = lex;
    if (probe.accept_keyword(k.spelling) && k.spelling.size() > best_len) {
      best = &k;
      best_len = k.spelling.size();
    }
  }
  if (best != nullptr) lex.accept_keyword(best->spelling);
  return best;
}

void Parser::o_word() {
  const std::size_t at = lex_.pos();
  lex_.advance();  // 'O'
  OWord o;
  o.col = col(at);
  if (lex_.peek() == '<') {
    lex_.advance();
    auto name = lex_.until('>');
    if (!name || normalise_label(*name).empty()) {
      fail(core::Code::BadOWord, at, "O-word name needs the form o<name>");
      return;
    }
    o.label = normalise_label(*name);
  } else if (auto n = lex_.number()) {
    o.label = fmt::format("{}", *n);
  } else if (lex_.peek() == '#' || lex_.peek() == '[') {
    o.label_expr = real_value(1);
    if (o.label_expr == kNoExpr) return;
    o.label.assign(1, '#');
  } else {
    fail(core::Code::BadOWord, at, "O-word needs a number or <name>");
    return;
  }
  const std::size_t kw_at = lex_.pos();
  const OKeyword* kw = match_okeyword(lex_);
  // A bare number (O100, then only comments) starts a Fanuc-style subprogram.
  const char after = lex_.peek();
  if (kw == nullptr && (after == '\0' || after == '(' || after == ';') && o.label.front() != '<' &&
      std::isdigit(static_cast<unsigned char>(o.label.front()))) {
    o.kind = OKind::Program;
    block_.o = std::move(o);
    return;
  }
  if (kw == nullptr) {
    fail(core::Code::BadOWord, kw_at,
         "O-word needs a keyword: sub, endsub, call, return, if, elseif, else, endif, while, "
         "endwhile, do, repeat, endrepeat, break or continue");
    return;
  }
  o.kind = kw->kind;
  const bool needs_expr = o.kind == OKind::If || o.kind == OKind::ElseIf ||
                          o.kind == OKind::While || o.kind == OKind::Repeat;
  const bool may_expr = o.kind == OKind::Return || o.kind == OKind::EndSub;
  if (needs_expr || (may_expr && lex_.peek() == '[')) {
    o.expr = bracketed(0);
    if (o.expr == kNoExpr) return;
  } else if (o.kind == OKind::Call) {
    // Arguments, with comments allowed between them (LinuxCNC's flowsnake.ngc).
    for (;;) {
      if (lex_.peek() == '(') {
        comment_paren();
        if (error) return;
        continue;
      }
      if (lex_.peek() != '[') break;
      const ExprRef arg = bracketed(0);
      if (arg == kNoExpr) return;
      o.args.push_back(arg);
    }
  }
  block_.o = std::move(o);
}

void Parser::comment_paren() {
  const std::size_t at = lex_.pos();
  lex_.advance();  // '('
  auto text = lex_.until(')');
  if (!text) {
    fail(core::Code::UnclosedComment, at, "comment not closed with ')'");
    return;
  }
  block_.comments.push_back({*text, col(at)});
}

void Parser::item() {
  const std::size_t at = lex_.pos();
  const char c = lex_.peek();
  if (c == '(') {
    comment_paren();
  } else if (c == ';') {
    lex_.advance();
    block_.comments.push_back({lex_.rest(), col(at)});
  } else if (c == '#') {
    lex_.advance();
    ParamAssign a;
    a.col = col(at);
    if (lex_.peek() == '<') {
      auto name = angle_name();
      if (!name) return;
      a.name = *name;
    } else {
      a.index = real_value(1);
      if (a.index == kNoExpr) return;
    }
    if (!lex_.accept('=')) {
      fail(core::Code::ExpectedExpression, lex_.pos(), "expected '=' after the parameter");
      return;
    }
    a.value = real_value(0);
    if (a.value == kNoExpr) return;
    block_.assigns.push_back(a);
  } else if ((c >= 'A' && c <= 'Z') || c == '@' || c == '^') {
    if (c == 'O') {
      fail(core::Code::MisplacedOWord, at, "an O-word must start the block");
      return;
    }
    if (c == 'N') {
      fail(core::Code::UnknownWord, at, "a line number (N) must start the block");
      return;
    }
    lex_.advance();
    Word& word = block_.words.emplace_back();
    word.letter = c;
    word.col = col(at);
    if (!word_value(word)) block_.words.pop_back();
  } else {
    const auto raw = static_cast<unsigned char>(lex_.text()[at]);
    fail(core::Code::UnexpectedCharacter, at,
         raw >= 0x20 && raw < 0x7f ? fmt::format("unexpected character '{}'", c)
                                   : fmt::format("unexpected byte 0x{:02x}", raw));
  }
}

void Parser::parse_line() {
  if (lex_.accept('/')) block_.deleted = true;
  if (lex_.peek() == '%') {
    const std::size_t at = lex_.pos();
    lex_.advance();
    block_.percent = true;
    // LinuxCNC: '%' stands alone on its line (docs/rs274ngc.md, "'%' lines").
    if (!lex_.at_end() || block_.deleted) {
      fail(core::Code::MisplacedPercent, at,
           "'%' stands alone on its line (blanks allowed): move what else is on it to a line of "
           "its own");
    }
    return;
  }
  if (lex_.peek() == 'N') {
    const std::size_t at = lex_.pos();
    lex_.advance();
    auto n = lex_.number();
    if (!n) {
      fail(core::Code::BadNumber, at, "N needs a line number");
      return;
    }
    block_.line_number = n;
  }
  if (lex_.peek() == 'O') {
    o_word();
    if (error) return;
  }
  while (!error && !lex_.at_end())
    item();
  if (!error && block_.o && !block_.words.empty()) {
    fail(core::Code::MisplacedOWord, block_.words.front().col - 1,
         "an O-word statement takes no other words");
  }
}

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// A word's letter the shortcut reads: upper case, not N or O (errors
// anywhere but at the start of a block and an O-word's).
constexpr std::array<bool, 256> kPlainLetter = [] {
  std::array<bool, 256> t{};
  for (int c = 'A'; c <= 'Z'; ++c)
    t[static_cast<std::size_t>(c)] = c != 'N' && c != 'O';
  return t;
}();

// The unsigned plain number at line[i] and the blanks after it: where the
// next word starts (or the line ends), or 0 when the parser reads it
// otherwise: a blank inside the number ("X1 5" is X15), an E right after
// it (the parser asks whether it was an exponent), more than 15 digits.
// Aligned to 64 bytes: a fifth of check runs in its digit loops, and where
// the link happened to place it decided how they were fetched: rs274ngc
// check took 18 % longer with the same instructions (docs/performance.md).
[[gnu::aligned(64)]] std::size_t plain_number_at(std::string_view line, std::size_t i,
                                                 double& value) {
  const Decimal d = scan_decimal(line, i);
  if (d.digits == 0 || d.digits > decimal_detail::kExactDigits) return 0;
  std::size_t next = d.end;
  while (next < line.size() && is_blank(line[next]))
    ++next;
  if (next < line.size()) {
    const char c = line[next];
    if ((c >= '0' && c <= '9') || c == '.' || (c == 'E' && next == d.end)) return 0;
  }
  value = d.value;
  return next;
}

}  // namespace

bool parse_plain_block(std::string_view line, std::size_t i, Block& block) {
  while (i < line.size() && is_blank(line[i]))
    ++i;
  if (i + 1 < line.size() && line[i] == 'N') {
    double n = 0.0;
    i = plain_number_at(line, i + 1, n);
    if (i == 0) return false;
    block.line_number = n;
  }
  while (i < line.size()) {
    const char letter = line[i];
    // Lower case, comments, parameters and expressions go the whole way.
    if (!kPlainLetter[static_cast<unsigned char>(letter)]) return false;
    const std::size_t at = i++;
    const bool minus = i < line.size() && line[i] == '-';
    if (minus || (i < line.size() && line[i] == '+')) ++i;
    double v = 0.0;
    i = plain_number_at(line, i, v);
    if (i == 0) return false;
    block.words.push_back(
        {letter, kPlainNumber, static_cast<std::uint32_t>(at + 1), minus ? -v : v});
  }
  return !block.words.empty();
}

bool parse_block(std::string_view line, const LinePos& where, Block& block,
                 core::DiagnosticSink& diags) {
  block.clear();
  std::size_t first = 0;
  while (first < line.size() && (line[first] == ' ' || line[first] == '\t'))
    ++first;
  block.loc = {where.file, where.line, static_cast<std::uint32_t>(first + 1), 0, where.offset};
  if (parse_plain_block(line, first, block)) return true;
  block.words.clear();
  block.line_number.reset();
  Parser p(line, block);
  p.parse_line();
  if (!p.error) return true;
  core::SourceLoc loc = block.loc;
  loc.col = static_cast<std::uint32_t>(p.error->pos + 1);
  loc.length = 1;
  diags.report({p.error->code, core::Severity::Error, loc, p.error->message});
  return false;
}

}  // namespace usina::gcode
