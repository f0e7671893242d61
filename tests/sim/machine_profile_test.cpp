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

void expect_error(const std::string& text, const std::string& fragment, std::uint32_t line) {
  core::DiagnosticList diags;
  auto p = read_machine_profile(text, 3, diags);
  EXPECT_FALSE(p.has_value()) << fragment;
  ASSERT_FALSE(diags.all().empty()) << fragment;
  const core::Diagnostic& d = diags.all().front();
  EXPECT_EQ(d.code, core::Code::BadMachineProfile);
  EXPECT_EQ(d.loc.file, 3u);
  EXPECT_NE(d.message.find(fragment), std::string::npos) << d.message;
  if (line > 0) {
    EXPECT_EQ(d.loc.line, line) << d.message;
  }
}

TEST(MachineProfileError, NotToml) {
  expect_error("[machine\nname = 1\n", "not valid TOML", 1);
}

TEST(MachineProfileError, MissingAxisSection) {
  std::string text = kMinimal;
  text = text.substr(0, text.find("[axes.z]"));
  expect_error(text, "[axes.z]", 0);
}

TEST(MachineProfileError, MissingKeyNamesIt) {
  std::string text = kMinimal;
  text.replace(text.find("accel = 100"), 11, "");
  expect_error(text, "'accel'", 0);
}

TEST(MachineProfileError, WrongTypeAtItsLine) {
  std::string text = kMinimal;
  text.replace(text.find("rapid = 1000"), 12, "rapid = \"fast\"");
  expect_error(text, "rapid must be a number", 8);
}

TEST(MachineProfileError, NegativeRate) {
  std::string text = kMinimal;
  text.replace(text.find("max_feed = 500"), 14, "max_feed = -5");
  expect_error(text, "must not be negative", 9);
}

TEST(MachineProfileError, MinAboveMax) {
  std::string text = kMinimal;
  text.replace(text.find("min = -10"), 9, "min = 20");
  expect_error(text, "min is above max", 0);
}

TEST(MachineProfileError, BadUnits) {
  std::string text = kMinimal;
  text.replace(text.find("units = \"mm\""), 12, "units = \"cm\"");
  expect_error(text, "must be \"mm\" or \"inch\"", 4);
}

TEST(MachineProfileError, ZeroRapid) {
  std::string text = kMinimal;
  text.replace(text.find("rapid = 1000"), 12, "rapid = 0");
  expect_error(text, "above zero", 0);
}

}  // namespace
}  // namespace usina::sim
