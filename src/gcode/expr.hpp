// Evaluation of RS274NGC expressions with LinuxCNC's semantics: angles in
// degrees, EQ, NE, LE and GE within 1e-4, MOD never negative.
#pragma once

#include <optional>
#include <string_view>

#include "gcode/block.hpp"
#include "gcode/interp/interp_error.hpp"

namespace usina::gcode {

// Where an expression reads its parameters from.
class ParameterSource {
 public:
  virtual ~ParameterSource() = default;
  // #index; `index` is already checked to be in 1..5602.
  virtual double numbered(int index) const = 0;
  // #<name> (normalised); nullopt when not defined.
  virtual std::optional<double> named(std::string_view name) const = 0;
};

struct EvalError {
  InterpError error;
  std::uint32_t col = 0;
};

// The value of `ref` in `block`; on error, nullopt and `err` set.
std::optional<double> evaluate(const Block& block, ExprRef ref, const ParameterSource& params,
                               EvalError& err);

// A word's value: its plain number, or its expression evaluated.
inline std::optional<double> evaluate_word(const Block& block, const Word& word,
                                           const ParameterSource& params, EvalError& err) {
  if (word.value == kPlainNumber) return word.number;
  return evaluate(block, word.value, params, err);
}

// An expression's value as a parameter index: an integer (within 1e-4, as
// LinuxCNC's read_integer_value) in 1..5602.
std::optional<int> parameter_index(double value, std::uint32_t col, EvalError& err);

}  // namespace usina::gcode
