// The server's data for the shop's systems: the MTConnect SHDR adapter and
// the MQTT events, both fed from the server's events.
#include "dnc/server.hpp"
#include "dnc/store_jobs.hpp"

namespace usina::dnc {

void Server::add_data_outputs() {
  if (config_.mtconnect.enabled) {
    shdr_ = std::make_unique<ShdrAdapter>(io_, config_.mtconnect);
    for (const auto& m : machines_->all()) {
      MachineItems items;  // offline until its port opens
      if (auto parts = machine_part_count(*store_, m->config.link.name)) {
        items.part_count = parts->parts;
        items.program = parts->last_program;
      }
      shdr_->add_machine(m->config.link.name, items);
    }
    events_.listen([this](std::string_view type, const nlohmann::json& event) {
      shdr_->on_event(type, event);
    });
  }
  if (config_.mqtt.enabled) {
    mqtt_ = std::make_unique<MqttPublisher>(config_.mqtt);
    events_.listen([this](std::string_view type, const nlohmann::json& event) {
      mqtt_->publish(type, event);
    });
  }
}

std::string Server::start_data_outputs() {
  if (shdr_) {
    if (std::string error = shdr_->start(); !error.empty()) return error;
  }
  if (mqtt_) {
    if (std::string error = mqtt_->start(); !error.empty()) return error;
  }
  return {};
}

std::optional<boost::asio::ip::tcp::endpoint> Server::mtconnect_endpoint() const {
  if (!shdr_) return std::nullopt;
  return shdr_->endpoint();
}

}  // namespace usina::dnc
