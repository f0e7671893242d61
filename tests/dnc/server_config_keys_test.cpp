// usina-serve.toml's tables besides [[machine]] (found with fuzz_config): a
// misspelt key (`max_uplaod`) or table (`[sever]`) was ignored without a
// word, and `server = 5` read as no [server]. Each unknown name is now
// W_UNKNOWN_DNC_KEY at its line with the nearest valid one; a known table
// that is no table is E_DNC_CONFIG.
#include <string>

#include <gtest/gtest.h>

#include "dnc/server_config.hpp"

namespace usina::dnc {
namespace {

TEST(ServerConfigKeys, AMisspeltKeyOfServerIsAWarningWithTheNearestName) {
  core::DiagnosticList diags;
  const auto c = read_server_config("[server]\nmax_uplaod = 1024\n", 0, diags);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->max_upload, 64ull << 20);
  ASSERT_EQ(diags.all().size(), 1u);
  const core::Diagnostic& d = diags.all()[0];
  EXPECT_EQ(d.code, core::Code::UnknownDncKey);
  EXPECT_EQ(d.severity, core::Severity::Warning);
  EXPECT_EQ(d.loc.line, 2u);
  EXPECT_NE(d.message.find("unknown key `max_uplaod` in [server] is not read; did you mean "
                           "`max_upload`?"),
            std::string::npos)
      << d.message;
}

TEST(ServerConfigKeys, EveryTablesUnknownKeysAndTablesAreWarnings) {
  core::DiagnosticList diags;
  const auto c = read_server_config(
      "[sever]\nlisten = \"0.0.0.0:80\"\n[web]\nroots = \"page\"\n[mtconnect]\nheartbeat = 1\n"
      "[mqtt]\nclientid = \"x\"\n",
      0, diags);
  ASSERT_TRUE(c);
  ASSERT_EQ(diags.all().size(), 4u);
  const char* expected[] = {
      "`sever` at the top of the configuration is not read; did you mean "
      "`server`?",
      "`roots` in [web] is not read; did you mean `root`?", "`heartbeat` in [mtconnect]",
      "`clientid` in [mqtt]"};
  std::string all;  // toml++ gives a table's keys in its own order
  for (const core::Diagnostic& d : diags.all()) {
    EXPECT_EQ(d.code, core::Code::UnknownDncKey);
    all += d.message + "\n";
  }
  for (const char* e : expected)
    EXPECT_NE(all.find(e), std::string::npos) << e << "\n" << all;
}

TEST(ServerConfigKeys, AKnownTableThatIsNoTableIsAnError) {
  for (const char* text : {"server = 5\n", "web = \"page\"\n", "mqtt = [1]\n", "mtconnect = 1\n"}) {
    core::DiagnosticList diags;
    EXPECT_FALSE(read_server_config(text, 0, diags)) << text;
    ASSERT_FALSE(diags.all().empty()) << text;
    EXPECT_EQ(diags.all()[0].code, core::Code::DncConfig) << text;
    EXPECT_NE(diags.all()[0].message.find("must be a table"), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace usina::dnc
