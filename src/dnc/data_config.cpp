#include "dnc/data_config.hpp"

#include <charconv>

#include <fmt/format.h>

#include "dnc/config_report.hpp"

namespace usina::dnc {
namespace {

void fail(core::DiagnosticSink& diags, std::uint32_t file_id, const toml::source_region& at,
          std::string message) {
  config_error(diags, file_id, at, std::move(message));
}

// A string key of `t` into `into`; false (reported) when it is not a string.
bool read_string(const toml::table& t, const char* table, const char* key, std::string& into,
                 std::uint32_t file_id, core::DiagnosticSink& diags) {
  const toml::node* n = t.get(key);
  if (n == nullptr) return true;
  if (auto v = n->value<std::string>()) {
    into = *v;
    return true;
  }
  fail(diags, file_id, n->source(), fmt::format("{}.{} must be a string", table, key));
  return false;
}

bool read_mtconnect(const toml::table& t, MtconnectConfig& c, std::uint32_t file_id,
                    core::DiagnosticSink& diags) {
  c.enabled = true;
  bool ok = read_string(t, "mtconnect", "listen", c.listen, file_id, diags);
  if (const toml::node* n = t.get("heartbeat_ms")) {
    const auto v = n->value<std::int64_t>();
    if (v && *v >= 1000 && *v <= 600000) {
      c.heartbeat_ms = static_cast<std::uint32_t>(*v);
    } else {
      fail(diags, file_id, n->source(),
           "mtconnect.heartbeat_ms must be a count of milliseconds, 1000 to 600000");
      ok = false;
    }
  }
  return ok;
}

// A path key of [mqtt]: a string, not empty (whether it can be read is
// checked when the server starts).
bool read_path(const toml::table& t, const char* key, std::string& into, std::uint32_t file_id,
               core::DiagnosticSink& diags) {
  if (!read_string(t, "mqtt", key, into, file_id, diags)) return false;
  if (t.get(key) == nullptr || !into.empty()) return true;
  fail(diags, file_id, t.get(key)->source(), fmt::format("mqtt.{} must be a file's path", key));
  return false;
}

// The TLS keys against the URL's scheme: mqtts:// needs the CA, mqtt:// takes none.
bool check_tls_keys(const toml::table& t, const MqttConfig& c, std::uint32_t file_id,
                    core::DiagnosticSink& diags) {
  if (!c.tls) {
    for (const char* key : {"ca_file", "cert_file", "key_file"}) {
      if (const toml::node* n = t.get(key)) {
        fail(diags, file_id, n->source(),
             fmt::format("mqtt.{} is for TLS, but mqtt.url `{}` is plain mqtt:// (not encrypted): "
                         "write mqtts://host:8883 to use it, or remove the key",
                         key, c.url));
        return false;
      }
    }
    return true;
  }
  if (c.ca_file.empty()) {
    fail(diags, file_id, t.get("url")->source(),
         "mqtts:// needs mqtt.ca_file: the CA (PEM) that signed the broker's certificate, which "
         "is verified with its host name");
    return false;
  }
  if (c.cert_file.empty() != c.key_file.empty()) {
    fail(diags, file_id, t.source(),
         "mqtt.cert_file and mqtt.key_file go together: give both for a client certificate, or "
         "neither");
    return false;
  }
  return true;
}

// The broker's user: a password is only read from a file.
bool check_login_keys(const toml::table& t, const MqttConfig& c, std::uint32_t file_id,
                      core::DiagnosticSink& diags) {
  if (const toml::node* n = t.get("password")) {
    fail(diags, file_id, n->source(),
         "mqtt.password is refused: the configuration is often readable by everyone or kept in "
         "git; put the password on the first line of a file only the server reads and give "
         "mqtt.password_file");
    return false;
  }
  if (!c.password_file.empty() && c.username.empty()) {
    fail(diags, file_id, t.get("password_file")->source(),
         "mqtt.password_file needs mqtt.username: the broker's user the password is for");
    return false;
  }
  if (const toml::node* n = t.get("username"); n != nullptr && c.username.empty()) {
    fail(diags, file_id, n->source(), "mqtt.username must not be empty");
    return false;
  }
  return true;
}

bool read_mqtt(const toml::table& t, MqttConfig& c, std::uint32_t file_id,
               core::DiagnosticSink& diags) {
  c.enabled = true;
  bool ok = read_string(t, "mqtt", "url", c.url, file_id, diags);
  ok = read_string(t, "mqtt", "prefix", c.prefix, file_id, diags) && ok;
  ok = read_string(t, "mqtt", "client_id", c.client_id, file_id, diags) && ok;
  ok = read_string(t, "mqtt", "username", c.username, file_id, diags) && ok;
  for (const auto& [key, into] :
       {std::pair{"ca_file", &c.ca_file}, std::pair{"cert_file", &c.cert_file},
        std::pair{"key_file", &c.key_file}, std::pair{"password_file", &c.password_file}})
    ok = read_path(t, key, *into, file_id, diags) && ok;
  if (ok && !parse_mqtt_url(c.url, c)) {
    fail(diags, file_id, t.get("url")->source(),
         fmt::format("mqtt.url `{}` is not mqtt://host[:port] or mqtts://host[:port]", c.url));
    ok = false;
  }
  ok = ok && check_tls_keys(t, c, file_id, diags);
  ok = check_login_keys(t, c, file_id, diags) && ok;
  if (ok && (c.prefix.empty() || c.prefix.find_first_of("+#") != std::string::npos)) {
    fail(diags, file_id, t.get("prefix")->source(),
         "mqtt.prefix must be a topic level, not empty, without + or #");
    ok = false;
  }
  return ok;
}

}  // namespace

bool parse_mqtt_url(std::string_view url, MqttConfig& into) {
  const bool tls = url.starts_with("mqtts://");
  if (!tls && !url.starts_with("mqtt://")) return false;
  std::string_view rest = url.substr(tls ? 8 : 7);
  if (!rest.empty() && rest.back() == '/') rest.remove_suffix(1);
  std::string_view host = rest;
  unsigned port = tls ? 8883 : 1883;
  if (const std::size_t colon = rest.rfind(':');
      colon != std::string_view::npos && rest.find(']', colon) == std::string_view::npos) {
    host = rest.substr(0, colon);
    const std::string_view p = rest.substr(colon + 1);
    const auto [end, ec] = std::from_chars(p.data(), p.data() + p.size(), port);
    if (ec != std::errc() || end != p.data() + p.size() || port == 0 || port > 65535) return false;
  }
  if (host.size() > 2 && host.front() == '[' && host.back() == ']')
    host = host.substr(1, host.size() - 2);
  if (host.empty() || host.find_first_of("/@ ") != std::string_view::npos) return false;
  into.host = std::string(host);
  into.tls = tls;
  into.port = static_cast<std::uint16_t>(port);
  return true;
}

bool read_data_tables(const toml::table& root, MtconnectConfig& mtconnect, MqttConfig& mqtt,
                      std::uint32_t file_id, core::DiagnosticSink& diags) {
  bool ok = true;
  if (const toml::table* t = root["mtconnect"].as_table())
    ok = read_mtconnect(*t, mtconnect, file_id, diags);
  if (const toml::table* t = root["mqtt"].as_table())
    ok = read_mqtt(*t, mqtt, file_id, diags) && ok;
  return ok;
}

}  // namespace usina::dnc
