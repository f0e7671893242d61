// Custom Macro B expressions of the fanuc dialect, one rule each
// (docs/fanuc.md §3.1 vacancy, §4 functions and precedence).
#include "gcode/fanuc/macro.hpp"

#include <map>

#include <gtest/gtest.h>

namespace usina::gcode::fanuc {
namespace {

class Vars : public VariableSource {
 public:
  std::map<long, double> set;

  std::optional<Value> read(long index, MacroError& err) override {
    if (index < 0 || index > 999) {
      err.code = core::Code::ParameterOutOfRange;
      err.message = "out of range";
      return std::nullopt;
    }
    auto it = set.find(index);
    return it == set.end() ? Value{0.0, true} : Value{it->second};
  }
};

std::optional<Value> eval(const std::string& text, Vars& v) {
  MacroReader r(text, v);
  auto x = r.expression();
  if (x && !r.at_end()) return std::nullopt;
  return x;
}

double value(const std::string& text) {
  Vars v;
  v.set[2] = 0.0;
  auto x = eval(text, v);
  EXPECT_TRUE(x.has_value()) << text;
  return x ? x->v : -999.0;
}

bool cond(const std::string& text) {
  Vars v;
  v.set[2] = 0.0;  // #1 vacant, #2 = 0
  MacroReader r(text, v);
  auto c = r.condition();
  EXPECT_TRUE(c.has_value()) << text;
  return c.value_or(false);
}

TEST(FanucMacro, VacantStaysVacantOnlyInAPlainReference) {
  Vars v;
  EXPECT_TRUE(eval("#1", v)->vacant);
  EXPECT_FALSE(eval("#1 + 1", v)->vacant);
  EXPECT_DOUBLE_EQ(eval("#1 + 1", v)->v, 1.0);
  EXPECT_DOUBLE_EQ(eval("1 + #1", v)->v, 1.0);
  EXPECT_DOUBLE_EQ(eval("#1 * 5", v)->v, 0.0);
  EXPECT_DOUBLE_EQ(eval("#1 + #1", v)->v, 0.0);
  EXPECT_FALSE(eval("[#1]", v)->vacant);
  EXPECT_DOUBLE_EQ(eval("SIN[#1]", v)->v, 0.0);
  EXPECT_TRUE(eval("#0", v)->vacant);
}

TEST(FanucMacro, VacantDiffersFromZeroOnlyForEqAndNe) {
  EXPECT_TRUE(cond("[#1 EQ #0]"));
  EXPECT_FALSE(cond("[#2 EQ #0]"));
  EXPECT_TRUE(cond("[#1 NE 0]"));
  EXPECT_FALSE(cond("[#2 NE 0]"));
  EXPECT_FALSE(cond("[#1 EQ 0]"));
  EXPECT_TRUE(cond("[#2 EQ 0]"));
  EXPECT_TRUE(cond("[#1 GE #0]"));
  EXPECT_FALSE(cond("[#1 GT 0]"));
  EXPECT_TRUE(cond("[#1 LE #0]"));
  EXPECT_FALSE(cond("[#1 LT 0]"));
}

TEST(FanucMacro, FixFupRoundAndAtanOfNegativeValues) {
  EXPECT_DOUBLE_EQ(value("FIX[-1.2]"), -1.0);
  EXPECT_DOUBLE_EQ(value("FUP[-1.2]"), -2.0);
  EXPECT_DOUBLE_EQ(value("FUP[1.2]"), 2.0);
  EXPECT_DOUBLE_EQ(value("ROUND[-2.5]"), -3.0);
  EXPECT_DOUBLE_EQ(value("ATAN[-1]/[-1]"), 225.0);
  EXPECT_DOUBLE_EQ(value("ATAN[-1]/[1]"), 315.0);
  EXPECT_DOUBLE_EQ(value("ATAN[1]/[1]"), 45.0);
  EXPECT_NEAR(value("ASIN[-1]"), 270.0, 1e-9);
  EXPECT_NEAR(value("ACOS[-1]"), 180.0, 1e-9);
  EXPECT_NEAR(value("SQRT[16] + ABS[-2] + LN[1] + EXP[0]"), 7.0, 1e-12);
  EXPECT_DOUBLE_EQ(value("BIN[16]"), 10.0);
  EXPECT_DOUBLE_EQ(value("BCD[10]"), 16.0);
}

TEST(FanucMacro, AndBindsLikeTimesOrLikePlusBitwise) {
  EXPECT_DOUBLE_EQ(value("1 + 6 AND 3"), 3.0);  // 1 + (6 AND 3)
  EXPECT_DOUBLE_EQ(value("4 OR 1 * 2"), 6.0);   // 4 OR (1 * 2)
  EXPECT_DOUBLE_EQ(value("5 XOR 1"), 4.0);
  EXPECT_DOUBLE_EQ(value("7 MOD 3"), 1.0);
  EXPECT_DOUBLE_EQ(value("-7 MOD 3"), -1.0);  // sign of the dividend
  EXPECT_DOUBLE_EQ(value("2 + 3 * 4"), 14.0);
}

TEST(FanucMacro, LogicalAndOfBracketedConditions) {
  EXPECT_TRUE(cond("[[#2 EQ 0] AND [#1 EQ #0]]"));
  EXPECT_FALSE(cond("[[#2 EQ 1] OR [#1 NE #0]]"));
}

TEST(FanucMacro, BracketsNestFiveDeepNotSix) {
  Vars v;
  EXPECT_TRUE(eval("[[[[[1]]]]]", v).has_value());
  MacroReader r("[[[[[[1]]]]]]", v);
  EXPECT_FALSE(r.expression().has_value());
  EXPECT_EQ(r.error().code, core::Code::UnclosedBracket);
}

TEST(FanucMacro, ErrorsHaveCodes) {
  Vars v;
  auto code = [&](const std::string& text) {
    MacroReader r(text, v);
    EXPECT_FALSE(r.expression().has_value()) << text;
    return r.error().code;
  };
  EXPECT_EQ(code("5 / 0"), core::Code::DivisionByZero);
  EXPECT_EQ(code("5 / #1"), core::Code::DivisionByZero);
  EXPECT_EQ(code("SQRT[-1]"), core::Code::DomainError);
  EXPECT_EQ(code("LN[0]"), core::Code::DomainError);
  EXPECT_EQ(code("FOO[1]"), core::Code::UnknownFunction);
  EXPECT_EQ(code("#-1"), core::Code::BadParameterName);
  EXPECT_EQ(code("[1 + 2"), core::Code::UnclosedBracket);
  EXPECT_EQ(code("#2000"), core::Code::ParameterOutOfRange);
  EXPECT_EQ(code("*5"), core::Code::ExpectedExpression);
  EXPECT_EQ(code("5 +"), core::Code::ExpectedExpression);
}

// Alarm 111 at the operation that overflows, even where what follows would
// hide it: a comparison, a division, a sum that comes back in range.
TEST(FanucMacro, EveryOperationThatOverflowsIsAlarm111) {
  Vars v;
  v.set[1] = 720.0;
  for (const char* text : {"[EXP[#1] GT 0]", "1 / EXP[#1]", "[1 / [EXP[#1]]]", "EXP[#1] - EXP[#1]",
                           "[10 * EXP[709]] / 100", "ATAN[EXP[#1]]"}) {
    MacroReader r(text, v);
    EXPECT_FALSE(r.expression().has_value()) << text;
    EXPECT_EQ(r.error().code, core::Code::NumberOutOfRange) << text << ": " << r.error().message;
  }
  EXPECT_DOUBLE_EQ(value("[EXP[700] GT 0]"), 1.0);
}

TEST(FanucMacro, IndirectVariable) {
  Vars v;
  v.set[1] = 3;
  v.set[103] = 42;
  EXPECT_DOUBLE_EQ(eval("#[#1 + 100]", v)->v, 42.0);
}

TEST(FanucMacro, FunctionsOnPlainNumbers) {
  EXPECT_DOUBLE_EQ(fix(-2.7), -2.0);
  EXPECT_DOUBLE_EQ(fup(-2.2), -3.0);
  EXPECT_DOUBLE_EQ(round_half_away(2.5), 3.0);
  EXPECT_DOUBLE_EQ(atan2_deg(0, -1), 180.0);
  EXPECT_DOUBLE_EQ(fanuc_mod(7.4, 3), 1.0);
}

}  // namespace
}  // namespace usina::gcode::fanuc
