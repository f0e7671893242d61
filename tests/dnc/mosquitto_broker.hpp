// A real Mosquitto broker for the tests, on 127.0.0.1 at a free port, its
// configuration in a scratch folder; and a subscriber (libmosquitto) that
// keeps every message it gets. A machine without the `mosquitto` binary
// skips the test with a message.
#pragma once

#include <mosquitto.h>
#include <signal.h>
#include <spawn.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <sys/wait.h>

extern char** environ;

namespace usina::test {

inline std::string mosquitto_binary() {
  for (const char* p : {"/usr/sbin/mosquitto", "/usr/bin/mosquitto", "/usr/local/sbin/mosquitto"}) {
    if (::access(p, X_OK) == 0) return p;
  }
  return {};
}

inline unsigned short free_port() {
  boost::asio::io_context io;
  boost::asio::ip::tcp::acceptor a(
      io, boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0));
  return a.local_endpoint().port();
}

class MosquittoBroker {
 public:
  // Starts the broker with the listener's `settings` (TLS, logins...);
  // false (and why) when it cannot.
  bool start(std::string* why, const std::string& settings = "allow_anonymous true\n") {
    const std::string bin = mosquitto_binary();
    if (bin.empty()) return *why = "the mosquitto binary is not installed", false;
    dir_ = std::filesystem::temp_directory_path() /
           ("usina_mqtt_" + std::to_string(::getpid()) + "_" + std::to_string(++made()));
    std::filesystem::create_directories(dir_);
    port_ = free_port();
    const std::string conf = (dir_ / "mosquitto.conf").string();
    std::ofstream(conf) << "listener " << port_ << " 127.0.0.1\n"
                        << settings << "persistence false\nlog_dest none\n";
    return spawn(why);
  }

  // Stops the broker and starts it again on its port: without persistence,
  // it has forgotten every retained message.
  bool restart(std::string* why) {
    ::kill(pid_, SIGTERM);
    ::waitpid(pid_, nullptr, 0);
    pid_ = -1;
    return spawn(why);
  }

  ~MosquittoBroker() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
    if (!dir_.empty()) std::filesystem::remove_all(dir_);
  }

  unsigned short port() const { return port_; }

 private:
  bool spawn(std::string* why) {
    const std::string bin = mosquitto_binary();
    const std::string conf = (dir_ / "mosquitto.conf").string();
    std::vector<std::string> args{bin, "-c", conf};
    std::vector<char*> argv;
    for (auto& a : args)
      argv.push_back(a.data());
    argv.push_back(nullptr);
    if (::posix_spawn(&pid_, bin.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
      return *why = "cannot start mosquitto", false;
    for (int i = 0; i < 200; ++i) {  // until it accepts connections
      boost::asio::io_context io;
      boost::asio::ip::tcp::socket s(io);
      boost::system::error_code ec;
      s.connect({boost::asio::ip::make_address("127.0.0.1"), port_}, ec);
      if (!ec) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return *why = "mosquitto did not listen", false;
  }

  static int& made() {
    static int n = 0;
    return n;
  }

  std::filesystem::path dir_;
  pid_t pid_ = -1;
  unsigned short port_ = 0;
};

struct MqttMessage {
  std::string topic;
  std::string payload;
  bool retained = false;
};

class MqttSubscriber {
 public:
  MqttSubscriber() {
    mosquitto_lib_init();
    mosq_ = mosquitto_new(nullptr, true, this);
    mosquitto_connect_callback_set(mosq_, [](mosquitto* m, void* self, int) {
      mosquitto_subscribe(m, nullptr, static_cast<MqttSubscriber*>(self)->filter_.c_str(), 1);
    });
    mosquitto_subscribe_callback_set(mosq_, [](mosquitto*, void* self, int, int, const int*) {
      auto* me = static_cast<MqttSubscriber*>(self);
      std::lock_guard lock(me->mutex_);
      me->subscribed_ = true;
      me->changed_.notify_all();
    });
    mosquitto_message_callback_set(mosq_, [](mosquitto*, void* self, const mosquitto_message* m) {
      auto* me = static_cast<MqttSubscriber*>(self);
      std::lock_guard lock(me->mutex_);
      me->messages_.push_back({m->topic,
                               std::string(static_cast<const char*>(m->payload),
                                           static_cast<std::size_t>(m->payloadlen)),
                               m->retain});
      me->changed_.notify_all();
    });
  }

  ~MqttSubscriber() {
    mosquitto_disconnect(mosq_);
    mosquitto_loop_stop(mosq_, false);
    mosquitto_destroy(mosq_);
  }

  // TLS to the broker, verified against `ca` (and our certificate when given).
  void use_tls(const std::string& ca, const std::string& cert = {}, const std::string& key = {}) {
    mosquitto_tls_set(mosq_, ca.c_str(), nullptr, cert.empty() ? nullptr : cert.c_str(),
                      key.empty() ? nullptr : key.c_str(), nullptr);
  }

  void use_login(const std::string& user, const std::string& password) {
    mosquitto_username_pw_set(mosq_, user.c_str(), password.c_str());
  }

  // Connects and subscribes to `filter`; true once the broker acknowledged.
  bool subscribe(unsigned short port, std::string filter) {
    filter_ = std::move(filter);
    if (mosquitto_connect(mosq_, "127.0.0.1", port, 30) != MOSQ_ERR_SUCCESS) return false;
    mosquitto_loop_start(mosq_);
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, std::chrono::seconds(30), [&] { return subscribed_; });
  }

  // The first message on `topic` (after `skip` earlier ones) that `want`
  // accepts; an empty topic when none came within the deadline.
  template <typename F>
  MqttMessage wait_for(const std::string& topic, F want) {
    std::unique_lock lock(mutex_);
    MqttMessage found;
    changed_.wait_for(lock, std::chrono::seconds(30), [&] {
      for (const MqttMessage& m : messages_) {
        if (m.topic == topic && want(m)) return found = m, true;
      }
      return false;
    });
    return found;
  }

  std::vector<MqttMessage> messages() {
    std::lock_guard lock(mutex_);
    return messages_;
  }

 private:
  mosquitto* mosq_ = nullptr;
  std::string filter_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<MqttMessage> messages_;
  bool subscribed_ = false;
};

}  // namespace usina::test
