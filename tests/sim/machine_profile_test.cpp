#include "sim/machine_profile.hpp"

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace usina::sim {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const char* kMinimal = R"(
[machine]
name = "m"
units = "mm"
[axes.x]
min = -10
max = 10
rapid = 1000
max_feed = 500
accel = 100
[axes.y]
min = -10
max = 10
rapid = 1000
max_feed = 500
accel = 100
[axes.z]
min = -10
max = 0
rapid = 1000
max_feed = 500
accel = 100
)";

TEST(MachineProfile, ShippedProfilesAreValid) {
  for (const char* name : {"small_vmc", "hobby_router", "romi_mill"}) {
    core::DiagnosticList diags;
    const std::string path =
        std::string(USINA_TEST_DIR) + "/../examples/machines/" + name + ".toml";
    auto p = read_machine_profile(slurp(path), 0, diags);
    ASSERT_TRUE(p.has_value()) << name;
    EXPECT_FALSE(diags.has_errors()) << name;
    EXPECT_FALSE(p->name.empty()) << name;
    EXPECT_TRUE(p->axes[2].present) << name;
  }
}

TEST(MachineProfile, ReadsEveryKey) {
  core::DiagnosticList diags;
  auto p = read_machine_profile(
      slurp(std::string(USINA_TEST_DIR) + "/../examples/machines/small_vmc.toml"), 0, diags);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->name, "small VMC");
  EXPECT_DOUBLE_EQ(p->axes[0].min, -300.0);
  EXPECT_DOUBLE_EQ(p->axes[0].rapid, 24000.0);
  EXPECT_DOUBLE_EQ(p->axes[2].accel, 1500.0);
  EXPECT_FALSE(p->axes[3].present);
  EXPECT_DOUBLE_EQ(p->spindle_max_rpm, 10000.0);
  EXPECT_DOUBLE_EQ(p->spindle_accel_time, 1.5);
  EXPECT_DOUBLE_EQ(p->tool_change_time, 6.0);
  EXPECT_DOUBLE_EQ(p->cost_per_hour, 60.0);
}

TEST(MachineProfile, InchFileIsConvertedToMm) {
  std::string text = kMinimal;
  text.replace(text.find("units = \"mm\""), 12, "units = \"inch\"");
  core::DiagnosticList diags;
  auto p = read_machine_profile(text, 0, diags);
  ASSERT_TRUE(p);
  EXPECT_TRUE(p->file_in_inch);
  EXPECT_DOUBLE_EQ(p->axes[0].max, 254.0);
  EXPECT_DOUBLE_EQ(p->axes[0].rapid, 25400.0);
  EXPECT_DOUBLE_EQ(p->axes[0].accel, 2540.0);
}

TEST(MachineProfile, OptionalSectionsDefaultToZero) {
  core::DiagnosticList diags;
  auto p = read_machine_profile(kMinimal, 0, diags);
  ASSERT_TRUE(p);
  EXPECT_DOUBLE_EQ(p->tool_change_time, 0.0);
  EXPECT_DOUBLE_EQ(p->axes[0].jerk, 0.0);
}

// kMinimal with `find` replaced by `replacement` (the whole text when `find`
// is null) must be refused with a message holding `fragment`, at `line` of
// the file (0: the line is not checked).
struct BadProfile {
  const char* what;  // the rule the row checks
  const char* find;
  const char* replacement;
  const char* fragment;
  std::uint32_t line;
};

constexpr BadProfile kBadProfiles[] = {
    {"not TOML at all", nullptr, "[machine\nname = 1\n", "not valid TOML", 1},
    {"a missing axis section is named",
     "[axes.z]\nmin = -10\nmax = 0\nrapid = 1000\nmax_feed = 500\naccel = 100\n", "", "[axes.z]",
     0},
    {"a missing key is named", "accel = 100", "", "'accel'", 0},
    {"a wrong type, at its line", "rapid = 1000", "rapid = \"fast\"", "rapid must be a number", 8},
    {"a negative rate, at its line", "max_feed = 500", "max_feed = -5",
     "max_feed = -5 is out of range", 9},
    {"min above max", "min = -10", "min = 20", "min is above max", 0},
    {"units other than mm and inch", "units = \"mm\"", "units = \"cm\"",
     "must be \"mm\" or \"inch\"", 4},
    {"a zero rapid", "rapid = 1000", "rapid = 0", "rapid = 0 is out of range", 8},
};

TEST(MachineProfileError, EachBadProfileIsRefusedWithItsMessage) {
  for (const BadProfile& c : kBadProfiles) {
    SCOPED_TRACE(c.what);
    std::string text = c.replacement;
    if (c.find != nullptr) {
      text = kMinimal;
      const std::string find = c.find;
      const auto at = text.find(find);
      ASSERT_NE(at, std::string::npos) << find;
      text.replace(at, find.size(), c.replacement);
    }
    core::DiagnosticList diags;
    auto p = read_machine_profile(text, 3, diags);
    EXPECT_FALSE(p.has_value());
    ASSERT_FALSE(diags.all().empty());
    const core::Diagnostic& d = diags.all().front();
    EXPECT_EQ(d.code, core::Code::BadMachineProfile);
    EXPECT_EQ(d.loc.file, 3u);
    EXPECT_NE(d.message.find(c.fragment), std::string::npos) << d.message;
    if (c.line > 0) {
      EXPECT_EQ(d.loc.line, c.line) << d.message;
    }
  }
}

}  // namespace
}  // namespace usina::sim
