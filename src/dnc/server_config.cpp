#include "dnc/server_config.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dnc/config_report.hpp"
#include "dnc/machine_config.hpp"
#include "dnc/tool_life_config.hpp"

namespace usina::dnc {
namespace {

// A byte count of [server] max_upload or [web] max_file_bytes: at least 1 KiB;
// at most 1 GiB, as a request body or a served file is held in memory (a
// count of 2^63 would let anyone's upload exhaust it).
constexpr std::int64_t kMinByteLimit = 1024;
constexpr std::int64_t kMaxByteLimit = std::int64_t{1} << 30;

// A login lasts a minute at least (shorter, every session has ended before
// its first request) and 30 days at most.
constexpr double kMinSessionHours = 1.0 / 60.0;
constexpr double kMaxSessionHours = 24.0 * 30;

bool byte_limit_ok(const std::optional<std::int64_t>& v) {
  return v && *v >= kMinByteLimit && *v <= kMaxByteLimit;
}

void fail(core::DiagnosticSink& diags, std::uint32_t file_id, const toml::source_region& at,
          std::string message) {
  config_error(diags, file_id, at, std::move(message));
}

// The tables of the file and their keys ([[machine]]'s are machine_config's).
constexpr std::array<std::string_view, 6> kTables{"machine",   "server", "web",
                                                  "mtconnect", "mqtt",   "calendar"};
constexpr std::array<std::string_view, 5> kServerKeys{"listen", "max_upload", "session_hours",
                                                      "tls_cert", "tls_key"};
constexpr std::array<std::string_view, 2> kWebKeys{"root", "max_file_bytes"};
constexpr std::array<std::string_view, 2> kMtconnectKeys{"listen", "heartbeat_ms"};
// `password` is known so that it is refused with a pointer to password_file.
constexpr std::array<std::string_view, 9> kMqttKeys{"url",      "prefix",    "client_id",
                                                    "ca_file",  "cert_file", "key_file",
                                                    "username", "password",  "password_file"};

std::span<const std::string_view> table_keys(std::string_view table) {
  if (table == "server") return kServerKeys;
  if (table == "web") return kWebKeys;
  if (table == "mtconnect") return kMtconnectKeys;
  if (table == "mqtt") return kMqttKeys;
  return {};
}

void unknown_key(core::DiagnosticSink& diags, std::uint32_t file_id, const toml::key& key,
                 std::string_view where, std::span<const std::string_view> keys) {
  config_unknown_key(diags, file_id, key, where, keys);
}

// A misspelt table or key was ignored without a word (`max_uplaod` left the
// limit at 64 MiB): each is a warning with the nearest name; a known table
// that is no table (`server = 5`) is an error.
bool check_tables(const toml::table& root, std::uint32_t file_id, core::DiagnosticSink& diags) {
  bool ok = true;
  for (auto&& [key, node] : root) {
    const std::string_view name = key.str();
    if (std::find(kTables.begin(), kTables.end(), name) == kTables.end()) {
      unknown_key(diags, file_id, key, "at the top of the configuration", kTables);
      continue;
    }
    if (name == "machine") continue;   // read_machine_links checks it
    if (name == "calendar") continue;  // read_calendars checks it
    const toml::table* t = node.as_table();
    if (t == nullptr) {
      fail(diags, file_id, node.source(),
           fmt::format("{} must be a table: write [{}]", name, name));
      ok = false;
      continue;
    }
    for (auto&& [sub, value] : *t) {
      (void)value;
      const auto keys = table_keys(name);
      if (std::find(keys.begin(), keys.end(), sub.str()) == keys.end())
        unknown_key(diags, file_id, sub, fmt::format("in [{}]", name), keys);
    }
  }
  return ok;
}

// The `[server]` table; false when a value is wrong.
bool read_server_table(const toml::table& root, ServerConfig& c, std::uint32_t file_id,
                       core::DiagnosticSink& diags) {
  const toml::table* t = root["server"].as_table();
  if (t == nullptr) return true;
  bool ok = true;
  if (const toml::node* n = t->get("listen")) {
    if (auto v = n->value<std::string>()) {
      c.listen = *v;
    } else {
      fail(diags, file_id, n->source(), "server.listen must be a string \"host:port\"");
      ok = false;
    }
  }
  if (const toml::node* n = t->get("max_upload")) {
    const auto v = n->value_exact<std::int64_t>();
    if (byte_limit_ok(v)) {
      c.max_upload = static_cast<std::uint64_t>(*v);
    } else {
      fail(diags, file_id, n->source(),
           fmt::format("server.max_upload must be a count of bytes from {} to {} (1 GiB)",
                       kMinByteLimit, kMaxByteLimit));
      ok = false;
    }
  }
  for (const auto& [key, into] :
       {std::pair{"tls_cert", &c.tls_cert}, std::pair{"tls_key", &c.tls_key}}) {
    const toml::node* n = t->get(key);
    if (n == nullptr) continue;
    const auto v = n->value<std::string>();
    if (v && !v->empty()) {
      *into = *v;
    } else {
      fail(diags, file_id, n->source(), fmt::format("server.{} must be a PEM file's path", key));
      ok = false;
    }
  }
  if (c.tls_cert.empty() != c.tls_key.empty()) {
    fail(diags, file_id, t->source(),
         "server.tls_cert and server.tls_key go together: give both, or neither for plain HTTP");
    ok = false;
  }
  if (const toml::node* n = t->get("session_hours")) {
    const auto v = n->value<double>();
    if (v && *v >= kMinSessionHours && *v <= kMaxSessionHours) {
      c.session_hours = *v;
    } else {
      fail(diags, file_id, n->source(),
           fmt::format("server.session_hours must be a number of hours from {:.4g} (a minute) to "
                       "{:g} (30 days)",
                       kMinSessionHours, kMaxSessionHours));
      ok = false;
    }
  }
  return ok;
}

// The `[web]` table; false when a value is wrong.
bool read_web_table(const toml::table& root, ServerConfig& c, std::uint32_t file_id,
                    core::DiagnosticSink& diags) {
  const toml::table* t = root["web"].as_table();
  if (t == nullptr) return true;
  bool ok = true;
  if (const toml::node* n = t->get("root")) {
    const auto v = n->value<std::string>();
    if (v && !v->empty()) {
      c.web_root = *v;
    } else {
      fail(diags, file_id, n->source(), "web.root must be the folder of the built page");
      ok = false;
    }
  }
  if (const toml::node* n = t->get("max_file_bytes")) {
    const auto v = n->value_exact<std::int64_t>();
    if (byte_limit_ok(v)) {
      c.web_max_file_bytes = static_cast<std::uint64_t>(*v);
    } else {
      fail(diags, file_id, n->source(),
           fmt::format("web.max_file_bytes must be a count of bytes from {} to {} (1 GiB)",
                       kMinByteLimit, kMaxByteLimit));
      ok = false;
    }
  }
  return ok;
}

// The machine's data patterns must be regular expressions (ECMAScript).
bool read_patterns_ok(const ServerMachine& m, const toml::table* t, std::uint32_t file_id,
                      core::DiagnosticSink& diags) {
  bool ok = true;
  for (const auto& [key, pattern] : {std::pair{"part_count_pattern", &m.part_count_pattern},
                                     std::pair{"cycle_time_pattern", &m.cycle_time_pattern}}) {
    if (std::string why = pattern_error(*pattern); !why.empty()) {
      const toml::node* n = t != nullptr ? t->get(key) : nullptr;
      fail(diags, file_id, n != nullptr ? n->source() : toml::source_region{},
           fmt::format("machine `{}`: {} is not a regular expression: {}", m.link.name, key, why));
      ok = false;
    }
  }
  return ok;
}

// `machine_class` of each [[machine]] (machine_config.cpp accepts the key).
bool read_machine_classes(const toml::table& root, ServerConfig& c, std::uint32_t file_id,
                          core::DiagnosticSink& diags) {
  const toml::array* list = root["machine"].as_array();
  if (list == nullptr) return true;
  bool ok = true;
  for (std::size_t i = 0; i < list->size() && i < c.machines.size(); ++i) {
    const toml::table* t = list->get(i)->as_table();
    ServerMachine& m = c.machines[i];
    for (const auto& [key, into] :
         {std::pair{"machine_class", &m.machine_class}, std::pair{"profile", &m.profile},
          std::pair{"part_count_pattern", &m.part_count_pattern},
          std::pair{"cycle_time_pattern", &m.cycle_time_pattern}}) {
      const toml::node* n = t != nullptr ? t->get(key) : nullptr;
      if (n == nullptr) continue;
      if (auto v = n->value<std::string>()) {
        *into = *v;
      } else {
        fail(diags, file_id, n->source(), fmt::format("{} must be a string", key));
        ok = false;
      }
    }
    if (!read_patterns_ok(m, t, file_id, diags)) ok = false;
    if (!c.machines[i].profile.empty() && c.machines[i].machine_class.empty()) {
      fail(diags, file_id, t->source(),
           fmt::format("machine `{}`: a profile belongs to a machine class; give machine_class",
                       c.machines[i].link.name));
      ok = false;
    }
  }
  return ok;
}

// [calendar], and each machine's own `calendar` table; a machine without
// one takes the server's.
bool read_calendars(const toml::table& root, ServerConfig& c, std::uint32_t file_id,
                    core::DiagnosticSink& diags) {
  bool ok = true;
  if (const toml::node* n = root.get("calendar")) {
    if (const toml::table* t = n->as_table()) {
      c.calendar = read_calendar(*t, "calendar", file_id, diags);
      if (c.calendar) c.calendar->source = "server";
      ok = c.calendar.has_value();
    } else {
      fail(diags, file_id, n->source(), "calendar must be a table: write [calendar]");
      ok = false;
    }
  }
  const toml::array* list = root["machine"].as_array();
  for (std::size_t i = 0; i < c.machines.size(); ++i) {
    ServerMachine& m = c.machines[i];
    const toml::table* t = list != nullptr ? list->get(i)->as_table() : nullptr;
    const toml::node* own = t != nullptr ? t->get("calendar") : nullptr;
    if (own == nullptr) {
      m.calendar = c.calendar;
      continue;
    }
    const toml::table* table = own->as_table();
    if (table == nullptr) {
      fail(diags, file_id, own->source(),
           fmt::format("machine `{}`: calendar must be a table: write [machine.calendar] "
                       "under its [[machine]]",
                       m.link.name));
      ok = false;
      continue;
    }
    m.calendar =
        read_calendar(*table, fmt::format("machine `{}` calendar", m.link.name), file_id, diags);
    if (m.calendar) m.calendar->source = "machine";
    ok = m.calendar.has_value() && ok;
  }
  return ok;
}

// Each machine's own `tool_life` table.
bool read_machine_tool_lives(const toml::table& root, ServerConfig& c, std::uint32_t file_id,
                             core::DiagnosticSink& diags) {
  bool ok = true;
  const toml::array* list = root["machine"].as_array();
  for (std::size_t i = 0; i < c.machines.size(); ++i) {
    ServerMachine& m = c.machines[i];
    const toml::table* t = list != nullptr ? list->get(i)->as_table() : nullptr;
    const toml::node* own = t != nullptr ? t->get("tool_life") : nullptr;
    if (own == nullptr) continue;
    const toml::table* table = own->as_table();
    if (table == nullptr) {
      fail(diags, file_id, own->source(),
           fmt::format("machine `{}`: tool_life must be a table: write [machine.tool_life] "
                       "under its [[machine]]",
                       m.link.name));
      ok = false;
      continue;
    }
    auto lives = read_tool_lives(*table, m.link.name, file_id, diags);
    if (lives) m.tool_life = std::move(*lives);
    ok = lives.has_value() && ok;
  }
  return ok;
}

std::optional<std::string> read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string pattern_error(const std::string& pattern) {
  if (pattern.size() > kMaxDataPatternLength) {
    return fmt::format("it is {} characters long; a pattern may have at most {}", pattern.size(),
                       kMaxDataPatternLength);
  }
  try {
    if (!pattern.empty()) std::regex(pattern, kDataPatternFlags);
  } catch (const std::regex_error& e) {
    return e.what();
  }
  return {};
}

bool load_profiles(ServerConfig& config, const std::string& base_dir, core::DiagnosticSink& diags) {
  std::map<std::string, std::string> files;  // class -> its profile's file
  for (const ServerMachine& m : config.machines) {
    if (m.profile.empty()) continue;
    const std::filesystem::path path = std::filesystem::path(base_dir) / m.profile;
    const auto [at, fresh] = files.emplace(m.machine_class, path.string());
    if (!fresh && at->second != path.string()) {
      fail(diags, 0, {},
           fmt::format("machine class `{}` has two profiles, {} and {}; give one", m.machine_class,
                       at->second, path.string()));
      return false;
    }
    if (!fresh) continue;
    const auto text = read_file(path);
    if (!text) {
      fail(diags, 0, {},
           fmt::format("cannot read the profile {} of machine `{}`", path.string(), m.link.name));
      return false;
    }
    auto profile = sim::read_machine_profile(*text, 0, diags);
    if (!profile) return false;
    config.profiles.emplace(m.machine_class, std::move(*profile));
  }
  return true;
}

std::optional<ServerConfig> read_server_config(std::string_view toml_text, std::uint32_t file_id,
                                               core::DiagnosticSink& diags) {
  auto links = read_machine_links(toml_text, file_id, diags);
  if (!links) return std::nullopt;
  ServerConfig c;
  for (LinkConfig& l : *links) {
    ServerMachine m;
    m.link = std::move(l);
    c.machines.push_back(std::move(m));
  }
  toml::table root;
  try {
    root = toml::parse(toml_text);
  } catch (const toml::parse_error&) {
    return std::nullopt;  // reported by read_machine_links
  }
  bool ok = check_tables(root, file_id, diags);
  ok = read_server_table(root, c, file_id, diags) && ok;
  ok = read_web_table(root, c, file_id, diags) && ok;
  ok = read_data_tables(root, c.mtconnect, c.mqtt, file_id, diags) && ok;
  ok = read_calendars(root, c, file_id, diags) && ok;
  ok = read_machine_tool_lives(root, c, file_id, diags) && ok;
  if (!read_machine_classes(root, c, file_id, diags) || !ok) return std::nullopt;
  return c;
}

}  // namespace usina::dnc
