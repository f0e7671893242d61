// Step 1 of an RS274NGC block: every word's value and every assignment's
// value read, before any assignment takes effect (RS274NGC 3.2.1); the
// result goes down the one road (run_evaluated) as any dialect's does.
#include <fmt/format.h>

#include "gcode/interp/block_words.hpp"
#include "gcode/interp/interpreter.hpp"

namespace usina::gcode {

EvaluatedBlock Interpreter::evaluated(const Block& b) const {
  return {b.loc, evaluated_, assigns_, b.comments};
}

bool Interpreter::evaluate(const Block& b) {
  assigns_.clear();
  // Sized once and written in place: a push_back's capacity test and
  // element-wise construction were a third of the step (issue 19).
  evaluated_.resize(b.words.size());
  EvaluatedWord* out = evaluated_.data();
  for (const Word& word : b.words) {
    // No std::optional on the way of a plain number: built field by field
    // and read back whole, it stalled every word (a failed store forward).
    double v = word.number;
    if (word.value != kPlainNumber) {
      EvalError err;
      const auto e = gcode::evaluate(b, word.value, *this, err);
      if (!e) {
        evaluated_.resize(static_cast<std::size_t>(out - evaluated_.data()));
        return evaluation_failed(err.error.code, err.col, err.error.message);
      }
      v = *e;
    }
    *out++ = {word.letter, v, word.col};
  }
  return b.assigns.empty() || evaluate_assigns(b);
}

bool Interpreter::evaluate_assigns(const Block& b) {
  EvalError err;
  for (const ParamAssign& a : b.assigns) {
    auto v = gcode::evaluate(b, a.value, *this, err);
    if (!v) return evaluation_failed(err.error.code, err.col, err.error.message);
    if (a.index == kNoExpr) {
      std::string name = normalise_name(a.name);
      if (predefined(name)) {
        return evaluation_failed(core::Code::ReadOnlyParameter, a.col,
                                 fmt::format("#<{}> is a read-only parameter", name));
      }
      assigns_.push_back({0, std::move(name), *v, a.col});
      continue;
    }
    auto idx = gcode::evaluate(b, a.index, *this, err);
    if (!idx) return evaluation_failed(err.error.code, err.col, err.error.message);
    auto index = parameter_index(*idx, a.col, err);
    if (!index) return evaluation_failed(err.error.code, err.col, err.error.message);
    assigns_.push_back({*index, {}, *v, a.col});
  }
  return true;
}

// The words are checked as they are read, so a word that cannot be placed
// (an unknown code, a repeated letter) before the value that failed is the
// error the block reports, as it always was.
bool Interpreter::evaluation_failed(core::Code code, std::uint32_t col, std::string message) {
  if (!sort_words(evaluated_, *words_)) return false;
  return error(code, col, std::move(message));
}

}  // namespace usina::gcode
