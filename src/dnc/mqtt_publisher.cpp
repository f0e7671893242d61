#include "dnc/mqtt_publisher.hpp"

#include <mosquitto.h>

#include <chrono>
#include <mutex>
#include <thread>

#include <fmt/format.h>

namespace usina::dnc {
namespace {

void init_library() {
  static std::once_flag once;
  std::call_once(once, [] { mosquitto_lib_init(); });
}

std::string levels(std::string_view type) {
  std::string out(type);
  for (char& c : out) {
    if (c == '.') c = '/';
  }
  return out;
}

bool retained(std::string_view type) {
  return type == "machine.state" || type == "machine.part";
}

}  // namespace

std::string mqtt_topic(const std::string& prefix, std::string_view type,
                       const nlohmann::json& event) {
  const auto machine = event.find("machine");
  if (machine == event.end() || !machine->is_string()) return prefix + "/" + levels(type);
  std::string_view rest = type;
  if (rest.starts_with("machine.")) rest.remove_prefix(8);
  return fmt::format("{}/machines/{}/{}", prefix, machine->get<std::string>(), levels(rest));
}

MqttPublisher::MqttPublisher(MqttConfig config) : config_(std::move(config)) {}

MqttPublisher::~MqttPublisher() {
  stop();
  if (mosq_ != nullptr) mosquitto_destroy(mosq_);
}

void MqttPublisher::on_published(mosquitto*, void* self, int) {
  --static_cast<MqttPublisher*>(self)->pending_;
}

std::string MqttPublisher::start() {
  init_library();
  mosq_ = mosquitto_new(config_.client_id.c_str(), true, this);
  if (mosq_ == nullptr) return "mqtt: cannot make a client (out of memory)";
  mosquitto_int_option(mosq_, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
  mosquitto_publish_callback_set(mosq_, &MqttPublisher::on_published);
  mosquitto_reconnect_delay_set(mosq_, 1, 30, true);
  // A broker that is not there yet is no error: the loop keeps trying.
  const int rc = mosquitto_connect_async(mosq_, config_.host.c_str(), config_.port, 30);
  if (rc != MOSQ_ERR_SUCCESS && rc != MOSQ_ERR_ERRNO)
    return fmt::format("mqtt: cannot connect to {}: {}", config_.url, mosquitto_strerror(rc));
  if (const int lrc = mosquitto_loop_start(mosq_); lrc != MOSQ_ERR_SUCCESS)
    return fmt::format("mqtt: cannot start the network loop: {}", mosquitto_strerror(lrc));
  running_ = true;
  return {};
}

void MqttPublisher::publish(std::string_view type, const nlohmann::json& event) {
  if (!running_) return;
  if (pending_ >= kMaxPending) {
    ++dropped_;
    return;
  }
  const std::string topic = mqtt_topic(config_.prefix, type, event);
  const std::string payload = event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  const int qos = type == "job.progress" ? 0 : 1;
  ++pending_;
  const int rc = mosquitto_publish(mosq_, nullptr, topic.c_str(), static_cast<int>(payload.size()),
                                   payload.data(), qos, retained(type));
  // Not connected: a QoS 1 message stays queued for the connection; QoS 0 is gone.
  if (rc != MOSQ_ERR_SUCCESS && (qos == 0 || rc != MOSQ_ERR_NO_CONN)) --pending_;
}

void MqttPublisher::stop() {
  if (!running_) return;
  running_ = false;
  // Give the queued messages a moment to leave before the disconnect.
  for (int i = 0; i < 20 && pending_ > 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  mosquitto_disconnect(mosq_);
  mosquitto_loop_stop(mosq_, false);
}

}  // namespace usina::dnc
