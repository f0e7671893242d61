// The server's events to an MQTT broker (libmosquitto), for plant-wide
// fan-out. Each event is its JSON (as on the WebSocket) at a topic:
//   PREFIX/machines/MACHINE/state          machine.state (retained)
//   PREFIX/machines/MACHINE/part           machine.part: part count, cycle time (retained)
//   PREFIX/machines/MACHINE/job/done ...   job.* of the machine
//   PREFIX/revision/created ...            the others, their type's dots as levels
// QoS 1, except job.progress (0). libmosquitto runs its own network loop on
// one thread of its own (mosquitto_loop_start): it connects, reconnects
// with a back-off, and keeps the keep-alive, whatever the server's loop is
// doing; publishing from the server's loop only queues the message. While
// the broker is away at most `kMaxPending` messages wait; more are dropped
// and counted.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

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

  // Starts connecting (in the background); an error message when it cannot start.
  std::string start();
  void publish(std::string_view type, const nlohmann::json& event);
  // Sends what is queued (briefly), disconnects and joins the network thread.
  void stop();

  std::uint64_t dropped() const { return dropped_; }

 private:
  static void on_published(mosquitto*, void* self, int);

  MqttConfig config_;
  mosquitto* mosq_ = nullptr;
  std::atomic<int> pending_{0};
  std::atomic<std::uint64_t> dropped_{0};
  bool running_ = false;
};

// The topic of an event: see above.
std::string mqtt_topic(const std::string& prefix, std::string_view type,
                       const nlohmann::json& event);

}  // namespace usina::dnc
