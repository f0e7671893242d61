// A subroutine name is only ever a file name (issue 11: "a '/' in an O-word
// name says 'unknown subroutine' instead of why").
#include "gcode/sub_name.hpp"

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

TEST(SubroutineName, WhatCannotBeAFileNameIsSaid) {
  using namespace std::string_literals;
  EXPECT_TRUE(subroutine_name_problem("pocket_2").has_value());
  EXPECT_TRUE(subroutine_name_problem("$(id)").has_value());  // never given to a shell
  EXPECT_NE(problem(subroutine_name_problem("a/b")).find("'/'"), std::string::npos);
  EXPECT_NE(problem(subroutine_name_problem("a\\b")).find("'\\'"), std::string::npos);
  EXPECT_NE(problem(subroutine_name_problem("..")).find("'.'"), std::string::npos);
  EXPECT_FALSE(subroutine_name_problem(".hidden").has_value());
  EXPECT_NE(problem(subroutine_name_problem("a\0b"s)).find("0x00"), std::string::npos);
  EXPECT_FALSE(subroutine_name_problem("a\x1b[2Jb").has_value());
  EXPECT_FALSE(subroutine_name_problem(std::string(252, 'a')).has_value());
  EXPECT_TRUE(subroutine_name_problem(std::string(251, 'a')).has_value());
}

std::string first_error(const std::string& text, Code& code) {
  auto r = run_in("rs274ngc", text);
  for (const core::Diagnostic& d : r->diags.all()) {
    if (d.severity == core::Severity::Error) {
      code = d.code;
      return d.message;
    }
  }
  code = Code::Message;
  return {};
}

TEST(SubroutineName, ASlashInACalledNameSaysWhy) {
  Code code{};
  const std::string m = first_error("o<a/b> call\nM2\n", code);
  EXPECT_EQ(code, Code::BadSubroutineName);
  EXPECT_NE(m.find("contains '/'"), std::string::npos) << m;
  EXPECT_NE(m.find("not a path"), std::string::npos) << m;
}

TEST(SubroutineName, OtherEscapesSayWhy) {
  using namespace std::string_literals;
  for (const std::string& name : {".."s, "../x"s, "a\\b"s, ".ngc"s, "a\0b"s}) {
    Code code{};
    const std::string m = first_error("o<" + name + "> call\nM2\n", code);
    EXPECT_EQ(code, Code::BadSubroutineName) << name << ": " << m;
    EXPECT_EQ(m.find('\0'), std::string::npos);  // shown as \x00, not raw
  }
}

TEST(SubroutineName, ANameDefinedInTheProgramNeedsNoFile) {
  // Only a file name is restricted: a subroutine of the program may be named so.
  auto r = run_in("rs274ngc", "o<a/b> sub\nG0 X1\no<a/b> endsub\no<a/b> call\nM2\n");
  EXPECT_TRUE(r->ok);
  EXPECT_FALSE(r->diags.has_errors());
}

TEST(SubroutineName, AnUnknownPlainNameIsStillUnknown) {
  Code code{};
  first_error("o<nothere> call\nM2\n", code);
  EXPECT_EQ(code, Code::UnknownSubroutine);
}

}  // namespace
}  // namespace usina::gcode
