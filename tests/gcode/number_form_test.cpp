// Forms of numbers a user may try (issue 11: "1e400 is reported as 'E word
// with no code'"). No dialect has exponents, so "1e3" stays the number 1
// and a word E3, as the controls read it; an exponent that makes a number
// beyond any double is reported as that.
#include "gcode/number_form.hpp"

#include <string>

#include <gtest/gtest.h>

#include "support/dialect_run.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using dialect_test::run_in;

// The problem a check reports, or "" when there is none.
std::string problem(const tl::expected<void, std::string>& checked) {
  return checked ? std::string() : checked.error();
}

struct First {
  Code code = Code::Message;
  std::uint32_t col = 0;
  std::string message;
};

First first_error(const char* dialect, const std::string& text) {
  auto r = run_in(dialect, text);
  for (const core::Diagnostic& d : r->diags.all()) {
    if (d.severity == core::Severity::Error) return {d.code, d.loc.col, d.message};
  }
  return {};
}

void expect_error(const char* dialect, const std::string& text, Code code, std::uint32_t col) {
  SCOPED_TRACE(text);
  const First f = first_error(dialect, text);
  EXPECT_EQ(core::code_name(f.code), core::code_name(code)) << f.message;
  EXPECT_EQ(f.col, col) << f.message;
}

TEST(NumberForm, ExponentBeyondADoubleIsOutOfRange) {
  EXPECT_EQ(problem(exponent_out_of_range("1e400", 0, 1)).find("number 1e400 is out of range"), 0u);
  EXPECT_FALSE(exponent_out_of_range("X1.5E-400", 1, 4).has_value());
  EXPECT_FALSE(exponent_out_of_range("-1e+999", 0, 2).has_value());  // the sign is skipped
  EXPECT_TRUE(exponent_out_of_range("1e3", 0, 1).has_value());       // a number and E3
  EXPECT_TRUE(exponent_out_of_range("1e308", 0, 1).has_value());
  EXPECT_TRUE(exponent_out_of_range("0e-999", 0, 1).has_value());  // zero is zero
  EXPECT_TRUE(exponent_out_of_range("1 e400", 0, 1).has_value());  // not one literal
  EXPECT_TRUE(exponent_out_of_range("1e", 0, 1).has_value());
  EXPECT_TRUE(exponent_out_of_range("1ex", 0, 1).has_value());
  EXPECT_TRUE(exponent_out_of_range("[1]e400", 0, 3).has_value());  // not a literal
}

TEST(NumberForm, Rs274ngcSaysTheNumberIsOutOfRange) {
  expect_error("rs274ngc", "G0 X1e400\nM2\n", Code::NumberOutOfRange, 5);
  expect_error("rs274ngc", "G0 X1e-400\nM2\n", Code::NumberOutOfRange, 5);
  expect_error("rs274ngc", "G0 X-1e400\nM2\n", Code::NumberOutOfRange, 6);
  expect_error("rs274ngc", "G0 X[2*1e400]\nM2\n", Code::NumberOutOfRange, 8);
  expect_error("rs274ngc", "#1=1e400\nM2\n", Code::NumberOutOfRange, 4);
  const First f = first_error("rs274ngc", "G0 X1e400\nM2\n");
  EXPECT_NE(f.message.find("out of range"), std::string::npos) << f.message;
  EXPECT_NE(f.message.find("E word"), std::string::npos) << f.message;
}

TEST(NumberForm, AnExponentInRangeReadsAsTheControlReadsIt) {
  // LinuxCNC reads X1e3 as X1 E3; E is used by G76 and M66 only.
  expect_error("rs274ngc", "G0 X1e3\nM2\n", Code::UnusedWord, 6);
}

TEST(NumberForm, OtherForms) {
  // More than 64 characters: refused before it is a number.
  expect_error("rs274ngc", "G0 X" + std::string(70, '1') + "\nM2\n", Code::BadNumber, 5);
  // 60 digits is a number, 1.1e59: beyond the range of a word's value.
  expect_error("rs274ngc", "G0 X" + std::string(60, '1') + "\nM2\n", Code::ValueOutOfRange, 4);
  // Hexadecimal is X0 and then a second X word.
  expect_error("rs274ngc", "G0 X0x10\nM2\n", Code::RepeatedWord, 6);
  expect_error("rs274ngc", "G0 X1.2.3\nM2\n", Code::UnexpectedCharacter, 8);
  expect_error("rs274ngc", "G0 X.\nM2\n", Code::BadNumber, 5);
}

TEST(NumberForm, RomiAndFanuc) {
  expect_error("romi", "G0 X1e400\nM30\n", Code::NumberOutOfRange, 5);
  expect_error("fanuc", "G0 X1e400\nM30\n", Code::NumberOutOfRange, 5);
  expect_error("fanuc", "G0 X-1e-400\nM30\n", Code::NumberOutOfRange, 5);
  // Fanuc reads digits without a limit: 400 of them are beyond any double.
  expect_error("fanuc", "G0 X" + std::string(400, '9') + ".\nM30\n", Code::NumberOutOfRange, 5);
  expect_error("fanuc", "G0 X1e3\nM30\n", Code::UnusedWord, 6);
}

}  // namespace
}  // namespace usina::gcode
