// MQTT events against a real Mosquitto broker on 127.0.0.1, started by the
// test: a job run through the server arrives as JSON at its topics (queued,
// running, done with the hash), the machine's state (retained) and its part
// count; an upload's revision too.
#include <gtest/gtest.h>

#include "api_control.hpp"
#include "mosquitto_broker.hpp"

namespace usina::dnc {
namespace {

using test::MqttMessage;

const std::string kProgram = "G21 G90\nN10 G0 X1 Y1\nN20 G1 X5 F300\nN30 M2\n";

nlohmann::json payload(const MqttMessage& m) {
  return nlohmann::json::parse(m.payload, nullptr, false);
}

TEST(Mqtt, AJobsEventsReachTheBrokerAsJson) {
  test::MosquittoBroker broker;
  std::string why;
  if (!broker.start(&why)) GTEST_SKIP() << why;
  test::MqttSubscriber sub;
  ASSERT_TRUE(sub.subscribe(broker.port(), "plant7/#"));

  RunningServer s;
  auto pair = open_pty_pair(s.io());
  ASSERT_TRUE(pair) << pair.error();
  Control control;
  control.link = std::move(pair->master);
  control.sim = std::make_shared<SimCnc>(s.io(), *control.link, SimCncConfig{});
  control.sim->start();
  ServerConfig config;
  config.machines.push_back(pty_machine("mill-1", pair->slave_path, 115200));
  config.mqtt.enabled = true;
  ASSERT_TRUE(parse_mqtt_url("mqtt://127.0.0.1:" + std::to_string(broker.port()), config.mqtt));
  config.mqtt.prefix = "plant7";
  s.start(config);

  const ApiClient c = s.client();
  const std::string rev = released(c, "O710", kProgram);
  const std::string oper = c.log_in("oper", test::kPassword);
  const auto r = c.post("/api/machines/mill-1/jobs",
                        {{"program", "O710"}, {"revision", rev}, {"mode", "drip"}}, oper);
  ASSERT_EQ(r.status, 201) << r.body;
  const std::int64_t id = r.json()["job"];
  const auto ended = wait_for_end(c, oper, id);
  ASSERT_EQ(ended["state"], "done");

  const auto of_job = [&](const MqttMessage& m) { return payload(m).value("job", 0) == id; };
  for (const char* state : {"queued", "running", "done"}) {
    const MqttMessage m = sub.wait_for(std::string("plant7/machines/mill-1/job/") + state, of_job);
    ASSERT_FALSE(m.topic.empty()) << "no job/" << state;
    const auto j = payload(m);
    EXPECT_EQ(j["type"], std::string("job.") + state);
    EXPECT_EQ(j["state"], state);
    EXPECT_EQ(j["program"], "O710");
    EXPECT_EQ(j["revision"], rev);
    EXPECT_EQ(j["machine"], "mill-1");
  }
  const auto done = payload(sub.wait_for("plant7/machines/mill-1/job/done", of_job));
  EXPECT_EQ(done["sha256"], ended["sha256"]);
  EXPECT_EQ(done["bytes_sent"], ended["bytes_sent"]);

  const MqttMessage part = sub.wait_for("plant7/machines/mill-1/part", [](auto&) { return true; });
  ASSERT_FALSE(part.topic.empty());
  EXPECT_EQ(payload(part)["part_count"], 1);
  EXPECT_EQ(payload(part)["program"], "O710");
  EXPECT_TRUE(payload(part)["last_cycle_seconds"].is_number());

  const MqttMessage idle = sub.wait_for("plant7/machines/mill-1/state", [](const MqttMessage& m) {
    return payload(m).value("state", "") == "idle";
  });
  ASSERT_FALSE(idle.topic.empty());
  EXPECT_EQ(payload(idle)["type"], "machine.state");

  const MqttMessage made = sub.wait_for("plant7/revision/created", [&](const MqttMessage& m) {
    return payload(m).value("revision", "") == rev;
  });
  EXPECT_FALSE(made.topic.empty());
}

// A server whose machine `mill-1` (a pty, no control behind it) is idle,
// publishing to `broker`; the pty's pair, kept open by the caller.
tl::expected<PtyPair, std::string> start_idle_mill(RunningServer& s,
                                                   const test::MosquittoBroker& broker) {
  auto pair = open_pty_pair(s.io());
  if (!pair) return pair;
  ServerConfig config;
  config.machines.push_back(pty_machine("mill-1", pair->slave_path, 115200));
  config.mqtt.enabled = true;
  if (!parse_mqtt_url("mqtt://127.0.0.1:" + std::to_string(broker.port()), config.mqtt))
    return tl::unexpected(std::string("the broker's URL was refused"));
  s.start(config);
  return pair;
}

TEST(Mqtt, TheMachinesStateIsRetainedForALateSubscriber) {
  test::MosquittoBroker broker;
  std::string why;
  if (!broker.start(&why)) GTEST_SKIP() << why;
  RunningServer s;
  const auto pair = start_idle_mill(s, broker);
  ASSERT_TRUE(pair) << pair.error();
  {  // a first subscriber sees the machine idle: the event has left
    test::MqttSubscriber first;
    ASSERT_TRUE(first.subscribe(broker.port(), "usina/#"));
    ASSERT_FALSE(
        first
            .wait_for("usina/machines/mill-1/state",
                      [](const MqttMessage& m) { return payload(m).value("state", "") == "idle"; })
            .topic.empty());
  }
  test::MqttSubscriber late;
  ASSERT_TRUE(late.subscribe(broker.port(), "usina/machines/+/state"));
  const MqttMessage m = late.wait_for("usina/machines/mill-1/state", [](auto&) { return true; });
  ASSERT_FALSE(m.topic.empty());
  EXPECT_TRUE(m.retained);
  EXPECT_EQ(payload(m)["state"], "idle");
}

// The server keeps each retained topic's last payload and sends it on every
// connection: a broker restarted without persistence has the machine's
// state again (and libmosquitto's resend of a message queued before the
// connection, which drops the retain flag, can no longer lose it).
TEST(Mqtt, ABrokerRestartedWithoutItsRetainedMessagesGetsTheMachinesStateAgain) {
  test::MosquittoBroker broker;
  std::string why;
  if (!broker.start(&why)) GTEST_SKIP() << why;
  RunningServer s;
  const auto pair = start_idle_mill(s, broker);
  ASSERT_TRUE(pair) << pair.error();
  const auto idle = [](const MqttMessage& m) { return payload(m).value("state", "") == "idle"; };
  {
    test::MqttSubscriber first;
    ASSERT_TRUE(first.subscribe(broker.port(), "usina/machines/+/state"));
    ASSERT_FALSE(first.wait_for("usina/machines/mill-1/state", idle).topic.empty());
  }
  ASSERT_TRUE(broker.restart(&why)) << why;
  {  // the server reconnects (after a second) and says it again
    test::MqttSubscriber probe;
    ASSERT_TRUE(probe.subscribe(broker.port(), "usina/machines/+/state"));
    ASSERT_FALSE(probe.wait_for("usina/machines/mill-1/state", idle).topic.empty());
  }
  test::MqttSubscriber late;
  ASSERT_TRUE(late.subscribe(broker.port(), "usina/machines/+/state"));
  const MqttMessage m = late.wait_for("usina/machines/mill-1/state", idle);
  ASSERT_FALSE(m.topic.empty());
  EXPECT_TRUE(m.retained);
}

}  // namespace
}  // namespace usina::dnc
