// Warnings and notes carry W_ and N_ codes, never an E_ code (issue 11:
// "warnings carry E_ codes"): programs that warn in each dialect, a tool
// table and a parameter file that warn.
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "gcode/tool_table.hpp"
#include "gcode/var_file.hpp"
#include "support/dialect_run.hpp"

namespace usina::gcode {
namespace {

using core::Code;
using dialect_test::run_in;

// Every diagnostic of `diags` that is not an error has a W_ or N_ code, and
// there is at least one: returns their codes.
std::string expect_warning_codes(const core::DiagnosticList& diags) {
  std::string codes;
  for (const core::Diagnostic& d : diags.all()) {
    if (d.severity == core::Severity::Error) continue;
    const std::string_view name = core::code_name(d.code);
    const std::string_view want = d.severity == core::Severity::Warning ? "W_" : "N_";
    EXPECT_EQ(name.substr(0, 2), want) << name << ": " << d.message;
    codes += std::string(name) + " ";
  }
  EXPECT_FALSE(codes.empty());
  return codes;
}

TEST(WarningCodes, Rs274ngc) {
  auto r = run_in("rs274ngc", "\xEF\xBB\xBFG0 X1 (MSG, hello)\n");  // BOM, message, no end
  const std::string codes = expect_warning_codes(r->diags);
  EXPECT_NE(codes.find("W_BYTE_ORDER_MARK"), std::string::npos) << codes;
  EXPECT_NE(codes.find("N_MESSAGE"), std::string::npos) << codes;
  EXPECT_NE(codes.find("W_NO_PROGRAM_END"), std::string::npos) << codes;
}

TEST(WarningCodes, FanucUnknownOffsetRegister) {
  auto r = run_in("fanuc", "G43 H5 Z10\nG0 X1\n");
  const std::string codes = expect_warning_codes(r->diags);
  EXPECT_NE(codes.find("W_UNKNOWN_OFFSET_REGISTER"), std::string::npos) << codes;
  EXPECT_NE(codes.find("W_INTEGER_COORDINATE"), std::string::npos) << codes;
}

TEST(WarningCodes, Romi) {
  auto r = run_in("romi",
                  "\xEF\xBB\xBFG0 X\xE2\x80\x93"
                  "1\nG81 R2 Z-5\nX0 Y0\n");
  const std::string codes = expect_warning_codes(r->diags);
  EXPECT_NE(codes.find("W_TYPOGRAPHIC_DASH"), std::string::npos) << codes;
}

TEST(WarningCodes, Grbl) {
  auto r = run_in("grbl", "G0 X1 ?\nM2\nG0 X2\n");
  expect_warning_codes(r->diags);
}

TEST(WarningCodes, ToolTableAndVarFile) {
  core::DiagnosticList tool_diags;
  const auto tools = core::SourceFile::from_string("t.tbl", "T1 Z1\nT1 P2\n");
  read_tool_table(*tools, 1, 1.0, tool_diags);
  const std::string t = expect_warning_codes(tool_diags);
  EXPECT_NE(t.find("W_TOOL_WITHOUT_POCKET"), std::string::npos) << t;
  EXPECT_NE(t.find("W_TOOL_REDEFINED"), std::string::npos) << t;
  core::DiagnosticList var_diags;
  const auto vars = core::SourceFile::from_string("p.var", "# offsets\n5221 1.0 X\n");
  read_var_file(*vars, 1, var_diags);
  const std::string v = expect_warning_codes(var_diags);
  EXPECT_NE(v.find("W_VAR_FILE_LINE_SKIPPED"), std::string::npos) << v;
  EXPECT_NE(v.find("W_VAR_FILE_EXTRA_TEXT"), std::string::npos) << v;
}

}  // namespace
}  // namespace usina::gcode
