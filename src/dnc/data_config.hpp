// The tables of usina-serve.toml for the data that go out of the server
// to the shop's systems:
//
//   [mtconnect]                   # present: the SHDR adapter runs
//   listen = "127.0.0.1:7878"     # where a cppagent connects (port 0: any)
//   heartbeat_ms = 10000          # the PONG's period, told to the agent
//
//   [mqtt]                        # present: events go to the broker
//   url = "mqtts://broker:8883"   # mqtt://host[:port] (1883), mqtts:// TLS (8883)
//   prefix = "usina"              # the topics' first level
//   client_id = "usina-serve"     # the client's id at the broker
//   ca_file = "ca.pem"            # mqtts:// only, required: verifies the broker
//   cert_file = "client.pem"      # mqtts:// only, with key_file: our certificate
//   key_file = "client.key"
//   username = "usina"            # the broker's user
//   password_file = "mqtt.pass"   # its password, the file's first line
//
// The password itself is refused in the TOML: the file is often readable by
// every user of the machine, or kept in git.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <toml++/toml.h>

#include "core/diagnostic.hpp"

namespace usina::dnc {

struct MtconnectConfig {
  bool enabled = false;
  std::string listen = "127.0.0.1:7878";
  std::uint32_t heartbeat_ms = 10000;
};

struct MqttConfig {
  bool enabled = false;
  std::string url = "mqtt://127.0.0.1:1883";
  std::string host = "127.0.0.1";
  std::uint16_t port = 1883;
  std::string prefix = "usina";
  std::string client_id = "usina-serve";
  bool tls = false;  // mqtts://
  std::string ca_file;
  std::string cert_file;
  std::string key_file;
  std::string username;
  std::string password_file;
};

// The `[mtconnect]` and `[mqtt]` tables of `root`; false when a value is
// wrong (E_DNC_CONFIG at its line).
bool read_data_tables(const toml::table& root, MtconnectConfig& mtconnect, MqttConfig& mqtt,
                      std::uint32_t file_id, core::DiagnosticSink& diags);

// "mqtt://host:port" (port 1883 when left out) or "mqtts://host:port" (TLS,
// port 8883) into `into`; false when malformed.
bool parse_mqtt_url(std::string_view url, MqttConfig& into);

}  // namespace usina::dnc
