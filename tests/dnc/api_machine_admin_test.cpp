// Machines added, changed and retired by an admin over HTTP: checked as the
// configuration file's are, at work at once (a job reaches the control of a
// machine just added), audited, refused while a job is under way, kept
// across a restart; the file's machines are read-only.
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/machine_settings.hpp"

namespace usina::dnc {
namespace {

const std::string kProgram = "G21 G90\nN10 G0 X1 Y1\nN20 G1 X5 F300\nN30 M2\n";

// A control on a pty whose slave is the port of the machine the test adds.
struct PtyControl {
  Control control;
  std::string port;
};

PtyControl pty_control(RunningServer& s) {
  auto pair = open_pty_pair(s.io());
  EXPECT_TRUE(pair) << pair.error();
  PtyControl p;
  p.control.link = std::move(pair->master);
  SimCncConfig sc;
  sc.keep_data = true;
  p.control.sim = std::make_shared<SimCnc>(s.io(), *p.control.link, sc);
  p.control.sim->start();
  p.port = pair->slave_path;
  return p;
}

nlohmann::json ascii_machine(const std::string& name, const std::string& port) {
  return {{"name", name},   {"port", port},     {"baud", 115200}, {"code", "ascii"},
          {"data_bits", 8}, {"parity", "none"}, {"leader", 0},    {"trailer", 0}};
}

// `m` with the keys of `patch` set.
nlohmann::json with(nlohmann::json m, const nlohmann::json& patch) {
  m.update(patch);
  return m;
}

nlohmann::json machine_once(const ApiClient& c, const std::string& token, const std::string& name,
                            const std::string& state) {
  nlohmann::json m;
  for (int i = 0; i < 600; ++i) {
    m = c.get("/api/machines/" + name, token).json();
    if (m.value("state", "") == state) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return m;
}

// The audit entries about `subject`, as "action:reason".
std::vector<std::string> audited(const ApiClient& c, const std::string& subject) {
  const auto log = c.get("/api/audit?verify=1", c.log_in("boss", test::kPassword)).json();
  EXPECT_EQ(log["ok"], true) << log.dump();
  std::vector<std::string> out;
  for (const auto& e : log["entries"]) {
    if (e["subject"] == subject)
      out.push_back(e["action"].get<std::string>() + ":" + e["reason"].get<std::string>());
  }
  return out;
}

TEST(ApiMachineAdmin, AMachineAddedTakesAJobAtOnce) {
  RunningServer s;
  PtyControl pty = pty_control(s);
  s.start();
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  nlohmann::json body = ascii_machine("mill-2", pty.port);
  body["reason"] = "the new mill";
  const test::Reply added = c.post("/api/machines", body, boss);
  ASSERT_EQ(added.status, 201) << added.body;
  EXPECT_EQ(added.json()["source"], "api");
  EXPECT_EQ(added.json()["settings"]["baud"], 115200);
  EXPECT_EQ(added.json()["settings"]["stop_bits"], 2);  // the file's default
  EXPECT_EQ(machine_once(c, boss, "mill-2", "idle")["state"], "idle");
  const std::string rev = released(c, "O800", kProgram);
  const test::Reply job = c.post("/api/machines/mill-2/jobs",
                                 {{"program", "O800"}, {"revision", rev}, {"mode", "send"}},
                                 c.log_in("oper", test::kPassword));
  ASSERT_EQ(job.status, 201) << job.body;
  EXPECT_EQ(wait_for_end(c, boss, job.json()["job"])["state"], "done");
  EXPECT_NE(received_once(s, pty.control, "N30 M2").find("N30 M2"), std::string::npos);
  EXPECT_EQ(audited(c, "mill-2"), std::vector<std::string>{"machine.add:the new mill"});
}

TEST(ApiMachineAdmin, BadSettingsAre400WithTheConfigurationsMessage) {
  RunningServer s;
  Control control = start_with_control(s);  // mill-1, the file's
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  const auto refused = [&](nlohmann::json body, int status, const std::string& says) {
    const test::Reply r = c.post("/api/machines", body, boss);
    EXPECT_EQ(r.status, status) << body.dump() << " " << r.body;
    EXPECT_NE(r.json().value("error", "").find(says), std::string::npos) << r.body;
  };
  nlohmann::json m = ascii_machine("mill-3", "tcp://127.0.0.1:9");
  refused(with(m, {{"baud", 1000}}), 400, "no UART rate");
  refused(with(m, {{"bauds", 9600}}), 400, "did you mean `baud`");
  refused(with(m, {{"profile", "/etc/passwd"}}), 400, "usina-serve.toml");
  refused(with(m, {{"parity", 1}}), 400, "parity must be a string");
  refused(with(m, {{"leader", nlohmann::json::array()}}), 400, "leader must be");
  refused(with(m, {{"part_count_pattern", "(("}}), 400, "not a regular");
  refused(with(m, {{"code", "eia"}, {"data_bits", 7}}), 400, "needs data_bits = 8");
  refused(with(m, {{"name", "a b"}}), 400, "a machine's name");
  refused({{"port", "tcp://127.0.0.1:9"}}, 400, "name is missing");
  // Only serial lines and ptys: opening another device does something of its own.
  refused(with(m, {{"port", "/dev/watchdog"}}), 400, "on a serial device");
  refused(with(m, {{"port", "/dev/pts/../sda"}}), 400, "on a serial device");
  refused(with(m, {{"port", "/tmp/cnc"}}), 400, "name any other in usina-serve.toml");
  refused(ascii_machine("mill-1", "tcp://127.0.0.1:9"), 409, "there is a machine mill-1");
  const std::string mill1_port = c.get("/api/machines/mill-1", boss).json()["port"];
  refused(ascii_machine("mill-3", mill1_port), 409, "is machine mill-1's");
  EXPECT_EQ(c.call(test::bhttp::verb::post, "/api/machines", "[1]", boss).status, 400);
  EXPECT_EQ(c.get("/api/machines/mill-3", boss).status, 404);  // nothing was added
  EXPECT_TRUE(audited(c, "mill-3").empty());
  EXPECT_EQ(c.post("/api/machines", m, c.log_in("prog", test::kPassword)).status, 403);
}

TEST(ApiMachineAdmin, AChangeIsCheckedAuditedAndOpensThePortAgain) {
  RunningServer s;
  PtyControl pty = pty_control(s);
  Control file_machine = start_with_control(s);
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  ASSERT_EQ(c.post("/api/machines", ascii_machine("mill-2", pty.port), boss).status, 201);
  const test::Reply r =
      c.post("/api/machines/mill-2", {{"mode", "tryout"}, {"reason", "proving out"}}, boss);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json()["mode"], "tryout");
  EXPECT_EQ(machine_once(c, boss, "mill-2", "idle")["state"], "idle");
  // null: the key's default again.
  EXPECT_EQ(c.post("/api/machines/mill-2", {{"mode", nullptr}}, boss).json()["mode"], "production");
  // The same values again change nothing and write nothing.
  EXPECT_EQ(c.post("/api/machines/mill-2", {{"mode", "production"}}, boss).status, 200);
  EXPECT_EQ(
      audited(c, "mill-2"),
      (std::vector<std::string>{"machine.add:", "machine.change:proving out", "machine.change:"}));
  const auto refused = [&](const std::string& name, nlohmann::json body, int status,
                           const std::string& says) {
    const test::Reply x = c.post("/api/machines/" + name, body, boss);
    EXPECT_EQ(x.status, status) << body.dump() << " " << x.body;
    EXPECT_NE(x.json().value("error", "").find(says), std::string::npos) << x.body;
  };
  refused("mill-2", {{"baud", 7}}, 400, "baud must be");
  refused("mill-2", {{"name", "mill-9"}}, 400, "does not change");
  refused("mill-2", nlohmann::json::object(), 400, "nothing to change");
  refused("mill-2", {{"port", c.get("/api/machines/mill-1", boss).json()["port"]}}, 409,
          "is machine mill-1's");
  refused("mill-1", {{"baud", 4800}}, 409, "usina-serve.toml");
  refused("mill-7", {{"baud", 4800}}, 404, "no machine mill-7");
  EXPECT_EQ(c.get("/api/machines/mill-2", boss).json()["settings"]["baud"], 115200);
}

TEST(ApiMachineAdmin, AMachineUnderAJobIsNeitherChangedNorRetired) {
  RunningServer s;
  PtyControl pty = pty_control(s);
  s.start();
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  nlohmann::json slow = ascii_machine("mill-2", pty.port);
  slow["baud"] = 1200;
  ASSERT_EQ(c.post("/api/machines", slow, boss).status, 201);
  machine_once(c, boss, "mill-2", "idle");
  std::string text = "G21 G90\n";
  for (int i = 0; i < 400; ++i)
    text += "G1 X" + std::to_string(i) + " F300\n";
  const std::string rev = released(c, "O810", text + "M2\n");
  const test::Reply job = c.post("/api/machines/mill-2/jobs",
                                 {{"program", "O810"}, {"revision", rev}, {"mode", "drip"}}, boss);
  ASSERT_EQ(job.status, 201) << job.body;
  const test::Reply change = c.post("/api/machines/mill-2", {{"baud", 9600}}, boss);
  EXPECT_EQ(change.status, 409) << change.body;
  EXPECT_NE(change.body.find("mill-2 "), std::string::npos) << change.body;  // what it is doing
  EXPECT_EQ(c.post("/api/machines/mill-2/retire", {{"reason", "x"}}, boss).status, 409);
  c.post("/api/jobs/" + std::to_string(job.json()["job"].get<std::int64_t>()) + "/stop",
         nlohmann::json::object(), boss);
  EXPECT_EQ(wait_for_end(c, boss, job.json()["job"])["state"], "interrupted");
  EXPECT_EQ(c.get("/api/machines/mill-2", boss).json()["settings"]["baud"], 1200);
}

TEST(ApiMachineAdmin, AMachineReceivingAPunchIsNeitherChangedNorRetired) {
  RunningServer s;
  PtyControl pty = pty_control(s);
  s.start();
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  ASSERT_EQ(
      c.post("/api/machines", with(ascii_machine("mill-2", pty.port), {{"receive_idle", 30}}), boss)
          .status,
      201);
  machine_once(c, boss, "mill-2", "idle");
  punch(s, pty.control, "%\nO1234\nG0 X1\n");  // no end: the punch goes on
  EXPECT_EQ(machine_once(c, boss, "mill-2", "receiving")["state"], "receiving");
  const test::Reply change = c.post("/api/machines/mill-2", {{"baud", 9600}}, boss);
  EXPECT_EQ(change.status, 409) << change.body;
  EXPECT_NE(change.body.find("mill-2 is receiving; wait until it is idle"), std::string::npos)
      << change.body;
  EXPECT_EQ(c.post("/api/machines/mill-2/retire", {{"reason", "x"}}, boss).status, 409);
  punch(s, pty.control, "M2\n%\n");
  EXPECT_EQ(machine_once(c, boss, "mill-2", "idle")["state"], "idle");
  EXPECT_EQ(c.post("/api/machines/mill-2", {{"baud", 9600}}, boss).status, 200);
}

TEST(ApiMachineAdmin, ARetiredMachineLeavesTheListAndKeepsItsName) {
  RunningServer s;
  PtyControl pty = pty_control(s);
  Control file_machine = start_with_control(s);
  const ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  ASSERT_EQ(c.post("/api/machines", ascii_machine("mill-2", pty.port), boss).status, 201);
  EXPECT_EQ(c.post("/api/machines/mill-2/retire", nlohmann::json::object(), boss).status, 400);
  EXPECT_EQ(c.post("/api/machines/mill-2/retire", {{"reason", ""}}, boss).status, 400);
  EXPECT_EQ(c.post("/api/machines/mill-1/retire", {{"reason", "old"}}, boss).status, 409);
  const test::Reply r = c.post("/api/machines/mill-2/retire", {{"reason", "sold"}}, boss);
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(r.json()["retire_reason"], "sold");
  EXPECT_EQ(c.get("/api/machines/mill-2", boss).status, 404);
  const auto list = c.get("/api/machines?retired=1", boss).json();
  ASSERT_EQ(list["machines"].size(), 1U);
  ASSERT_EQ(list["retired"].size(), 1U);
  EXPECT_EQ(list["retired"][0]["name"], "mill-2");
  EXPECT_EQ(list["retired"][0]["retired_by"], "boss");
  EXPECT_FALSE(c.get("/api/machines", boss).json().contains("retired"));
  const test::Reply again = c.post("/api/machines", ascii_machine("mill-2", pty.port), boss);
  EXPECT_EQ(again.status, 409) << again.body;
  EXPECT_EQ(audited(c, "mill-2"),
            (std::vector<std::string>{"machine.add:", "machine.retire:sold"}));
}

TEST(ApiMachineAdmin, TheStoresMachinesComeBackAfterARestart) {
  RunningServer first;
  first.start();
  const ApiClient c1 = first.client();
  const std::string boss = c1.log_in("boss", test::kPassword);
  ASSERT_EQ(c1.post("/api/machines", ascii_machine("kept", "tcp://127.0.0.1:9"), boss).status, 201);
  ASSERT_EQ(c1.post("/api/machines", ascii_machine("gone", "tcp://127.0.0.1:10"), boss).status,
            201);
  ASSERT_EQ(c1.post("/api/machines/kept", {{"eob", "crlf"}}, boss).status, 200);
  ASSERT_EQ(c1.post("/api/machines/gone/retire", {{"reason", "sold"}}, boss).status, 200);
  first.stop();
  {
    RunningServer second;
    second.use_store(first.where());
    second.start();
    const ApiClient c2 = second.client();
    const auto list = c2.get("/api/machines", c2.log_in("boss", test::kPassword)).json();
    ASSERT_EQ(list["machines"].size(), 1U) << list.dump();
    EXPECT_EQ(list["machines"][0]["name"], "kept");
    EXPECT_EQ(list["machines"][0]["source"], "api");
    EXPECT_EQ(list["machines"][0]["settings"]["eob"], "crlf");
  }
  // A file naming a machine the store has too: the start says which.
  boost::asio::io_context io;
  ServerConfig config;
  config.machines.push_back(pty_machine("kept", "tcp://127.0.0.1:11", 9600));
  auto clash = Server::open(io, first.where(), config, test::fast_store());
  ASSERT_FALSE(clash);
  EXPECT_NE(clash.error().find("machine kept is in the configuration file"), std::string::npos)
      << clash.error();
}

TEST(MachineSettings, ReadAsTheFileReadsThemAndWrittenBackWhole) {
  auto m = machine_from_settings({{"name", "m1"},
                                  {"port", "/dev/ttyS1"},
                                  {"flow", "rtscts"},
                                  {"xon_timeout", 30},
                                  {"wait_for_xon", true}});
  ASSERT_TRUE(m) << m.error();
  EXPECT_EQ(m->link.flow, Flow::RtsCts);
  EXPECT_EQ(m->link.xon_timeout, 30.0);
  EXPECT_TRUE(m->link.wait_for_xon);
  EXPECT_EQ(m->link.dialect, "rs274ngc");
  auto back = machine_from_settings(machine_settings(*m));
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(machine_settings(*back), machine_settings(*m));
  EXPECT_FALSE(machine_from_settings(nlohmann::json::array()));
  EXPECT_FALSE(machine_from_settings({{"name", "m1"}, {"port", "/dev/x"}, {"calendar", "x"}}));
  const auto huge = machine_from_settings(
      {{"name", "m1"}, {"port", "/dev/x"}, {"skid", 18446744073709551615ULL}});
  ASSERT_FALSE(huge);
  EXPECT_NE(huge.error().find("skid"), std::string::npos) << huge.error();
}

}  // namespace
}  // namespace usina::dnc
