// The server's events to an MQTT broker (libmosquitto), for plant-wide
// fan-out. Each event is its JSON (as on the WebSocket) at a topic:
//   PREFIX/machines/MACHINE/state          machine.state (retained)
//   PREFIX/machines/MACHINE/part           machine.part: part count, cycle time (retained)
//   PREFIX/machines/MACHINE/job/done ...   job.* of the machine
//   PREFIX/revision/created ...            the others, their type's dots as levels
//   PREFIX/server/state                    the server itself: online, or
//                                          offline (the will) (retained)
// QoS 1, except job.progress (0). libmosquitto's network loop runs on one
// thread of ours (mosquitto_loop, not mosquitto_loop_start: that thread
// ends for good on a TLS failure, and we want every failure logged and
// retried): it connects, reconnects with a back-off of 1 s to 30 s, and
// keeps the keep-alive, whatever the server's loop is doing; publishing from
// the server's loop only queues the message. While the broker is away at
// most `kMaxPending` messages wait; more are dropped and counted.
//
// mqtts:// is TLS 1.2 or later, the broker's certificate verified against
// ca_file with its host name, never insecure; a client certificate when
// cert_file and key_file are given. The will (PREFIX/server/state offline,
// retained) is left with the broker at connect, so subscribers learn that
// the server died; a clean stop publishes offline itself.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "dnc/data_config.hpp"

struct mosquitto;

namespace usina::dnc {

class MqttPublisher {
 public:
  static constexpr int kMaxPending = 10000;

  explicit MqttPublisher(MqttConfig config);
  ~MqttPublisher();
  MqttPublisher(const MqttPublisher&) = delete;
  MqttPublisher& operator=(const MqttPublisher&) = delete;

  // Checks the files of the configuration (an error naming the key when one
  // cannot be read) and starts connecting in the background; an error
  // message when it cannot start. A broker that is away or refuses us is
  // no error here: the attempts are logged and retried.
  std::string start();
  void publish(std::string_view type, const nlohmann::json& event);
  // Publishes offline, sends what is queued (briefly), disconnects and joins
  // the network thread.
  void stop();

  std::uint64_t dropped() const { return dropped_; }

  // Connection attempts that failed, and the last one's reason (as logged).
  std::uint64_t failures() const { return failures_; }

  std::string last_failure() const;

  bool connected() const { return connected_; }

 private:
  static void on_connect(mosquitto*, void* self, int reason);
  static void on_disconnect(mosquitto*, void* self, int);
  static void on_published(mosquitto*, void* self, int);
  static void on_log(mosquitto*, void* self, int level, const char* line);

  std::string set_up_tls();
  std::string set_up_login();
  std::string set_up_session();
  void network_loop();
  void run_connection(bool first);
  void note_failure(int rc, int error_number);
  bool wait_before_retry(int seconds);
  void publish_server_state(const nlohmann::json& state);
  void send(const std::string& topic, const std::string& payload, int qos, bool retain);
  void send_retained();

  MqttConfig config_;
  std::string password_;
  mosquitto* mosq_ = nullptr;
  std::thread network_;
  std::atomic<int> pending_{0};
  std::atomic<std::uint64_t> dropped_{0};
  std::atomic<std::uint64_t> failures_{0};
  std::atomic<bool> connected_{false};
  std::atomic<bool> stopping_{false};
  std::chrono::steady_clock::time_point stop_deadline_;  // set before stopping_
  bool running_ = false;
  bool had_connack_ = false;  // network thread only: the back-off starts again
  int refused_reason_ = 0;    // network thread only: the CONNACK's code
  mutable std::mutex mutex_;
  std::condition_variable woken_;
  std::string tls_error_;  // libmosquitto's last error line (OpenSSL's reason)
  std::string last_failure_;
  // The last payload of each retained topic (a machine's state and part
  // count), guarded by mutex_: sent again on every connection, so a
  // subscriber always finds them retained (below, send_retained).
  std::map<std::string, std::string> retained_;
};

// The retained payloads of PREFIX/server/state: online (at each connect,
// with its time), the will (offline, the connection lost) and a clean stop.
nlohmann::json mqtt_server_online(const MqttConfig& config);
nlohmann::json mqtt_server_offline(const MqttConfig& config, bool stopped);

// The topic of an event: see above.
std::string mqtt_topic(const std::string& prefix, std::string_view type,
                       const nlohmann::json& event);

}  // namespace usina::dnc
