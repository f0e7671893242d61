// The MTConnect SHDR adapter, read by a TCP client as cppagent reads it:
// every line `timestamp|key|value...`; the whole state on connect; a PONG
// for each PING; a drip feed's execution, program, line and part count;
// every item UNAVAILABLE when the machine's link is lost.
#include <regex>

#include <gtest/gtest.h>

#include "api_control.hpp"
#include "line_client.hpp"

namespace usina::dnc {
namespace {

using test::LineClient;

const std::string kProgram = "G21 G90\nN10 G0 X1 Y1\nN20 G1 X5 F300\nN30 M2\n";

struct Shop {
  Control control;
  boost::asio::ip::tcp::endpoint shdr;
};

// A simulated control on a pty; `port` is the machine's end of it.
Control simulated_control(RunningServer& s, std::string& port) {
  auto pair = open_pty_pair(s.io());
  EXPECT_TRUE(pair) << pair.error();
  Control control;
  control.link = std::move(pair->master);
  SimCncConfig sc;
  sc.keep_data = true;
  control.sim = std::make_shared<SimCnc>(s.io(), *control.link, sc);
  control.sim->start();
  port = pair->slave_path;
  return control;
}

// A server with `mill-1` on a pty (its control simulated), `lathe-2` on a
// port that never opens, and the adapter on a free port.
Shop start_shop(RunningServer& s) {
  Shop shop;
  std::string port;
  shop.control = simulated_control(s, port);
  ServerConfig config;
  config.machines.push_back(pty_machine("mill-1", port, 115200));
  config.machines.push_back(pty_machine("lathe-2", "/nonexistent/usina-tty", 9600));
  config.mtconnect.enabled = true;
  config.mtconnect.listen = "127.0.0.1:0";
  s.start(config);
  shop.shdr = *s.server().mtconnect_endpoint();
  return shop;
}

// timestamp|key|value(|key|value)* — a message is key|native code|text.
bool well_formed(const std::string& line) {
  static const std::regex shdr(
      R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z(\|[A-Za-z0-9_.-]+:[a-z_]+\|[^|]*)+)");
  static const std::regex message(
      R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\d\.\d{3}Z\|[A-Za-z0-9_.-]+:message\|[^|]*\|.*)");
  return std::regex_match(line, message) || std::regex_match(line, shdr);
}

TEST(Mtconnect, AClientGetsEveryItemOfEveryMachineOnConnect) {
  RunningServer s;
  const Shop shop = start_shop(s);
  LineClient agent(shop.shdr);
  ASSERT_TRUE(agent.wait_for_text("|mill-1:avail|"));
  const std::string first = agent.lines().front();
  EXPECT_TRUE(well_formed(first)) << first;
  for (const char* key : {"avail", "execution", "program", "part_count", "line"}) {
    EXPECT_NE(first.find(std::string("|mill-1:") + key + "|"), std::string::npos) << first;
    EXPECT_NE(first.find(std::string("|lathe-2:") + key + "|"), std::string::npos) << first;
  }
  // The lathe's port never opens: all of it is unavailable.
  EXPECT_NE(first.find("|lathe-2:avail|UNAVAILABLE"), std::string::npos) << first;
  EXPECT_NE(first.find("|lathe-2:execution|UNAVAILABLE"), std::string::npos) << first;
  ASSERT_TRUE(agent.wait_for_text("|lathe-2:message||UNAVAILABLE"));
  ASSERT_TRUE(agent.wait_for_text("|mill-1:message||UNAVAILABLE"));
  // Once its port is open, a second agent sees the mill available and ready at once.
  ASSERT_TRUE(agent.wait_for_text("|mill-1:avail|AVAILABLE"));
  LineClient second(shop.shdr);
  ASSERT_TRUE(second.wait_for_text("|mill-1:"));
  EXPECT_NE(second.lines().front().find("|mill-1:avail|AVAILABLE|mill-1:execution|READY"),
            std::string::npos)
      << second.lines().front();
  for (const std::string& line : agent.lines())
    EXPECT_TRUE(well_formed(line)) << line;
}

TEST(Mtconnect, APingIsAnsweredWithAPongAndTheHeartbeat) {
  RunningServer s;
  const Shop shop = start_shop(s);
  LineClient agent(shop.shdr);
  agent.send("* PING\n");
  ASSERT_TRUE(agent.wait_for([](const std::string& l) { return l == "* PONG 10000"; }));
  agent.send("* PING\r\n");  // CR LF as well: a second PONG
  int pongs = 0;
  ASSERT_TRUE(
      agent.wait_for([&](const std::string& l) { return l == "* PONG 10000" && ++pongs == 2; }));
}

TEST(Mtconnect, ADripFeedIsActiveThenReadyWithItsProgramLineAndPartCount) {
  RunningServer s;
  const Shop shop = start_shop(s);
  LineClient agent(shop.shdr);
  ASSERT_TRUE(agent.wait_for_text("|mill-1:avail|AVAILABLE"));
  const ApiClient c = s.client();
  const std::string rev = released(c, "O710", kProgram);
  const std::string oper = c.log_in("oper", test::kPassword);
  const auto r = c.post("/api/machines/mill-1/jobs",
                        {{"program", "O710"}, {"revision", rev}, {"mode", "drip"}}, oper);
  ASSERT_EQ(r.status, 201) << r.body;
  ASSERT_EQ(wait_for_end(c, oper, r.json()["job"])["state"], "done");
  ASSERT_TRUE(agent.wait_for_text("|mill-1:execution|ACTIVE"));
  ASSERT_TRUE(agent.wait_for_text("|mill-1:program|O710"));
  ASSERT_TRUE(agent.wait_for_text("|mill-1:part_count|1"));
  ASSERT_TRUE(agent.wait_for_text("|mill-1:execution|READY"));
  // The line the feed last sent: the program's 4 lines and its % lines.
  bool line_seen = false;
  for (const std::string& l : agent.lines()) {
    EXPECT_TRUE(well_formed(l)) << l;
    line_seen = line_seen || std::regex_search(l, std::regex(R"(\|mill-1:line\|[0-9]+)"));
  }
  EXPECT_TRUE(line_seen);
}

TEST(Mtconnect, ALostLinkMakesEveryItemOfTheMachineUnavailable) {
  RunningServer s;
  Shop shop = start_shop(s);
  LineClient agent(shop.shdr);
  ASSERT_TRUE(agent.wait_for_text("|mill-1:avail|AVAILABLE"));
  s.on_loop([&] {
    shop.control.sim->stop();
    shop.control.link->close();
    return 0;
  });
  ASSERT_TRUE(agent.wait_for_text("|mill-1:avail|UNAVAILABLE"));
  const std::string lost = agent.last_match();
  for (const char* key : {"execution", "part_count"})  // the others were unavailable already
    EXPECT_NE(lost.find(std::string("|mill-1:") + key + "|UNAVAILABLE"), std::string::npos) << lost;
  // An agent connecting now gets every item of the mill unavailable.
  LineClient late(shop.shdr);
  ASSERT_TRUE(late.wait_for_text("|mill-1:"));
  const std::string now = late.lines().front();
  for (const char* key : {"avail", "execution", "program", "part_count", "line"})
    EXPECT_NE(now.find(std::string("|mill-1:") + key + "|UNAVAILABLE"), std::string::npos) << now;
  EXPECT_TRUE(late.wait_for_text("|mill-1:message||UNAVAILABLE"));
}

// An admin adds a machine while an agent is connected: its items come at
// once, unavailable until its port opens, then available; retired, they are
// all unavailable and an agent connecting after does not get it.
TEST(Mtconnect, AMachineAddedOrRetiredOverTheApiIsInOrOutAtOnce) {
  RunningServer s;
  Shop shop = start_shop(s);
  std::string port;
  Control mill3 = simulated_control(s, port);
  LineClient agent(shop.shdr);
  ASSERT_TRUE(agent.wait_for_text("|mill-1:avail|AVAILABLE"));
  EXPECT_EQ(agent.lines().front().find("|mill-3:"), std::string::npos);
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  const nlohmann::json m = {{"name", "mill-3"}, {"port", port},   {"baud", 115200},
                            {"code", "ascii"},  {"data_bits", 8}, {"parity", "none"}};
  ASSERT_EQ(c.post("/api/machines", m, boss).status, 201);
  ASSERT_TRUE(agent.wait_for_text("|mill-3:avail|UNAVAILABLE"));
  EXPECT_NE(agent.last_match().find("|mill-3:part_count|UNAVAILABLE"), std::string::npos);
  ASSERT_TRUE(agent.wait_for_text("|mill-3:avail|AVAILABLE"));
  EXPECT_NE(agent.last_match().find("|mill-3:part_count|0"), std::string::npos)
      << agent.last_match();
  LineClient second(shop.shdr);
  ASSERT_TRUE(second.wait_for_text("|mill-3:avail|AVAILABLE"));

  ASSERT_EQ(c.post("/api/machines/mill-3/retire", {{"reason", "sold"}}, boss).status, 200);
  ASSERT_TRUE(agent.wait_for_text("|mill-3:avail|UNAVAILABLE|mill-3:execution|UNAVAILABLE"));
  EXPECT_NE(agent.last_match().find("|mill-3:part_count|UNAVAILABLE"), std::string::npos);
  LineClient late(shop.shdr);
  ASSERT_TRUE(late.wait_for_text("|mill-1:"));
  EXPECT_EQ(late.lines().front().find("|mill-3:"), std::string::npos) << late.lines().front();
}

}  // namespace
}  // namespace usina::dnc
