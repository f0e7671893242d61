// What fuzz_config found in usina-serve.toml's reader: a data pattern of
// 100,000 characters (or parentheses 10,000 deep) overflowed the stack as
// std::regex compiled it; max_upload and web.max_file_bytes took any count up
// to 2^63 (an upload as large as anyone sends, held in memory); a session of
// 1e-300 hours ended before its first request.
#include <string>

#include <gtest/gtest.h>

#include "dnc/server_config.hpp"

namespace usina::dnc {
namespace {

std::string machine_with_pattern(const std::string& pattern) {
  return "[[machine]]\nname = \"m1\"\nport = \"/dev/ttyS0\"\npart_count_pattern = \"" + pattern +
         "\"\n";
}

// The first diagnostic's message; the configuration must be refused.
std::string refusal(const std::string& text) {
  core::DiagnosticList diags;
  EXPECT_FALSE(read_server_config(text, 0, diags)) << text.substr(0, 80);
  if (diags.all().empty()) return "";
  EXPECT_EQ(diags.all()[0].code, core::Code::DncConfig);
  return diags.all()[0].message;
}

TEST(ServerConfigLimits, ADataPatternOfAHundredThousandCharactersIsAnError) {
  const std::string message = refusal(machine_with_pattern(std::string(100000, 'a')));
  EXPECT_NE(message.find("100000 characters long; a pattern may have at most 256"),
            std::string::npos)
      << message;
}

TEST(ServerConfigLimits, ADataPatternNestedTenThousandDeepIsAnError) {
  const std::string deep = std::string(10000, '(') + "a" + std::string(10000, ')');
  EXPECT_NE(refusal(machine_with_pattern(deep)).find("at most 256"), std::string::npos);
}

TEST(ServerConfigLimits, ADataPatternOf256CharactersIsRead) {
  const std::string pattern = "^" + std::string(255, 'a');
  core::DiagnosticList diags;
  const auto c = read_server_config(machine_with_pattern(pattern), 0, diags);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->machines[0].part_count_pattern, pattern);
  EXPECT_NE(pattern_error(std::string(257, 'a')).find("257 characters"), std::string::npos);
}

TEST(ServerConfigLimits, AByteCountPastAGibibyteIsAnError) {
  for (const char* text :
       {"[server]\nmax_upload = 9223372036854775807\n", "[server]\nmax_upload = 1073741825\n",
        "[server]\nmax_upload = 1e300\n", "[web]\nmax_file_bytes = 9223372036854775807\n",
        "[web]\nmax_file_bytes = nan\n"}) {
    EXPECT_NE(refusal(text).find("from 1024 to 1073741824 (1 GiB)"), std::string::npos) << text;
  }
  core::DiagnosticList diags;
  const auto c = read_server_config(
      "[server]\nmax_upload = 1073741824\n[web]\nmax_file_bytes = 1024\n", 0, diags);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->max_upload, 1073741824u);
  EXPECT_EQ(c->web_max_file_bytes, 1024u);
}

TEST(ServerConfigLimits, ASessionShorterThanAMinuteIsAnError) {
  for (const char* hours : {"1e-300", "0.01", "-0.0", "nan", "inf", "721"}) {
    EXPECT_NE(refusal(std::string("[server]\nsession_hours = ") + hours + "\n")
                  .find("from 0.01667 (a minute) to 720 (30 days)"),
              std::string::npos)
        << hours;
  }
  core::DiagnosticList diags;
  const auto c = read_server_config("[server]\nsession_hours = 0.0167\n", 0, diags);
  ASSERT_TRUE(c);
  EXPECT_DOUBLE_EQ(c->session_hours, 0.0167);
}

}  // namespace
}  // namespace usina::dnc
