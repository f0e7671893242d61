#include "gcode/expr.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "core/units.hpp"
#include "gcode/parameters.hpp"
#include "gcode/parser.hpp"

namespace usina::gcode {
namespace {

using core::Code;

class MapParams final : public ParameterSource {
 public:
  double numbered(int index) const override {
    last_index = index;
    auto it = numbers.find(index);
    return it != numbers.end() ? it->second : 0.0;
  }

  std::optional<double> named(std::string_view name) const override {
    auto it = names.find(std::string(name));
    if (it == names.end()) return std::nullopt;
    return it->second;
  }

  std::map<int, double> numbers;
  std::map<std::string, double> names;
  mutable int last_index = 0;
};

struct Result {
  std::optional<double> value;
  EvalError err;
};

// Evaluates `expr` as the value of an X word: the line is "X" + expr, so
// column n of `expr` is column n + 1 of the line.
Result eval(const std::string& expr, const MapParams& params = MapParams{}) {
  const std::string line = "X" + expr;
  Block b;
  core::DiagnosticList diags;
  Result r;
  const bool ok = parse_block(line, {0, 1, 0}, b, diags);
  EXPECT_TRUE(ok) << line << ": " << (diags.all().empty() ? "" : diags.all()[0].message);
  if (!ok || b.words.size() != 1) return r;
  r.value = evaluate_word(b, b.words[0], params, r.err);
  return r;
}

double value_of(const std::string& expr, const MapParams& params = MapParams{}) {
  const Result r = eval(expr, params);
  EXPECT_TRUE(r.value.has_value()) << expr << ": " << r.err.error.message;
  return r.value.value_or(std::nan(""));
}

// The error of `expr`: its code and column in the line "X" + expr.
std::pair<std::string_view, std::uint32_t> error_of(const std::string& expr,
                                                    const MapParams& params = MapParams{}) {
  const Result r = eval(expr, params);
  EXPECT_FALSE(r.value.has_value()) << expr << " gave " << r.value.value_or(0);
  EXPECT_FALSE(r.err.error.message.empty()) << expr;
  return {core::code_name(r.err.error.code), r.err.col};
}

// --- arithmetic and functions ----------------------------------------------

// An expression and the value it must have; `tol` 0 asks for the exact value.
struct ValueCase {
  const char* what;  // the rule the row checks
  const char* expr;
  double want;
  double tol;
};

constexpr ValueCase kValueCases[] = {
    {"trigonometry is in degrees", "SIN[30]", 0.5, 1e-12},
    {"trigonometry is in degrees", "COS[60]", 0.5, 1e-12},
    {"trigonometry is in degrees", "TAN[45]", 1.0, 1e-12},
    {"trigonometry is in degrees", "ASIN[1]", 90.0, 1e-12},
    {"trigonometry is in degrees", "ACOS[0]", 90.0, 1e-12},
    {"trigonometry is in degrees", "ACOS[-1]", 180.0, 1e-12},
    {"trigonometry is in degrees", "ATAN[1]/[1]", 45.0, 1e-12},
    {"ATAN of two arguments keeps the quadrant", "ATAN[1]/[-1]", 135.0, 1e-12},
    {"ATAN of two arguments keeps the quadrant", "ATAN[-1]/[-1]", -135.0, 1e-12},
    {"ATAN of two arguments keeps the quadrant", "ATAN[-1]/[1]", -45.0, 1e-12},
    {"ATAN of two arguments keeps the quadrant", "ATAN[1]/[0]", 90.0, 1e-12},
    // LinuxCNC interp_execute.cc: fmod, then + |b| when negative.
    {"MOD takes the divisor's magnitude, never negative", "[7 MOD 3]", 1.0, 0},
    {"MOD takes the divisor's magnitude, never negative", "[-7 MOD 3]", 2.0, 0},
    {"MOD takes the divisor's magnitude, never negative", "[-7 MOD -3]", 2.0, 0},
    {"MOD takes the divisor's magnitude, never negative", "[7 MOD -3]", 1.0, 0},
    {"MOD takes the divisor's magnitude, never negative", "[6 MOD 3]", 0.0, 0},
    {"MOD takes the divisor's magnitude, never negative", "[5.5 MOD 2]", 1.5, 1e-12},
    // LinuxCNC TOLERANCE_EQUAL = 0.0001.
    {"EQ and NE compare within 0.0001", "[1 EQ 1.00005]", 1.0, 0},
    {"EQ and NE compare within 0.0001", "[1 EQ 1.0002]", 0.0, 0},
    {"EQ and NE compare within 0.0001", "[1 NE 1.00005]", 0.0, 0},
    {"EQ and NE compare within 0.0001", "[1 NE 1.0002]", 1.0, 0},
    {"ordering comparisons are exact", "[1 GT 1.00005]", 0.0, 0},
    {"ordering comparisons are exact", "[1.00005 GT 1]", 1.0, 0},
    {"ordering comparisons are exact", "[2 GE 2]", 1.0, 0},
    {"ordering comparisons are exact", "[2 LT 2]", 0.0, 0},
    {"ordering comparisons are exact", "[2 LE 2]", 1.0, 0},
    {"ordering comparisons are exact", "[1 LT 2]", 1.0, 0},
    {"logical operators treat non-zero as true", "[2 AND 3]", 1.0, 0},
    {"logical operators treat non-zero as true", "[2 AND 0]", 0.0, 0},
    {"logical operators treat non-zero as true", "[0 OR 0]", 0.0, 0},
    {"logical operators treat non-zero as true", "[0 OR -1]", 1.0, 0},
    {"logical operators treat non-zero as true", "[1 XOR 1]", 0.0, 0},
    {"logical operators treat non-zero as true", "[1 XOR 0]", 1.0, 0},
    {"ROUND halves away from zero", "ROUND[2.5]", 3.0, 0},
    {"ROUND halves away from zero", "ROUND[-2.5]", -3.0, 0},
    {"ROUND halves away from zero", "ROUND[0.4999]", 0.0, 0},
    {"ROUND halves away from zero", "ROUND[1.5]", 2.0, 0},
    {"FIX rounds down, FUP rounds up", "FIX[1.9]", 1.0, 0},
    {"FIX rounds down, FUP rounds up", "FIX[-1.5]", -2.0, 0},
    {"FIX rounds down, FUP rounds up", "FUP[1.2]", 2.0, 0},
    {"FIX rounds down, FUP rounds up", "FUP[-1.5]", -1.0, 0},
    {"FIX rounds down, FUP rounds up", "FIX[3]", 3.0, 0},
    {"FIX rounds down, FUP rounds up", "FUP[3]", 3.0, 0},
    {"EXP, LN, SQRT, ABS", "EXP[1]", 2.718281828459045, 1e-15},  // e
    {"EXP, LN, SQRT, ABS", "LN[EXP[2]]", 2.0, 1e-12},
    {"EXP, LN, SQRT, ABS", "SQRT[2.25]", 1.5, 0},
    {"EXP, LN, SQRT, ABS", "SQRT[0]", 0.0, 0},
    {"EXP, LN, SQRT, ABS", "ABS[-3.5]", 3.5, 0},
    {"a negative base to an integer power", "[-2 ** 3]", -8.0, 0},
    {"a negative base to an integer power", "[2 ** -1]", 0.5, 0},
    {"division is floating point", "[1/4]", 0.25, 0},
};

TEST(Expr, OperatorsAndFunctionsGiveTheirValues) {
  for (const ValueCase& c : kValueCases) {
    SCOPED_TRACE(std::string(c.what) + ": " + c.expr);
    if (c.tol == 0) {
      EXPECT_EQ(value_of(c.expr), c.want);
    } else {
      EXPECT_NEAR(value_of(c.expr), c.want, c.tol);
    }
  }
}

// --- parameters -------------------------------------------------------------

TEST(Expr, NumberedParameterIsReadFromTheSource) {
  MapParams p;
  p.numbers[100] = 4.5;
  EXPECT_EQ(value_of("#100", p), 4.5);
  EXPECT_EQ(p.last_index, 100);
}

TEST(Expr, IndirectParameter) {
  MapParams p;
  p.numbers[1] = 100;
  p.numbers[100] = 9;
  EXPECT_EQ(value_of("##1", p), 9.0);
  EXPECT_EQ(value_of("#[#1]", p), 9.0);
}

TEST(Expr, NamedParameterNameIsNormalised) {
  MapParams p;
  p.names["depthofcut"] = 0.75;
  EXPECT_EQ(value_of("#<Depth Of Cut>", p), 0.75);
  EXPECT_EQ(value_of("#<depthofcut>", p), 0.75);
}

TEST(Expr, IndexWithinOneTenThousandthOfAnIntegerIsThatInteger) {
  MapParams p;
  p.numbers[2] = 7;
  EXPECT_EQ(value_of("#[2.00005]", p), 7.0);
  EXPECT_EQ(value_of("#[1.99995]", p), 7.0);
}

TEST(Expr, ExistsOfNamedParameter) {
  MapParams p;
  p.names["_tool_dia"] = 6;
  EXPECT_EQ(value_of("EXISTS[#<_Tool_Dia>]", p), 1.0);
  EXPECT_EQ(value_of("EXISTS[#<_other>]", p), 0.0);
}

TEST(Expr, ExistsOfNumberedParameterIsWhetherTheNumberIsValid) {
  EXPECT_EQ(value_of("EXISTS[#1]"), 1.0);
  EXPECT_EQ(value_of("EXISTS[#5602]"), 1.0);
  EXPECT_EQ(value_of("EXISTS[#5603]"), 0.0);
  EXPECT_EQ(value_of("EXISTS[#0]"), 0.0);
  EXPECT_EQ(value_of("EXISTS[#1.5]"), 0.0);
}

TEST(ParameterIndex, AcceptsIntegersWithinRange) {
  EvalError err;
  EXPECT_EQ(parameter_index(1.0, 3, err), 1);
  EXPECT_EQ(parameter_index(5602.0, 3, err), 5602);
  EXPECT_EQ(parameter_index(0.99995, 3, err), 1);
}

TEST(ParameterIndex, RejectsOutOfRangeAndFractionsWithTheColumn) {
  for (const double v :
       {0.0, -1.0, 5603.0, 2.5, 1e12, -1e12, std::numeric_limits<double>::infinity()}) {
    EvalError err;
    EXPECT_FALSE(parameter_index(v, 9, err).has_value()) << v;
    EXPECT_EQ(core::code_name(err.error.code), "E_PARAMETER_OUT_OF_RANGE") << v;
    EXPECT_EQ(err.col, 9u) << v;
  }
}

// Regression (a bug the tests found, fixed): parameter_index(NaN) returns a value: every comparison
// with NaN is false, so it passes the range checks and static_cast<int>(NaN) (undefined behaviour;
// INT_MIN on x86) is returned. Expected: nullopt and E_PARAMETER_OUT_OF_RANGE. Actual: an index of
// -2147483648, which Interpreter::numbered() then reads out of bounds (`#1=#[[10**400]-[10**400]]`
// crashes `usina trace` with SIGSEGV).
TEST(ParameterIndex, RejectsNotANumber) {
  EvalError err;
  EXPECT_FALSE(parameter_index(std::nan(""), 4, err).has_value());
  EXPECT_EQ(core::code_name(err.error.code), "E_PARAMETER_OUT_OF_RANGE");
}

TEST(NormaliseName, LowerCaseWithoutBlanks) {
  EXPECT_EQ(normalise_name(" My\tVar "), "myvar");
  EXPECT_EQ(normalise_name("_GLOBAL"), "_global");
}

// --- errors: code and column ------------------------------------------------

// An expression that must fail with `code`, at column `col` of the line
// "X" + expr (0: the column is not checked).
struct ErrorCase {
  const char* what;  // the rule the row checks
  const char* expr;
  Code code;
  std::uint32_t col;
};

constexpr ErrorCase kErrorCases[] = {
    {"division by zero", "[1/0]", Code::DivisionByZero, 0},
    {"division by a zero parameter", "[5/#3]", Code::DivisionByZero, 0},
    {"MOD by zero", "[5 MOD 0]", Code::DivisionByZero, 0},
    {"a negative base to a fractional power", "[-8 ** 0.5]", Code::DomainError, 0},
    // Regression (a bug the tests found, fixed): a binary operator's error points at the token
    // after its right operand (the ']' or the next operator), not at the operator. Expected:
    // `X[1/0]` reports column 4 (the '/'); actual: column 6 (the ']'). The parser gave a Binary
    // node the column of the lookahead at the time it reduced.
    {"a binary operator's error points at the operator", "[1/0]", Code::DivisionByZero, 4},
    {"a binary operator's error points at the operator", "[1/0+5]", Code::DivisionByZero, 4},
    {"a binary operator's error points at the operator", "[5 MOD 0]", Code::DivisionByZero, 5},
    {"a binary operator's error points at the operator", "[-8**0.5]", Code::DomainError, 5},
    {"SQRT of a negative points at the function", "[1+SQRT[-1]]", Code::DomainError, 5},
    {"LN of zero", "LN[0]", Code::DomainError, 2},
    {"LN of a negative", "LN[-1]", Code::DomainError, 2},
    {"ACOS outside -1..1", "ACOS[1.5]", Code::DomainError, 2},
    {"ASIN outside -1..1", "ASIN[-1.01]", Code::DomainError, 2},
    {"an undefined named parameter points at the hash", "[2*#<nope>]", Code::UndefinedParameter, 5},
    {"parameter number zero", "#0", Code::ParameterOutOfRange, 2},
    {"a parameter number above the last", "[1+#5603]", Code::ParameterOutOfRange, 5},
    {"a parameter number not an integer", "#[1.5]", Code::ParameterOutOfRange, 2},
    {"a negative parameter number", "#-2", Code::ParameterOutOfRange, 2},
    {"an infinite result is out of range", "[10**400]", Code::NumberOutOfRange, 0},
    {"an infinite result is out of range", "EXP[1000]", Code::NumberOutOfRange, 0},
    {"an error inside a function's argument stops evaluation", "SIN[#<undefined>]",
     Code::UndefinedParameter, 0},
    {"an error inside a function's argument stops evaluation", "ATAN[1]/[1/0]",
     Code::DivisionByZero, 0},
};

TEST(ExprError, EachErrorHasItsCodeAndColumn) {
  for (const ErrorCase& c : kErrorCases) {
    SCOPED_TRACE(std::string(c.what) + ": " + c.expr);
    const auto [code, col] = error_of(c.expr);
    EXPECT_EQ(code, core::code_name(c.code));
    if (c.col != 0) {
      EXPECT_EQ(col, c.col);
    }
  }
}

TEST(ExprError, UndefinedNamedParameterIsNamedInTheMessage) {
  const Result r = eval("#<Nope>");
  EXPECT_NE(r.err.error.message.find("#<nope>"), std::string::npos) << r.err.error.message;
}

// Regression (a bug the tests found, fixed): same cause as
// ParameterIndex.DISABLED_RejectsNotANumber. Expected: an error (E_PARAMETER_OUT_OF_RANGE or
// E_NUMBER_OUT_OF_RANGE) and no read. Actual: numbered(-2147483648) is called and its value
// returned.
TEST(ExprError, NotANumberAsAParameterIndexIsAnErrorNotARead) {
  // inf - inf is NaN; reading #NaN must be refused before the source is asked.
  MapParams p;
  p.last_index = -1;
  const Result r = eval("#[[10**400]-[10**400]]", p);
  EXPECT_FALSE(r.value.has_value());
  EXPECT_EQ(p.last_index, -1) << "numbered() was asked for index " << p.last_index;
}

}  // namespace
}  // namespace usina::gcode
