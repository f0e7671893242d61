// usina-serve.toml as the server reads it: the example is valid; the
// [server] table's values are checked like the machines'.
#include "dnc/server_config.hpp"

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "dnc/server.hpp"

namespace usina::dnc {
namespace {

TEST(ServerConfig, TheExampleIsValid) {
  std::ifstream in(std::string(USINA_TEST_DIR) + "/../examples/usina-serve.toml");
  ASSERT_TRUE(in);
  std::ostringstream text;
  text << in.rdbuf();
  core::DiagnosticList diags;
  const auto c = read_server_config(text.str(), 0, diags);
  ASSERT_TRUE(c);
  EXPECT_TRUE(diags.all().empty());
  ASSERT_EQ(c->machines.size(), 2U);
  EXPECT_EQ(c->machines[0].link.name, "romi-1");
  EXPECT_EQ(c->machines[0].machine_class, "lathe");
  EXPECT_EQ(c->machines[1].link.mode, MachineMode::Tryout);
  EXPECT_EQ(c->listen, "127.0.0.1:8080");
  EXPECT_TRUE(parse_listen(c->listen));
  ServerConfig loaded = *c;
  ASSERT_TRUE(load_profiles(loaded, std::string(USINA_TEST_DIR) + "/../examples", diags));
  ASSERT_EQ(loaded.profiles.count("mill"), 1U);
  EXPECT_EQ(loaded.profiles.at("mill").name, "small VMC");
}

TEST(ServerConfig, AProfileThatCannotBeReadIsAnError) {
  core::DiagnosticList diags;
  auto c = read_server_config(
      "[[machine]]\nname = \"m\"\nport = \"/dev/null\"\nmachine_class = \"mill\"\n"
      "profile = \"no-such.toml\"\n",
      0, diags);
  ASSERT_TRUE(c);
  EXPECT_FALSE(load_profiles(*c, "/nonexistent", diags));
  ASSERT_TRUE(diags.has_errors());
  EXPECT_NE(diags.all().back().message.find("no-such.toml"), std::string::npos);
}

TEST(ServerConfig, AWrongServerValueIsAnErrorAtItsLine) {
  core::DiagnosticList diags;
  EXPECT_FALSE(read_server_config("[server]\nlisten = 8080\nmax_upload = 10\n", 0, diags));
  ASSERT_EQ(diags.error_count(), 2);
  EXPECT_EQ(diags.all()[0].code, core::Code::DncConfig);
  EXPECT_EQ(diags.all()[0].loc.line, 2U);
  EXPECT_EQ(diags.all()[1].loc.line, 3U);
}

TEST(ServerConfig, ListenAddressesAreHostAndPort) {
  EXPECT_TRUE(parse_listen("127.0.0.1:0"));
  EXPECT_TRUE(parse_listen("[::1]:8080"));
  EXPECT_FALSE(parse_listen("localhost"));
  EXPECT_FALSE(parse_listen("127.0.0.1:99999"));
  EXPECT_FALSE(parse_listen("127.0.0.1:80x"));
  EXPECT_FALSE(parse_listen("host.example:80"));  // an address, not a name to resolve
}

}  // namespace
}  // namespace usina::dnc
