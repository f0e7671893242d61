// What fuzz_config found in the machine profile reader: a value of the wrong
// kind that was read as something else without a word (a name that is no
// string read as none, 2.5 segments read as 2, units = 5 reported as "").
#include <string>

#include <gtest/gtest.h>

#include "sim/machine_profile.hpp"

namespace usina::sim {
namespace {

std::string profile(const std::string& machine, const std::string& planner = "") {
  std::string axes;
  for (const char* a : {"x", "y", "z"}) {
    axes += std::string("[axes.") + a +
            "]\nmin = -10\nmax = 10\nrapid = 1000\nmax_feed = 500\naccel = 100\n";
  }
  return "[machine]\n" + machine + axes + (planner.empty() ? "" : "[planner]\n" + planner);
}

// The first error's message, or "" when the profile was read.
std::string error_of(const std::string& text, std::uint32_t* line = nullptr) {
  core::DiagnosticList diags;
  const auto p = read_machine_profile(text, 0, diags);
  for (const core::Diagnostic& d : diags.all()) {
    if (d.severity != core::Severity::Error) continue;
    EXPECT_FALSE(p);
    if (line != nullptr) *line = d.loc.line;
    return d.message;
  }
  EXPECT_TRUE(p);
  return "";
}

TEST(MachineProfileValues, ANameThatIsNoStringIsAnErrorAtItsLine) {
  std::uint32_t line = 0;
  EXPECT_NE(error_of(profile("name = 5\n"), &line).find("name must be a string"),
            std::string::npos);
  EXPECT_EQ(line, 2u);
  EXPECT_EQ(error_of(profile("name = \"Mill 1\"\n")), "");
}

TEST(MachineProfileValues, UnitsThatAreNoStringSayWhatIsWrong) {
  EXPECT_NE(error_of(profile("units = 5\n")).find("units must be the string"), std::string::npos);
  EXPECT_NE(error_of(profile("units = \"cm\"\n")).find("units = \"cm\""), std::string::npos);
}

TEST(MachineProfileValues, AFractionOfASegmentIsNoOptimizationDepth) {
  EXPECT_NE(error_of(profile("", "optimization_depth = 2.5\n")).find("must be a whole number"),
            std::string::npos);
  core::DiagnosticList diags;
  const auto p = read_machine_profile(profile("", "optimization_depth = 30.0\n"), 0, diags);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->linuxcnc.optimization_depth, 30u);
}

TEST(MachineProfileValues, NumbersAtTheEdgesOfADoubleAreErrors) {
  for (const char* v : {"nan", "inf", "-inf", "1e308", "-1e308", "1.7976931348623157e308"}) {
    const std::string text = profile("") + "[cost]\nper_hour = " + v + "\n";
    EXPECT_NE(error_of(text), "") << v;
  }
  EXPECT_EQ(error_of(profile("") + "[cost]\nper_hour = -0.0\n"), "");
}

}  // namespace
}  // namespace usina::sim
