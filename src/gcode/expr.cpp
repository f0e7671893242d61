#include "gcode/expr.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "gcode/parameters.hpp"

namespace usina::gcode {
namespace {

// LinuxCNC interp_internal.hh TOLERANCE_EQUAL: EQ, NE, LE and GE compare
// within it (interp_execute.cc execute_binary2); LT and GT do not.
constexpr double kEqualTolerance = 1e-4;

// LinuxCNC converts angles with M_PIl in long double (interp_execute.cc:
// sin((x * M_PIl) / 180.0), which C++ resolves to the long double sin;
// (asin(x) * 180.0) / M_PIl). Rounded to double, SIN[30] is then exactly 0.5
// and SIN[180] -5e-20 (double gives 0.49999999999999994 and +1.2e-16), and
// FIX, comparisons and LN decide as LinuxCNC does.
constexpr long double kPi = std::numbers::pi_v<long double>;

long double radians(double degrees) {
  return (static_cast<long double>(degrees) * kPi) / 180.0L;
}

double degrees(double radians) {
  return static_cast<double>((static_cast<long double>(radians) * 180.0L) / kPi);
}

std::string not_finite(double v) {
  return fmt::format(
      "the value is {}: beyond the largest number (about ±1.8e308) or undefined; check the "
      "arithmetic",
      v);
}

class Evaluator {
 public:
  Evaluator(const Block& block, const ParameterSource& params, EvalError& err)
      : block_(block), params_(params), err_(err) {}

  std::optional<double> eval(ExprRef ref);

 private:
  std::optional<double> fail(std::uint32_t col, core::Code code, std::string message) {
    err_ = {{code, std::move(message)}, col};
    return std::nullopt;
  }

  // A function's result and a checked operation's value must be finite
  // (ExprNode::checked says which are checked).
  std::optional<double> finite(const ExprNode& n, std::optional<double> v) {
    if (!v || std::isfinite(*v)) return v;
    return fail(n.col, core::Code::NumberOutOfRange, not_finite(*v));
  }

  std::optional<double> binary(const ExprNode& n, double a, double b);
  std::optional<double> function(const ExprNode& n, double a);
  std::optional<double> parameter(const ExprNode& n);

  const Block& block_;
  const ParameterSource& params_;
  EvalError& err_;
};

std::optional<double> Evaluator::eval(ExprRef ref) {
  const ExprNode& n = block_.expr(ref);
  switch (n.kind) {
  case ExprKind::Number: return n.value;
  case ExprKind::Param:
  case ExprKind::NamedParam: return parameter(n);
  case ExprKind::Exists: {
    if (n.a == kNoExpr) return params_.named(normalise_name(n.name)) ? 1.0 : 0.0;
    auto idx = eval(n.a);
    if (!idx) return std::nullopt;
    return (std::round(*idx) == *idx && *idx >= 1 && *idx <= kMaxParameter) ? 1.0 : 0.0;
  }
  case ExprKind::Negate: {
    auto a = eval(n.a);
    if (!a) return std::nullopt;
    return -*a;
  }
  case ExprKind::Func: {
    auto a = eval(n.a);
    if (!a) return std::nullopt;
    return finite(n, function(n, *a));
  }
  case ExprKind::Atan2:
  case ExprKind::Binary: {
    auto a = eval(n.a);
    if (!a) return std::nullopt;
    auto b = eval(n.b);
    if (!b) return std::nullopt;
    if (n.kind == ExprKind::Atan2) return finite(n, degrees(std::atan2(*a, *b)));
    if (n.checked) return finite(n, binary(n, *a, *b));
    return binary(n, *a, *b);
  }
  }
  return fail(n.col, core::Code::ExpectedExpression, "bad expression");
}

std::optional<double> Evaluator::parameter(const ExprNode& n) {
  if (n.kind == ExprKind::NamedParam) {
    const std::string name = normalise_name(n.name);
    if (auto v = params_.named(name)) return v;
    return fail(n.col, core::Code::UndefinedParameter,
                fmt::format("named parameter #<{}> is not defined", name));
  }
  auto idx = eval(n.a);
  if (!idx) return std::nullopt;
  auto index = parameter_index(*idx, n.col, err_);
  if (!index) return std::nullopt;
  return params_.numbered(*index);
}

std::optional<double> Evaluator::binary(const ExprNode& n, double a, double b) {
  switch (static_cast<BinOp>(n.op)) {
  case BinOp::Pow:
    if (a < 0.0 && std::floor(b) != b) {
      return fail(n.col, core::Code::DomainError,
                  fmt::format("negative base {} to a non-integer power {}", a, b));
    }
    return std::pow(a, b);
  case BinOp::Mul: return a * b;
  case BinOp::Div:
    if (b == 0.0) return fail(n.col, core::Code::DivisionByZero, fmt::format("{} / 0", a));
    return a / b;
  case BinOp::Mod: {
    if (b == 0.0) return fail(n.col, core::Code::DivisionByZero, fmt::format("{} MOD 0", a));
    double r = std::fmod(a, b);
    if (r < 0.0) r += std::fabs(b);  // LinuxCNC: the result is never negative
    return r;
  }
  case BinOp::Add: return a + b;
  case BinOp::Sub: return a - b;
  case BinOp::Eq: return std::fabs(a - b) < kEqualTolerance ? 1.0 : 0.0;
  case BinOp::Ne: return std::fabs(a - b) >= kEqualTolerance ? 1.0 : 0.0;
  case BinOp::Gt: return a > b ? 1.0 : 0.0;
  case BinOp::Ge: return (std::fabs(a - b) < kEqualTolerance || a >= b) ? 1.0 : 0.0;
  case BinOp::Lt: return a < b ? 1.0 : 0.0;
  case BinOp::Le: return (std::fabs(a - b) < kEqualTolerance || a <= b) ? 1.0 : 0.0;
  case BinOp::And: return (a != 0.0 && b != 0.0) ? 1.0 : 0.0;
  case BinOp::Or: return (a != 0.0 || b != 0.0) ? 1.0 : 0.0;
  case BinOp::Xor: return ((a != 0.0) != (b != 0.0)) ? 1.0 : 0.0;
  }
  return fail(n.col, core::Code::ExpectedExpression, "bad operator");
}

std::optional<double> Evaluator::function(const ExprNode& n, double a) {
  switch (static_cast<Func>(n.op)) {
  // LinuxCNC negates only what is below zero: ABS[-0] stays -0, which
  // ATAN's quadrant tells apart (differential fuzzer, seed 10432060).
  case Func::Abs: return a < 0.0 ? -a : a;
  case Func::Acos:
  case Func::Asin:
    if (a < -1.0 || a > 1.0) {
      return fail(n.col, core::Code::DomainError,
                  fmt::format("{}[{}]: the argument must be within -1 and 1",
                              static_cast<Func>(n.op) == Func::Acos ? "ACOS" : "ASIN", a));
    }
    return degrees(static_cast<Func>(n.op) == Func::Acos ? std::acos(a) : std::asin(a));
  case Func::Atan: return degrees(std::atan(a));
  case Func::Cos: return static_cast<double>(std::cos(radians(a)));
  case Func::Exp: return std::exp(a);
  case Func::Fix: return std::floor(a);
  case Func::Fup: return std::ceil(a);
  case Func::Ln:
    if (a <= 0.0) {
      return fail(n.col, core::Code::DomainError,
                  fmt::format("LN[{}]: the argument must be positive", a));
    }
    return std::log(a);
  case Func::Round: {
    // Halves away from zero, as LinuxCNC, whose ROUND goes through an int:
    // what rounds to zero is +0, never -0 (ATAN[ROUND[-0.3]]/[-1] is 180).
    const double r = std::round(a);
    return r == 0.0 ? 0.0 : r;
  }
  case Func::Sin: return static_cast<double>(std::sin(radians(a)));
  case Func::Sqrt:
    if (a < 0.0) {
      return fail(n.col, core::Code::DomainError,
                  fmt::format("SQRT[{}]: the argument must not be negative", a));
    }
    return std::sqrt(a);
  case Func::Tan: return static_cast<double>(std::tan(radians(a)));
  case Func::Log10:
    if (a <= 0.0) {
      return fail(n.col, core::Code::DomainError,
                  fmt::format("LOG({}): the argument must be positive", a));
    }
    return std::log10(a);
  case Func::Trunc: return std::trunc(a);
  }
  return fail(n.col, core::Code::UnknownFunction, "bad function");
}

}  // namespace

std::optional<int> parameter_index(double value, std::uint32_t col, EvalError& err) {
  const double rounded = std::round(value);
  // Written so that NaN fails every test.
  if (!(std::fabs(value - rounded) <= 1e-4 && rounded >= 1.0 && rounded <= kMaxParameter)) {
    err = {{core::Code::ParameterOutOfRange,
            fmt::format("parameter number {} is not an integer within 1 and {}", value,
                        kMaxParameter)},
           col};
    return std::nullopt;
  }
  return static_cast<int>(rounded);
}

std::optional<double> evaluate(const Block& block, ExprRef ref, const ParameterSource& params,
                               EvalError& err) {
  Evaluator e(block, params, err);
  auto v = e.eval(ref);
  if (v && !std::isfinite(*v)) {
    err = {{core::Code::NumberOutOfRange, not_finite(*v)}, block.expr(ref).col};
    return std::nullopt;
  }
  return v;
}

}  // namespace usina::gcode
