#include "dnc/server_config.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include "dnc/machine_config.hpp"

namespace usina::dnc {
namespace {

void fail(core::DiagnosticSink& diags, std::uint32_t file_id, const toml::source_region& at,
          std::string message) {
  core::Diagnostic d;
  d.code = core::Code::DncConfig;
  d.severity = core::Severity::Error;
  d.loc.file = file_id;
  d.loc.line = at.begin.line;
  d.loc.col = at.begin.column;
  d.message = std::move(message);
  diags.report(std::move(d));
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
    const auto v = n->value<std::int64_t>();
    if (v && *v >= 1024) {
      c.max_upload = static_cast<std::uint64_t>(*v);
    } else {
      fail(diags, file_id, n->source(), "server.max_upload must be a count of bytes, 1024 or more");
      ok = false;
    }
  }
  if (const toml::node* n = t->get("session_hours")) {
    const auto v = n->value<double>();
    if (v && *v > 0.0 && *v <= 24.0 * 30) {
      c.session_hours = *v;
    } else {
      fail(diags, file_id, n->source(), "server.session_hours must be a number of hours, 0 to 720");
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
    const toml::node* n = t != nullptr ? t->get("machine_class") : nullptr;
    if (n == nullptr) continue;
    if (auto v = n->value<std::string>()) {
      c.machines[i].machine_class = *v;
    } else {
      fail(diags, file_id, n->source(), "machine_class must be a string");
      ok = false;
    }
  }
  return ok;
}

}  // namespace

std::optional<ServerConfig> read_server_config(std::string_view toml_text, std::uint32_t file_id,
                                               core::DiagnosticSink& diags) {
  auto links = read_machine_links(toml_text, file_id, diags);
  if (!links) return std::nullopt;
  ServerConfig c;
  for (LinkConfig& l : *links)
    c.machines.push_back(ServerMachine{std::move(l), {}});
  toml::table root;
  try {
    root = toml::parse(toml_text);
  } catch (const toml::parse_error&) {
    return std::nullopt;  // reported by read_machine_links
  }
  const bool ok = read_server_table(root, c, file_id, diags);
  if (!read_machine_classes(root, c, file_id, diags) || !ok) return std::nullopt;
  return c;
}

}  // namespace usina::dnc
