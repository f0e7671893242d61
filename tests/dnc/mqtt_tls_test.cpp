// MQTT over TLS with the broker's user and password, and the will, against
// a real Mosquitto on 127.0.0.1: a CA, the broker's and a client's
// certificates are made by the openssl CLI at test time, the logins by
// mosquitto_passwd. The tests are skipped, with a message, when mosquitto,
// mosquitto_passwd or openssl is missing.
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "dnc/mqtt_publisher.hpp"
#include "mosquitto_broker.hpp"

namespace usina::dnc {
namespace {

namespace fs = std::filesystem;
using test::MqttMessage;

constexpr const char* kUserPassword = "s3cret pass";
constexpr const char* kReaderPassword = "reader-pass";

nlohmann::json payload(const MqttMessage& m) {
  return nlohmann::json::parse(m.payload, nullptr, false);
}

// Waits (30 s at most) until `done` holds; its last answer.
template <typename F>
bool eventually(F done) {
  for (int i = 0; i < 600 && !done(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  return done();
}

// A scratch folder with a CA, the broker's certificate for 127.0.0.1, one
// for another host name, a client certificate, a second CA that signed
// none of them, and Mosquitto's password file (users `usina`, `reader`).
class TestPki {
 public:
  bool make(std::string* why) {
    if (test::mosquitto_binary().empty()) return *why = "mosquitto is not installed", false;
    dir_ = fs::temp_directory_path() /
           ("usina_mqtt_pki_" + std::to_string(::getpid()) + "_" + std::to_string(++made()));
    fs::create_directories(dir_);
    const std::string script = R"sh(
set -e
key() { openssl req -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes "$@"; }
key -x509 -days 2 -keyout ca.key -out ca.pem -subj /CN=usina-test-ca
key -x509 -days 2 -keyout other-ca.key -out other-ca.pem -subj /CN=other-test-ca
sign() {
  key -keyout $1.key -out $1.csr -subj /CN=$2
  printf '%s\n' "$3" > $1.ext
  openssl x509 -req -in $1.csr -CA ca.pem -CAkey ca.key -CAcreateserial -days 2 \
    -out $1.pem -extfile $1.ext
}
sign server 127.0.0.1 subjectAltName=IP:127.0.0.1,DNS:localhost
sign elsewhere elsewhere.example subjectAltName=DNS:elsewhere.example
sign client usina-serve extendedKeyUsage=clientAuth
mosquitto_passwd -b -c passwd usina 's3cret pass'
mosquitto_passwd -b passwd reader reader-pass
printf 'wrong\n' > wrong.pass
printf 's3cret pass\n' > usina.pass
chmod 644 *
)sh";
    std::ofstream(dir_ / "make.sh") << script;
    const std::string command = "cd '" + dir_.string() + "' && sh make.sh >make.log 2>&1";
    // The test's own thread is the only one running here.
    if (std::system(command.c_str()) != 0) {  // NOLINT(concurrency-mt-unsafe)
      *why =
          "cannot make the certificates or the password file (openssl, mosquitto_passwd): "
          "see " +
          (dir_ / "make.log").string();
      return false;
    }
    return true;
  }

  ~TestPki() {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  std::string file(const char* name) const { return (dir_ / name).string(); }

  // The listener's settings: TLS with `cert`, logins required.
  std::string broker_settings(const char* cert, bool require_certificate) const {
    return "cafile " + file("ca.pem") + "\ncertfile " + file((std::string(cert) + ".pem").c_str()) +
           "\nkeyfile " + file((std::string(cert) + ".key").c_str()) +
           "\ntls_version tlsv1.2\nrequire_certificate " +
           (require_certificate ? "true" : "false") + "\nallow_anonymous false\npassword_file " +
           file("passwd") + "\n";
  }

  // The publisher's [mqtt] for a broker at `port`.
  MqttConfig publisher(unsigned short port) const {
    MqttConfig c;
    c.enabled = true;
    EXPECT_TRUE(parse_mqtt_url("mqtts://127.0.0.1:" + std::to_string(port), c));
    c.prefix = "plant9";
    c.client_id = "usina-test-" + std::to_string(::getpid());
    c.ca_file = file("ca.pem");
    c.username = "usina";
    c.password_file = file("usina.pass");
    return c;
  }

  void as_reader(test::MqttSubscriber& sub, bool with_certificate = false) const {
    if (with_certificate) {
      sub.use_tls(file("ca.pem"), file("client.pem"), file("client.key"));
    } else {
      sub.use_tls(file("ca.pem"));
    }
    sub.use_login("reader", kReaderPassword);
  }

 private:
  static int& made() {
    static int n = 0;
    return n;
  }

  fs::path dir_;
};

struct TlsBroker {
  TestPki pki;
  test::MosquittoBroker broker;

  bool start(std::string* why, const char* cert = "server", bool require_certificate = false) {
    return pki.make(why) && broker.start(why, pki.broker_settings(cert, require_certificate));
  }
};

const nlohmann::json kIdle = {{"type", "machine.state"}, {"machine", "mill-1"}, {"state", "idle"}};

TEST(MqttTls, AnEventArrivesOverTlsWithTheBrokersUser) {
  TlsBroker b;
  std::string why;
  if (!b.start(&why)) GTEST_SKIP() << why;
  MqttPublisher publisher(b.pki.publisher(b.broker.port()));
  ASSERT_EQ(publisher.start(), "");
  ASSERT_TRUE(eventually([&] { return publisher.connected(); })) << publisher.last_failure();
  publisher.publish("machine.state", kIdle);

  test::MqttSubscriber sub;
  b.pki.as_reader(sub);
  ASSERT_TRUE(sub.subscribe(b.broker.port(), "plant9/#"));
  const MqttMessage state =
      sub.wait_for("plant9/machines/mill-1/state", [](auto&) { return true; });
  ASSERT_FALSE(state.topic.empty());
  EXPECT_EQ(payload(state)["state"], "idle");
  // The server's own state, retained since it connected: a late subscriber has it.
  const MqttMessage online = sub.wait_for("plant9/server/state", [](auto&) { return true; });
  ASSERT_FALSE(online.topic.empty());
  EXPECT_TRUE(online.retained);
  EXPECT_EQ(payload(online)["state"], "online");
  EXPECT_EQ(payload(online)["type"], "server.state");
  EXPECT_TRUE(payload(online)["since"].is_string());
  EXPECT_EQ(publisher.failures(), 0u);
}

TEST(MqttTls, AClientCertificateIsShownWhenTheBrokerAsksForOne) {
  TlsBroker b;
  std::string why;
  if (!b.start(&why, "server", true)) GTEST_SKIP() << why;
  MqttConfig with = b.pki.publisher(b.broker.port());
  with.cert_file = b.pki.file("client.pem");
  with.key_file = b.pki.file("client.key");
  MqttPublisher shown(with);
  ASSERT_EQ(shown.start(), "");
  ASSERT_TRUE(eventually([&] { return shown.connected(); })) << shown.last_failure();

  test::MqttSubscriber sub;
  b.pki.as_reader(sub, true);
  ASSERT_TRUE(sub.subscribe(b.broker.port(), "plant9/#"));
  shown.publish("machine.state", kIdle);
  EXPECT_FALSE(
      sub.wait_for("plant9/machines/mill-1/state", [](auto&) { return true; }).topic.empty());

  MqttConfig without = b.pki.publisher(b.broker.port());
  without.client_id += "-bare";
  MqttPublisher bare(without);
  ASSERT_EQ(bare.start(), "");
  ASSERT_TRUE(eventually([&] { return bare.failures() >= 1; }));
  EXPECT_FALSE(bare.connected());
}

TEST(MqttTls, AWrongPasswordIsRefusedAndRetriedWithoutACrash) {
  TlsBroker b;
  std::string why;
  if (!b.start(&why)) GTEST_SKIP() << why;
  MqttConfig c = b.pki.publisher(b.broker.port());
  c.password_file = b.pki.file("wrong.pass");
  MqttPublisher publisher(c);
  ASSERT_EQ(publisher.start(), "");
  publisher.publish("machine.state", kIdle);  // queued, never sent: no harm
  // Attempts go on; one of them reads the CONNACK's refusal (another may
  // find the socket closed first, after the broker said no).
  ASSERT_TRUE(eventually([&] {
    return publisher.failures() >= 2 &&
           publisher.last_failure().find("refused us: Connection Refused") != std::string::npos;
  })) << publisher.last_failure();
  EXPECT_FALSE(publisher.connected());
  publisher.stop();  // returns: no hang between attempts
}

TEST(MqttTls, ABrokerSignedByAnotherCaIsNotTrusted) {
  TlsBroker b;
  std::string why;
  if (!b.start(&why)) GTEST_SKIP() << why;
  MqttConfig c = b.pki.publisher(b.broker.port());
  c.ca_file = b.pki.file("other-ca.pem");
  MqttPublisher publisher(c);
  ASSERT_EQ(publisher.start(), "");
  ASSERT_TRUE(eventually([&] { return publisher.failures() >= 2; })) << publisher.last_failure();
  EXPECT_NE(publisher.last_failure().find("certificate verify failed"), std::string::npos)
      << publisher.last_failure();
  EXPECT_FALSE(publisher.connected());
}

TEST(MqttTls, TheBrokersHostNameIsChecked) {
  TlsBroker b;
  std::string why;
  // Signed by our CA, but for elsewhere.example, not 127.0.0.1.
  if (!b.start(&why, "elsewhere")) GTEST_SKIP() << why;
  MqttPublisher publisher(b.pki.publisher(b.broker.port()));
  ASSERT_EQ(publisher.start(), "");
  ASSERT_TRUE(eventually([&] { return publisher.failures() >= 1; })) << publisher.last_failure();
  EXPECT_NE(publisher.last_failure().find("certificate verify failed"), std::string::npos)
      << publisher.last_failure();
  EXPECT_FALSE(publisher.connected());
}

TEST(MqttTls, StartNamesTheKeyOfAFileThatCannotBeRead) {
  TestPki pki;
  std::string why;
  if (!pki.make(&why)) GTEST_SKIP() << why;
  std::ofstream(pki.file("empty.pass")).flush();
  std::ofstream(pki.file("blank.pass")) << "\nsecond line\n";
  const std::string missing = pki.file("missing.pem");
  const auto start_error = [&](auto change) {
    MqttConfig c = pki.publisher(1);
    change(c);
    MqttPublisher p(c);
    return p.start();
  };
  const auto has = [](const std::string& error, const char* text) {
    return error.find(text) != std::string::npos;
  };
  std::string e = start_error([&](MqttConfig& c) { c.ca_file = missing; });
  EXPECT_TRUE(has(e, "mqtt.ca_file") && has(e, "No such file")) << e;
  e = start_error([&](MqttConfig& c) {
    c.cert_file = missing;
    c.key_file = pki.file("client.key");
  });
  EXPECT_TRUE(has(e, "mqtt.cert_file")) << e;
  e = start_error([&](MqttConfig& c) {
    c.cert_file = pki.file("client.pem");
    c.key_file = missing;
  });
  EXPECT_TRUE(has(e, "mqtt.key_file")) << e;
  e = start_error([&](MqttConfig& c) { c.password_file = missing; });
  EXPECT_TRUE(has(e, "mqtt.password_file")) << e;
  e = start_error([&](MqttConfig& c) { c.password_file = pki.file("empty.pass"); });
  EXPECT_TRUE(has(e, "mqtt.password_file") && has(e, "empty")) << e;
  e = start_error([&](MqttConfig& c) { c.password_file = pki.file("blank.pass"); });
  EXPECT_TRUE(has(e, "mqtt.password_file") && has(e, "empty")) << e;
  e = start_error([&](MqttConfig& c) { c.ca_file = fs::temp_directory_path().string(); });
  EXPECT_TRUE(has(e, "mqtt.ca_file") && has(e, "not a file")) << e;
}

// A plain broker with anonymous access, for the will (TLS plays no part in it).
MqttConfig plain(unsigned short port, const std::string& client_id) {
  MqttConfig c;
  c.enabled = true;
  EXPECT_TRUE(parse_mqtt_url("mqtt://127.0.0.1:" + std::to_string(port), c));
  c.prefix = "plant9";
  c.client_id = client_id;
  return c;
}

TEST(MqttWill, TheBrokerSaysOfflineWhenTheServersProcessDies) {
  test::MosquittoBroker broker;
  std::string why;
  if (!broker.start(&why)) GTEST_SKIP() << why;
  const MqttConfig config = plain(broker.port(), "usina-will-" + std::to_string(::getpid()));
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // the server: connects, then waits to be killed
    MqttPublisher publisher(config);
    if (!publisher.start().empty()) ::_exit(2);
    for (;;)
      ::pause();
  }
  test::MqttSubscriber sub;
  ASSERT_TRUE(sub.subscribe(broker.port(), "plant9/server/state"));
  const MqttMessage online = sub.wait_for("plant9/server/state", [](const MqttMessage& m) {
    return payload(m).value("state", "") == "online";
  });
  const bool seen_online = !online.topic.empty();
  ::kill(child, SIGKILL);  // no DISCONNECT: the broker sends the will
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(seen_online);
  EXPECT_EQ(payload(online)["client_id"], config.client_id);
  const MqttMessage offline = sub.wait_for("plant9/server/state", [](const MqttMessage& m) {
    return payload(m).value("state", "") == "offline";
  });
  ASSERT_FALSE(offline.topic.empty());
  EXPECT_EQ(payload(offline)["reason"], "connection lost");
  EXPECT_EQ(payload(offline)["client_id"], config.client_id);

  test::MqttSubscriber late;  // the will is retained
  ASSERT_TRUE(late.subscribe(broker.port(), "plant9/server/state"));
  const MqttMessage kept = late.wait_for("plant9/server/state", [](auto&) { return true; });
  ASSERT_FALSE(kept.topic.empty());
  EXPECT_TRUE(kept.retained);
  EXPECT_EQ(payload(kept)["state"], "offline");
}

TEST(MqttWill, ACleanStopSaysOfflineItself) {
  test::MosquittoBroker broker;
  std::string why;
  if (!broker.start(&why)) GTEST_SKIP() << why;
  test::MqttSubscriber sub;
  ASSERT_TRUE(sub.subscribe(broker.port(), "plant9/server/state"));
  MqttPublisher publisher(plain(broker.port(), "usina-stop-" + std::to_string(::getpid())));
  ASSERT_EQ(publisher.start(), "");
  ASSERT_FALSE(
      sub.wait_for("plant9/server/state",
                   [](const MqttMessage& m) { return payload(m).value("state", "") == "online"; })
          .topic.empty());
  publisher.stop();
  const MqttMessage offline = sub.wait_for("plant9/server/state", [](const MqttMessage& m) {
    return payload(m).value("state", "") == "offline";
  });
  ASSERT_FALSE(offline.topic.empty());
  EXPECT_EQ(payload(offline)["reason"], "stopped");
  EXPECT_TRUE(payload(offline)["since"].is_string());
}

}  // namespace
}  // namespace usina::dnc
