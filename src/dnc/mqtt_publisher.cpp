#include "dnc/mqtt_publisher.hpp"

#include <mosquitto.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "dnc/mtconnect_items.hpp"

namespace usina::dnc {
namespace {

constexpr int kKeepAliveSeconds = 30;
constexpr int kMaxRetrySeconds = 30;

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

void log_line(const std::string& text) {
  fmt::print(stderr, "usina serve: mqtt: {}\n", text);
}

// Why the file of mqtt.`key` cannot be read, empty when it can.
std::string unreadable(const char* key, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    return fmt::format("mqtt.{} {} cannot be read: {}", key, path,
                       std::generic_category().message(errno));
  }
  char c = 0;
  if (!in.get(c)) return fmt::format("mqtt.{} {} is empty or not a file", key, path);
  return {};
}

// The password: the first line of mqtt.password_file, without its line end.
std::string read_password(const std::string& path, std::string& password) {
  if (std::string why = unreadable("password_file", path); !why.empty()) return why;
  std::ifstream in(path, std::ios::binary);
  std::getline(in, password);
  if (!password.empty() && password.back() == '\r') password.pop_back();
  if (password.empty())
    return fmt::format("mqtt.password_file {}: its first line (the password) is empty", path);
  return {};
}

// The broker as the log names it (the URL as parsed: scheme, host, port).
std::string broker_name(const MqttConfig& c) {
  return fmt::format("{}://{}:{}", c.tls ? "mqtts" : "mqtt",
                     c.host.find(':') != std::string::npos ? "[" + c.host + "]" : c.host, c.port);
}

// An encrypted client key would make OpenSSL ask on the terminal: a server
// does not ask, the key is refused instead (no password given).
int no_key_password(char*, int, int, void*) {
  return 0;
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

nlohmann::json mqtt_server_online(const MqttConfig& config) {
  return {{"type", "server.state"},
          {"state", "online"},
          {"client_id", config.client_id},
          {"since", shdr_timestamp()}};
}

nlohmann::json mqtt_server_offline(const MqttConfig& config, bool stopped) {
  nlohmann::json j = {{"type", "server.state"},
                      {"state", "offline"},
                      {"client_id", config.client_id},
                      {"reason", stopped ? "stopped" : "connection lost"}};
  if (stopped) j["since"] = shdr_timestamp();
  return j;
}

MqttPublisher::MqttPublisher(MqttConfig config) : config_(std::move(config)) {}

MqttPublisher::~MqttPublisher() {
  try {
    stop();
  } catch (...) {  // NOLINT(bugprone-empty-catch): out of memory while stopping; the thread is gone
  }
  if (mosq_ != nullptr) mosquitto_destroy(mosq_);
}

std::string MqttPublisher::last_failure() const {
  std::lock_guard lock(mutex_);
  return last_failure_;
}

void MqttPublisher::on_connect(mosquitto*, void* self, int reason) {
  auto* me = static_cast<MqttPublisher*>(self);
  if (reason != 0) {  // refused: the loop reports it, with this reason
    me->refused_reason_ = reason;
    return;
  }
  me->had_connack_ = true;
  me->connected_ = true;
  log_line(fmt::format("connected to {}", broker_name(me->config_)));
  me->publish_server_state(mqtt_server_online(me->config_));
  me->send_retained();
}

void MqttPublisher::on_disconnect(mosquitto*, void* self, int) {
  static_cast<MqttPublisher*>(self)->connected_ = false;
}

void MqttPublisher::on_published(mosquitto*, void* self, int) {
  --static_cast<MqttPublisher*>(self)->pending_;
}

void MqttPublisher::on_log(mosquitto*, void* self, int level, const char* line) {
  if (level != MOSQ_LOG_ERR) return;
  auto* me = static_cast<MqttPublisher*>(self);
  std::lock_guard lock(me->mutex_);
  me->tls_error_ = line;
}

// TLS: the files checked, the broker verified, a client certificate.
std::string MqttPublisher::set_up_tls() {
  for (const auto& [key, path] :
       {std::pair{"ca_file", &config_.ca_file}, std::pair{"cert_file", &config_.cert_file},
        std::pair{"key_file", &config_.key_file}}) {
    if (path->empty()) continue;
    if (std::string why = unreadable(key, *path); !why.empty()) return why;
  }
  const auto optional = [](const std::string& s) { return s.empty() ? nullptr : s.c_str(); };
  int rc = mosquitto_tls_set(mosq_, config_.ca_file.c_str(), nullptr, optional(config_.cert_file),
                             optional(config_.key_file), &no_key_password);
  // The broker's certificate verified, TLS 1.2 at the least, and its host
  // name checked (insecure mode off, as it is by default).
  if (rc == MOSQ_ERR_SUCCESS) rc = mosquitto_tls_opts_set(mosq_, 1, "tlsv1.2", nullptr);
  if (rc == MOSQ_ERR_SUCCESS) rc = mosquitto_tls_insecure_set(mosq_, false);
  if (rc != MOSQ_ERR_SUCCESS)
    return fmt::format("mqtt: cannot set up TLS: {}", mosquitto_strerror(rc));
  return {};
}

// The broker's user, its password read from password_file.
std::string MqttPublisher::set_up_login() {
  if (!config_.password_file.empty()) {
    if (std::string why = read_password(config_.password_file, password_); !why.empty()) return why;
  }
  if (config_.username.empty()) return {};
  const int rc = mosquitto_username_pw_set(mosq_, config_.username.c_str(),
                                           password_.empty() ? nullptr : password_.c_str());
  if (rc != MOSQ_ERR_SUCCESS) return fmt::format("mqtt.username: {}", mosquitto_strerror(rc));
  return {};
}

// TLS, the broker's user and the will, before the first connect.
std::string MqttPublisher::set_up_session() {
  if (config_.tls) {
    if (std::string error = set_up_tls(); !error.empty()) return error;
  }
  if (std::string error = set_up_login(); !error.empty()) return error;
  const std::string topic = config_.prefix + "/server/state";
  const std::string will = mqtt_server_offline(config_, false).dump();
  if (const int rc = mosquitto_will_set(mosq_, topic.c_str(), static_cast<int>(will.size()),
                                        will.data(), 1, true);
      rc != MOSQ_ERR_SUCCESS)
    return fmt::format("mqtt: cannot set the will: {}", mosquitto_strerror(rc));
  return {};
}

std::string MqttPublisher::start() {
  init_library();
  mosq_ = mosquitto_new(config_.client_id.c_str(), true, this);
  if (mosq_ == nullptr) return "mqtt: cannot make a client (out of memory)";
  mosquitto_int_option(mosq_, MOSQ_OPT_PROTOCOL_VERSION, MQTT_PROTOCOL_V311);
  mosquitto_connect_callback_set(mosq_, &MqttPublisher::on_connect);
  mosquitto_disconnect_callback_set(mosq_, &MqttPublisher::on_disconnect);
  mosquitto_publish_callback_set(mosq_, &MqttPublisher::on_published);
  mosquitto_log_callback_set(mosq_, &MqttPublisher::on_log);
  if (std::string error = set_up_session(); !error.empty()) return error;
  // Our own thread runs the loop: publish() only queues and wakes it.
  mosquitto_threaded_set(mosq_, true);
  running_ = true;
  network_ = std::thread([this] { network_loop(); });
  return {};
}

// Connects, and after a failure connects again with a back-off of 1 s
// doubling to 30 s (from 1 s again after a connection that was accepted),
// until stop().
void MqttPublisher::network_loop() {
  int retry_seconds = 1;
  for (bool first = true; !stopping_; first = false) {
    run_connection(first);
    if (stopping_) break;
    if (had_connack_) retry_seconds = 1;
    had_connack_ = false;
    if (!wait_before_retry(retry_seconds)) break;
    retry_seconds = std::min(retry_seconds * 2, kMaxRetrySeconds);
  }
}

// One connection, from the connect to its end (its failure noted).
void MqttPublisher::run_connection(bool first) {
  {
    std::lock_guard lock(mutex_);
    tls_error_.clear();
  }
  refused_reason_ = 0;
  int rc =
      first ? mosquitto_connect_async(mosq_, config_.host.c_str(), config_.port, kKeepAliveSeconds)
            : mosquitto_reconnect_async(mosq_);
  // Stopping, the loop runs on while connected, to send offline and the
  // DISCONNECT; for 2 s at most, as the broker may not read.
  const auto done = [this] {
    return stopping_ && (!connected_ || std::chrono::steady_clock::now() > stop_deadline_);
  };
  while (rc == MOSQ_ERR_SUCCESS && !done())
    rc = mosquitto_loop(mosq_, 1000, 1);
  const int error_number = errno;
  connected_ = false;
  if (!stopping_) note_failure(rc, error_number);
}

void MqttPublisher::note_failure(int rc, int error_number) {
  std::string why;
  {
    std::lock_guard lock(mutex_);
    if (rc == MOSQ_ERR_CONN_REFUSED && refused_reason_ != 0) {
      why = fmt::format("the broker refused us: {}", mosquitto_connack_string(refused_reason_));
    } else if (!tls_error_.empty()) {
      why = tls_error_;  // OpenSSL's reason: a certificate not verified, a bad key...
    } else if (rc == MOSQ_ERR_ERRNO) {
      why = std::generic_category().message(error_number);
    } else {
      why = mosquitto_strerror(rc);
    }
    last_failure_ = why;
  }
  ++failures_;
  log_line(fmt::format("no connection to {}: {}; trying again", broker_name(config_), why));
}

// Sleeps `seconds`, or less when stop() wakes it; false when stopping.
bool MqttPublisher::wait_before_retry(int seconds) {
  std::unique_lock lock(mutex_);
  return !woken_.wait_for(lock, std::chrono::seconds(seconds), [this] { return stopping_.load(); });
}

void MqttPublisher::publish_server_state(const nlohmann::json& state) {
  const std::string topic = config_.prefix + "/server/state";
  const std::string payload = state.dump();
  ++pending_;
  if (mosquitto_publish(mosq_, nullptr, topic.c_str(), static_cast<int>(payload.size()),
                        payload.data(), 1, true) != MOSQ_ERR_SUCCESS)
    --pending_;
}

void MqttPublisher::send(const std::string& topic, const std::string& payload, int qos,
                         bool retain) {
  ++pending_;
  const int rc = mosquitto_publish(mosq_, nullptr, topic.c_str(), static_cast<int>(payload.size()),
                                   payload.data(), qos, retain);
  // Not connected: a QoS 1 message stays queued for the connection; QoS 0 is gone.
  if (rc != MOSQ_ERR_SUCCESS && (qos == 0 || rc != MOSQ_ERR_NO_CONN)) --pending_;
}

// libmosquitto 2.0.11 (Debian 12) sends a message queued before the
// connection again without its retain flag (the broker's log: "d1, q1,
// r0"), so a state published while the connection was being made reached
// the subscribers then but was never retained for a later one. Retained
// messages are therefore never queued: they are kept here and sent, with
// the flag, on each connection (a broker restarted without persistence gets
// them again too).
void MqttPublisher::send_retained() {
  std::map<std::string, std::string> now;
  {
    std::lock_guard lock(mutex_);
    now = retained_;
  }
  for (const auto& [topic, payload] : now)
    send(topic, payload, 1, true);
}

void MqttPublisher::publish(std::string_view type, const nlohmann::json& event) {
  if (!running_) return;
  if (pending_ >= kMaxPending) {
    ++dropped_;
    return;
  }
  const std::string topic = mqtt_topic(config_.prefix, type, event);
  const std::string payload = event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (retained(type)) {
    {
      std::lock_guard lock(mutex_);
      retained_[topic] = payload;
    }
    // Kept before connected_ is read: a connection made meanwhile sends it.
    if (connected_) send(topic, payload, 1, true);
    return;
  }
  send(topic, payload, type == "job.progress" ? 0 : 1, false);
}

void MqttPublisher::stop() {
  if (!running_) return;
  running_ = false;
  // The broker sends no will on a clean disconnect: say offline ourselves.
  if (connected_) publish_server_state(mqtt_server_offline(config_, true));
  // Give the queued messages a moment to leave before the disconnect.
  for (int i = 0; i < 20 && pending_ > 0 && connected_; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  {
    std::lock_guard lock(mutex_);
    stop_deadline_ = std::chrono::steady_clock::now() + std::chrono::seconds(2);
    stopping_ = true;
  }
  woken_.notify_all();
  mosquitto_disconnect(mosq_);
  if (network_.joinable()) network_.join();
}

}  // namespace usina::dnc
