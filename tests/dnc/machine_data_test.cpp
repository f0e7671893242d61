// Machine data the control punches while idle (DPRNT lines, (MSG comments):
// part counts and cycle times in GET /api/machines/{machine}, on the
// MTConnect adapter; the machine's own patterns; bad patterns refused.
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "core/diagnostic.hpp"
#include "line_client.hpp"

namespace usina::dnc {
namespace {

// A server with `mill-1` on a pty (its punches end after 0.2 s of silence)
// and the MTConnect adapter.
Control start_mill(RunningServer& s, const ServerMachine* with = nullptr) {
  ServerConfig config;
  config.mtconnect.enabled = true;
  config.mtconnect.listen = "127.0.0.1:0";
  return start_punching_mill(s, with != nullptr ? *with : ServerMachine{}, config);
}

bool idle(const nlohmann::json& m) {
  return m.value("state", "") == "idle";
}

TEST(MachineData, DprntPartAndCycleLinesCountAPartWithTheControlsCycleTime) {
  RunningServer s;
  Control control = start_mill(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", test::kPassword);
  ASSERT_TRUE(idle(machine_when(c, oper, idle)));
  test::LineClient agent(*s.server().mtconnect_endpoint());
  punch(s, control, "CYCLE TIME 83.5\r\nPART COUNT 41\r\n");
  const auto m =
      machine_when(c, oper, [](const nlohmann::json& j) { return j.value("part_count", 0) == 1; });
  EXPECT_EQ(m["part_count"], 1);
  EXPECT_EQ(m["control_part_count"], 41);
  EXPECT_DOUBLE_EQ(m["last_cycle_seconds"].get<double>(), 83.5);
  EXPECT_TRUE(agent.wait_for_text("|mill-1:part_count|1"));
  // Not a program: nothing was stored.
  EXPECT_EQ(c.get("/api/programs", oper).json()["programs"].size(), 0u);
}

TEST(MachineData, AMsgCommentIsTheMachinesMessage) {
  RunningServer s;
  Control control = start_mill(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", test::kPassword);
  ASSERT_TRUE(idle(machine_when(c, oper, idle)));
  test::LineClient agent(*s.server().mtconnect_endpoint());
  punch(s, control, "(MSG, TOOL 5 WORN | CHANGE)\n");
  const auto m = machine_when(
      c, oper, [](const nlohmann::json& j) { return !j.value("last_message", "").empty(); });
  EXPECT_EQ(m["last_message"], "TOOL 5 WORN | CHANGE");
  EXPECT_EQ(m["part_count"], 0);
  // The pipe is escaped, the value quoted (SHDR).
  EXPECT_TRUE(agent.wait_for_text(R"(|mill-1:message||"TOOL 5 WORN \| CHANGE")"));
}

TEST(MachineData, TheMachinesOwnPatternCountsPartsTimedBetweenTwoLines) {
  RunningServer s;
  ServerMachine with;
  with.part_count_pattern = "^END OF PART";
  with.cycle_time_pattern = "";
  Control control = start_mill(s, &with);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", test::kPassword);
  ASSERT_TRUE(idle(machine_when(c, oper, idle)));
  punch(s, control, "PART COUNT 3\nend of part\n");  // the default pattern is replaced
  auto m =
      machine_when(c, oper, [](const nlohmann::json& j) { return j.value("part_count", 0) == 1; });
  EXPECT_EQ(m["part_count"], 1);
  EXPECT_TRUE(m["control_part_count"].is_null());
  EXPECT_TRUE(m["last_cycle_seconds"].is_null());  // one line: no cycle yet
  ASSERT_TRUE(idle(machine_when(c, oper, idle)));
  punch(s, control, "END OF PART\n");
  m = machine_when(c, oper, [](const nlohmann::json& j) { return j.value("part_count", 0) == 2; });
  EXPECT_EQ(m["part_count"], 2);
  ASSERT_TRUE(m["last_cycle_seconds"].is_number()) << m.dump();
  EXPECT_GT(m["last_cycle_seconds"].get<double>(), 0.0);
}

TEST(MachineData, APunchWithoutANameOrMachineDataIsStillRefused) {
  RunningServer s;
  Control control = start_mill(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", test::kPassword);
  ASSERT_TRUE(idle(machine_when(c, oper, idle)));
  punch(s, control, "%\nG0 X1\nM30\n%");
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const auto m = machine_when(c, oper, idle);
  EXPECT_EQ(m["part_count"], 0);
  EXPECT_EQ(m["last_message"], "");
}

TEST(MachineData, ConfigReadsTheDataTablesAndRefusesABadPattern) {
  core::DiagnosticList diags;
  const auto good = read_server_config(R"toml(
[mtconnect]
listen = "127.0.0.1:7979"
heartbeat_ms = 5000
[mqtt]
url = "mqtt://10.0.0.5:1884"
prefix = "plant7"
[[machine]]
name = "m1"
port = "/dev/ttyS0"
part_count_pattern = "PIECE (\\d+)"
)toml",
                                       0, diags);
  ASSERT_TRUE(good);
  EXPECT_TRUE(good->mtconnect.enabled);
  EXPECT_EQ(good->mtconnect.listen, "127.0.0.1:7979");
  EXPECT_EQ(good->mtconnect.heartbeat_ms, 5000u);
  EXPECT_TRUE(good->mqtt.enabled);
  EXPECT_EQ(good->mqtt.host, "10.0.0.5");
  EXPECT_EQ(good->mqtt.port, 1884);
  EXPECT_EQ(good->mqtt.prefix, "plant7");
  EXPECT_EQ(good->machines[0].part_count_pattern, "PIECE (\\d+)");
  EXPECT_TRUE(diags.all().empty());

  const auto off =
      read_server_config("[[machine]]\nname = \"m1\"\nport = \"/dev/ttyS0\"\n", 0, diags);
  ASSERT_TRUE(off);
  EXPECT_FALSE(off->mtconnect.enabled);
  EXPECT_FALSE(off->mqtt.enabled);

  for (const char* bad : {"[[machine]]\nname = \"m1\"\nport = \"x\"\npart_count_pattern = \"(\"\n",
                          "[mqtt]\nurl = \"http://x\"\n", "[mqtt]\nprefix = \"a/#\"\n",
                          "[mtconnect]\nheartbeat_ms = 5\n"}) {
    core::DiagnosticList d;
    EXPECT_FALSE(read_server_config(bad, 0, d)) << bad;
    ASSERT_FALSE(d.all().empty()) << bad;
    EXPECT_EQ(d.all()[0].code, core::Code::DncConfig) << bad;
  }
}

TEST(MachineData, ConfigReadsTheMqttTlsAndLoginKeys) {
  core::DiagnosticList diags;
  const auto good = read_server_config(R"toml(
[mqtt]
url = "mqtts://broker.plant"
ca_file = "/etc/usina/ca.pem"
cert_file = "/etc/usina/client.pem"
key_file = "/etc/usina/client.key"
username = "usina"
password_file = "/etc/usina/mqtt.pass"
)toml",
                                       0, diags);
  ASSERT_TRUE(good);
  EXPECT_TRUE(diags.all().empty());
  EXPECT_TRUE(good->mqtt.tls);
  EXPECT_EQ(good->mqtt.host, "broker.plant");
  EXPECT_EQ(good->mqtt.port, 8883);
  EXPECT_EQ(good->mqtt.ca_file, "/etc/usina/ca.pem");
  EXPECT_EQ(good->mqtt.cert_file, "/etc/usina/client.pem");
  EXPECT_EQ(good->mqtt.key_file, "/etc/usina/client.key");
  EXPECT_EQ(good->mqtt.username, "usina");
  EXPECT_EQ(good->mqtt.password_file, "/etc/usina/mqtt.pass");
  const auto plain = read_server_config("[mqtt]\nurl = \"mqtt://b\"\nusername = \"u\"\n", 0, diags);
  ASSERT_TRUE(plain);
  EXPECT_FALSE(plain->mqtt.tls);
  EXPECT_EQ(plain->mqtt.port, 1883);

  // Each bad table and a word its message must hold.
  const std::pair<const char*, const char*> bad[] = {
      {"[mqtt]\nurl = \"mqtts://b\"\n", "needs mqtt.ca_file"},
      {"[mqtt]\nurl = \"mqtts://b\"\nca_file = \"c\"\ncert_file = \"x\"\n", "go together"},
      {"[mqtt]\nurl = \"mqtts://b\"\nca_file = \"c\"\nkey_file = \"x\"\n", "go together"},
      {"[mqtt]\nurl = \"mqtt://b\"\nca_file = \"c\"\n", "mqtt.ca_file is for TLS"},
      {"[mqtt]\nurl = \"mqtt://b\"\ncert_file = \"c\"\nkey_file = \"k\"\n", "is for TLS"},
      {"[mqtt]\nurl = \"mqtts://b\"\nca_file = \"\"\n", "mqtt.ca_file must be a file's path"},
      {"[mqtt]\nurl = \"mqtts://b\"\nca_file = 5\n", "mqtt.ca_file must be a string"},
      {"[mqtt]\nusername = \"u\"\npassword = \"p\"\n", "mqtt.password_file"},
      {"[mqtt]\npassword_file = \"p\"\n", "needs mqtt.username"},
      {"[mqtt]\nusername = \"\"\n", "mqtt.username must not be empty"},
      {"[mqtt]\nusername = 7\n", "mqtt.username must be a string"},
      {"[mqtt]\nusername = \"u\"\npassword_file = \"\"\n", "mqtt.password_file must be"},
      {"[mqtt]\nurl = \"mqtts://b:0\"\nca_file = \"c\"\n", "is not mqtt://"},
  };
  for (const auto& [text, says] : bad) {
    core::DiagnosticList d;
    EXPECT_FALSE(read_server_config(text, 0, d)) << text;
    ASSERT_FALSE(d.all().empty()) << text;
    EXPECT_EQ(d.all()[0].code, core::Code::DncConfig) << text;
    EXPECT_NE(d.all()[0].message.find(says), std::string::npos) << d.all()[0].message;
  }
}

}  // namespace
}  // namespace usina::dnc
