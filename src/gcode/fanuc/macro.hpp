// Custom Macro B expressions (docs/fanuc.md §3.1, §4): values that may be
// vacant, '[ ]' grouping, Fanuc's precedence (AND with '*', OR XOR with
// '+', bitwise), its functions in degrees and its rounding, and relations
// only inside the bracketed condition of IF and WHILE.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/diagnostic.hpp"

namespace usina::gcode::fanuc {

struct Value {
  double v = 0.0;
  bool vacant = false;
};

struct MacroError {
  core::Code code = core::Code::ExpectedExpression;
  std::size_t pos = 0;  // in the text read
  std::string message;
};

// Where variable values come from (the engine's store).
class VariableSource {
 public:
  virtual ~VariableSource() = default;
  // The value of #index, or nullopt with `err` set.
  virtual std::optional<Value> read(long index, MacroError& err) = 0;
};

class MacroReader {
 public:
  MacroReader(std::string_view text, VariableSource& vars) : text_(text), vars_(vars) {}

  // An expression: a number, a variable, '[ ]', a function, operators.
  std::optional<Value> expression();
  // The variable number after '#' ('#12', '#[#1+100]'); `pos` at the '#'.
  std::optional<long> variable_number();
  // '[ cond ]' of IF/WHILE: true or false.
  std::optional<bool> condition();

  // The next letters spelled as a keyword (upper case), consumed if they
  // match `word`.
  bool keyword(std::string_view word);
  bool accept(char c);
  bool at_end();
  char peek();

  std::size_t pos() const { return i_; }

  void set_pos(std::size_t p) { i_ = p; }

  std::string_view text() const { return text_; }

  const MacroError& error() const { return err_; }

  // Whether the last expression read was one variable reference ('#1',
  // '-#1'): a vacant one then leaves its word out of an NC block.
  bool single_variable() const { return single_var_; }

  // Whether the literal number just read had a decimal point.
  bool had_point() const { return had_point_; }

  bool literal() const { return literal_; }

  bool relation_used() const { return relation_; }

  std::nullopt_t fail(core::Code code, std::string message);

  // ROUND in an NC address rounds to the address's least increment
  // (docs/fanuc.md §4); 0, in macro statements, to an integer.
  void set_round_step(double step) { round_step_ = step; }

 private:
  void blanks();
  std::optional<Value> sum();
  std::optional<Value> product();
  std::optional<Value> unary();
  std::optional<Value> primary();
  std::optional<Value> bracket();
  std::optional<Value> function(std::string_view name);
  std::optional<Value> calculated(double v);
  std::optional<double> number();
  std::optional<Value> plain_number();
  std::string_view letters();

  std::string_view text_;
  VariableSource& vars_;
  std::size_t i_ = 0;
  int depth_ = 0;
  bool single_var_ = false;
  bool had_point_ = false;
  bool literal_ = false;
  bool relation_ = false;
  double round_step_ = 0.0;
  MacroError err_;
};

// Fanuc's functions and operators on plain numbers (unit-tested apart).
// Digits with at most one point from text[i] on, correctly rounded
// (gcode/decimal.hpp, as MacroReader::number and every dialect read them);
// `i` ends at the first other character. False, `i` unchanged, when there
// is no digit, or the number is beyond a double.
bool plain_digits(std::string_view text, std::size_t& i, double& v, bool& had_point);

double fix(double x);  // toward zero
double fup(double x);  // away from zero
double round_half_away(double x);
double round_to_step(double x, double step);  // half away from zero
double atan2_deg(double a, double b);         // angle of (b, a), 0 <= r < 360
double fanuc_mod(double a, double b);         // both rounded to integers; sign of a

}  // namespace usina::gcode::fanuc
