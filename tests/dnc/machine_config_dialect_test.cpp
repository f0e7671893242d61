// A [[machine]]'s dialect is one usina reads (found by fuzz_config: any
// string was accepted, and every punch of the machine refused later).
#include <string>

#include <gtest/gtest.h>

#include "dnc/machine_config.hpp"

namespace usina::dnc {
namespace {

std::string machine(const std::string& dialect_line) {
  return "[[machine]]\nname = \"m1\"\nport = \"/dev/ttyS0\"\n" + dialect_line;
}

TEST(MachineConfigDialect, AnUnknownDialectIsAnErrorAtItsLine) {
  core::DiagnosticList diags;
  EXPECT_FALSE(read_machine_links(machine("dialect = \"no-such-control\"\n"), 0, diags));
  ASSERT_EQ(diags.all().size(), 1u);
  const core::Diagnostic& d = diags.all()[0];
  EXPECT_EQ(d.code, core::Code::DncConfig);
  EXPECT_EQ(d.loc.line, 4u);
  EXPECT_NE(d.message.find("dialect = \"no-such-control\" is no dialect usina reads"),
            std::string::npos)
      << d.message;
  EXPECT_NE(d.message.find("rs274ngc"), std::string::npos) << d.message;
}

TEST(MachineConfigDialect, EveryKnownDialectAndTheDefaultAreRead) {
  for (const char* line :
       {"", "dialect = \"rs274ngc\"\n", "dialect = \"fanuc\"\n", "dialect = \"romi\"\n"}) {
    core::DiagnosticList diags;
    const auto links = read_machine_links(machine(line), 0, diags);
    ASSERT_TRUE(links) << line;
    EXPECT_TRUE(diags.all().empty()) << line;
  }
}

}  // namespace
}  // namespace usina::dnc
