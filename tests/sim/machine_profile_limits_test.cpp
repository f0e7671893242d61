// Issue 11: a machine profile with max_feed = 0, max_rpm = 0 or
// accel = 1e-300 was accepted and gave garbage times; an unknown key
// (per_hours) was silently ignored. Out-of-range values are errors; an
// unknown key is a warning at its line with the nearest valid name.
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "sim/machine_profile.hpp"
#include "sim/profile_keys.hpp"

namespace usina::sim {
namespace {

const std::string kProfile = R"([machine]
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
[spindle]
max_rpm = 10000
accel_time = 1
[times]
tool_change = 5
block = 0
[cost]
per_hour = 60
)";

std::string with(const std::string& find, const std::string& replacement) {
  std::string text = kProfile;
  const auto at = text.find(find);
  EXPECT_NE(at, std::string::npos) << find;
  if (at != std::string::npos) text.replace(at, find.size(), replacement);
  return text;
}

TEST(MachineProfileLimits, TheExampleProfileIsGood) {
  core::DiagnosticList d;
  EXPECT_TRUE(read_machine_profile(kProfile, 1, d));
  EXPECT_TRUE(d.all().empty());
}

TEST(MachineProfileLimits, AbsurdRatesAndTimesAreErrorsAtTheirLine) {
  struct Case {
    const char* find;
    const char* replacement;
    std::uint32_t line;
  };

  const Case cases[] = {
      {"max_feed = 500", "max_feed = 0", 8},
      {"max_rpm = 10000", "max_rpm = 0", 23},
      {"accel = 100", "accel = 1e-300", 9},
      {"accel = 100", "accel = 1e300", 9},
      {"rapid = 1000", "rapid = 1e-9", 7},
      {"rapid = 1000", "rapid = nan", 7},
      {"rapid = 1000", "rapid = inf", 7},
      {"max = 10", "max = 1e300", 6},
      {"accel = 100\n[axes.y]", "accel = 100\njerk = 1e-300\n[axes.y]", 10},
      {"accel_time = 1", "accel_time = -1", 24},
      {"tool_change = 5", "tool_change = 1e12", 26},
      {"block = 0", "block = -0.1", 27},
      {"per_hour = 60", "per_hour = -60", 29},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.replacement);
    core::DiagnosticList d;
    EXPECT_FALSE(read_machine_profile(with(c.find, c.replacement), 1, d));
    ASSERT_EQ(d.error_count(), 1);
    EXPECT_EQ(d.all().front().code, core::Code::BadMachineProfile);
    EXPECT_EQ(d.all().front().loc.line, c.line);
  }
}

TEST(MachineProfileLimits, TheMessageGivesTheRangeInTheFilesUnits) {
  core::DiagnosticList d;
  EXPECT_FALSE(read_machine_profile(with("accel = 100", "accel = 1e-300"), 1, d));
  EXPECT_EQ(d.all().front().message,
            "[axes.x] accel = 1e-300 is out of range: give from 1 to 1e+06 mm/s²");
  d.clear();
  std::string inch = with("units = \"mm\"", "units = \"inch\"");
  inch.replace(inch.find("max_feed = 500"), 14, "max_feed = 0");
  EXPECT_FALSE(read_machine_profile(inch, 1, d));
  EXPECT_THAT(d.all().front().message, testing::HasSubstr("inch/min"));
}

TEST(MachineProfileLimits, ZeroJerkIsTrapezoidalAndAllowed) {
  core::DiagnosticList d;
  EXPECT_TRUE(
      read_machine_profile(with("accel = 100\n[axes.y]", "accel = 100\njerk = 0\n[axes.y]"), 1, d));
  EXPECT_TRUE(d.all().empty());
}

TEST(MachineProfileLimits, AnUnknownKeyIsAWarningWithTheNearestName) {
  core::DiagnosticList d;
  const auto p = read_machine_profile(with("per_hour = 60", "per_hours = 60"), 4, d);
  ASSERT_TRUE(p);  // a warning: the profile is still read
  ASSERT_EQ(d.all().size(), 1u);
  const core::Diagnostic& w = d.all().front();
  EXPECT_EQ(w.code, core::Code::UnknownProfileKey);
  EXPECT_EQ(w.severity, core::Severity::Warning);
  EXPECT_EQ(w.loc.file, 4u);
  EXPECT_EQ(w.loc.line, 29u);
  EXPECT_EQ(w.loc.col, 1u);
  EXPECT_EQ(w.message, "unknown key `per_hours` in [cost] is not read; did you mean `per_hour`?");
  EXPECT_EQ(p->cost_per_hour, 0.0);  // not read
}

TEST(MachineProfileLimits, UnknownSectionsAndAxisKeysAreWarnedToo) {
  const std::pair<std::string, std::string> cases[] = {
      {"[cost]\n", "[costs]\n"},                          // a section
      {"accel_time = 1", "acel_time = 1"},                // in [spindle]
      {"max_feed = 500", "max_feed = 500\nmaxfeed = 1"},  // in [axes.x]
      {"[axes.z]", "[axes.w]\nmin = 0\n[axes.z]"},        // an axis
  };
  const char* suggestions[] = {"`cost`", "`accel_time`", "`max_feed`", "the keys here are x"};
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    SCOPED_TRACE(cases[i].second);
    core::DiagnosticList d;
    EXPECT_TRUE(read_machine_profile(with(cases[i].first, cases[i].second), 1, d));
    ASSERT_EQ(d.all().size(), 1u);
    EXPECT_EQ(d.all().front().code, core::Code::UnknownProfileKey);
    EXPECT_THAT(d.all().front().message, testing::HasSubstr(suggestions[i]));
  }
}

TEST(ProfileKeys, EditDistanceCountsASwapOfNeighboursAsOne) {
  EXPECT_EQ(edit_distance("per_hours", "per_hour"), 1u);
  EXPECT_EQ(edit_distance("per_huor", "per_hour"), 1u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(nearest_key("per_hours", profile_keys("cost")), "per_hour");
  EXPECT_EQ(nearest_key("colour", profile_keys("cost")), "");
  EXPECT_EQ(nearest_key("maxfeed", profile_keys("axes.x")), "max_feed");
}

}  // namespace
}  // namespace usina::sim
