// The syntax of one block (one line of RS274NGC): words, parameter
// assignments, an O-word statement, comments. No evaluation, no modal
// knowledge. Expressions live in a small arena owned by the block, which is
// reused from block to block, so a long program allocates nothing per block.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"

namespace usina::gcode {

using ExprRef = std::uint32_t;
inline constexpr ExprRef kNoExpr = 0xffffffffu;

enum class ExprKind : std::uint8_t {
  Number,      // value
  Param,       // #a
  NamedParam,  // #<name>
  Negate,      // -a
  Binary,      // a op b
  Func,        // func[a]
  Atan2,       // atan[a]/[b]
  Exists,      // exists[#<name>]
};

// Binary operators, by RS274NGC precedence groups (LinuxCNC interp_read.cc).
enum class BinOp : std::uint8_t {
  Pow,
  Mul,
  Div,
  Mod,
  Add,
  Sub,
  Eq,
  Ne,
  Gt,
  Ge,
  Lt,
  Le,
  And,
  Or,
  Xor
};

enum class Func : std::uint8_t {
  Abs,
  Acos,
  Asin,
  Atan,
  Cos,
  Exp,
  Fix,
  Fup,
  Ln,
  Round,
  Sin,
  Sqrt,
  Tan,
  Log10,  // Fagor LOG
  Trunc,  // Fagor INT: the integer part, toward zero
};

struct ExprNode {
  ExprKind kind = ExprKind::Number;
  std::uint8_t op = 0;  // BinOp or Func
  ExprRef a = kNoExpr;
  ExprRef b = kNoExpr;
  double value = 0.0;
  std::string_view name;  // NamedParam, Exists: as written (normalised on use)
  std::uint32_t col = 0;
  // Whether an operation's value must be finite where it is made (a
  // function's result always must). rs274ngc sets it on a bracket read as a
  // value ("[a + b]" in "X[a + b]" or "2 * [a + b]"): LinuxCNC
  // (read_real_value) refuses such a value, but not what one operation
  // hands the next inside a bracket: "[10 ** 400 GT 0]" is 1,
  // "[[10 ** 400] GT 0]" and "[EXP[720] GT 0]" are errors, and a
  // function's own bracket is not checked ("ATAN[10 ** 400]/[1]" is 90).
  // romi sets it on every operation, as a control's overflow alarm.
  bool checked = false;
};

// A word's value that is a plain number ("X12.5", nearly every word): kept
// in the word, with no node to write and read back.
inline constexpr ExprRef kPlainNumber = 0xfffffffeu;

struct Word {
  char letter = 0;          // upper case; '@' and '^' for polar words
  ExprRef value = kNoExpr;  // the expression, or kPlainNumber: then `number`
  std::uint32_t col = 0;
  double number = 0.0;
};

struct ParamAssign {
  ExprRef index = kNoExpr;  // numbered: #index = value
  std::string_view name;    // named: #<name> = value (index is kNoExpr)
  ExprRef value = kNoExpr;
  std::uint32_t col = 0;
};

struct CommentText {
  std::string_view text;  // inside the parentheses, or after ';'
  std::uint32_t col = 0;
};

enum class OKind : std::uint8_t {
  Sub,
  EndSub,
  Call,
  Return,
  If,
  ElseIf,
  Else,
  EndIf,
  While,
  EndWhile,
  Do,
  Repeat,
  EndRepeat,
  Break,
  Continue,
  Program,  // a bare O-number: a Fanuc-style subprogram (M98 P..) starts here
};

const char* okind_name(OKind k);

struct OWord {
  OKind kind = OKind::Sub;
  std::string label;             // "100" or a name, lower case, blanks removed
  ExprRef label_expr = kNoExpr;  // o#1 / o[..]: the label is this value (calls only)
  ExprRef expr = kNoExpr;        // condition, repeat count or return value
  std::vector<ExprRef> args;     // call arguments
  std::uint32_t col = 0;
};

struct Block {
  core::SourceLoc loc;   // line, column of the block's first character
  bool deleted = false;  // block delete '/'
  bool percent = false;  // a '%' line
  std::optional<double> line_number;
  std::vector<Word> words;
  std::vector<ParamAssign> assigns;
  std::vector<CommentText> comments;
  std::optional<OWord> o;
  std::vector<ExprNode> exprs;

  void clear();

  bool empty() const { return words.empty() && assigns.empty() && !o && comments.empty(); }

  const ExprNode& expr(ExprRef r) const { return exprs[r]; }
};

}  // namespace usina::gcode
