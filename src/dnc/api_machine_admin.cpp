// An admin's machines (docs/dnc-server.md, "Machines added from the
// page"): a machine added, its settings changed, a machine retired, each
// kept in the store with its audit entry (store_machines.hpp) and put to
// work at once (server_machine_admin.cpp). The machines of usina-serve.toml
// are the file's: the API reads them and changes none.
#include <algorithm>
#include <array>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"
#include "dnc/machine_settings.hpp"
#include "dnc/store_machines.hpp"

namespace usina::dnc {
namespace {

HttpResponse failure(const ApiCall& c, http::status status, const std::string& message) {
  return error_response(c.req, status, message);
}

HttpResponse store_failure(const ApiCall& c, const StoreError& e) {
  return error_response(c.req, status_of(e), e.message);
}

// The body's `reason` (optional unless `required`), taken out of it: the
// rest are the machine's settings.
tl::expected<std::string, std::string> take_reason(nlohmann::json& body, bool required) {
  auto reason = string_field(body, "reason", required);
  if (!reason) return tl::unexpected(reason.error());
  body.erase("reason");
  return reason->value_or("");
}

// A device a machine added here may open: a serial line or a pty, by its
// path and, when it is there, by the path it resolves to. Opening any other
// device has effects of its own (a watchdog starts when opened), so those
// are named in usina-serve.toml by whoever keeps the server's files.
constexpr std::array<std::string_view, 4> kSerialDevices{"/dev/tty", "/dev/pts/", "/dev/serial/",
                                                         "/dev/rfcomm"};

bool serial_path(std::string_view path) {
  if (path.find("/..") != std::string_view::npos || path.find("/./") != std::string_view::npos)
    return false;
  return std::any_of(kSerialDevices.begin(), kSerialDevices.end(),
                     [&](std::string_view d) { return path.starts_with(d); });
}

std::optional<std::string> device_refused(const ServerMachine& m) {
  const std::string& port = m.link.port;
  if (port.starts_with("tcp://") || port.starts_with("tcp-listen://")) return std::nullopt;
  std::error_code ec;
  const auto real = std::filesystem::canonical(port, ec);
  if (serial_path(port) && (ec || serial_path(real.string()))) return std::nullopt;
  return fmt::format(
      "port {}: a machine added here is on a serial device (/dev/tty*, /dev/pts/*, "
      "/dev/serial/*, /dev/rfcomm*) or tcp://host:port; name any other in usina-serve.toml",
      port);
}

// Another machine in service on the same port: two stations cannot share one.
std::optional<std::string> port_taken(ApiCall& c, const ServerMachine& m) {
  for (const auto& other : c.ctx.machines.all()) {
    if (other->config.link.name != m.link.name && other->config.link.port == m.link.port)
      return fmt::format("port {} is machine {}'s", m.link.port, other->config.link.name);
  }
  return std::nullopt;
}

// What changed from `before` to `after`: {"key": {"from", "to"}}.
nlohmann::json changes(const nlohmann::json& before, const nlohmann::json& after) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [key, to] : after.items()) {
    const auto from = before.find(key);
    if (from == before.end() || *from != to)
      out[key] = {{"from", from == before.end() ? nlohmann::json(nullptr) : *from}, {"to", to}};
  }
  return out;
}

StoreResult<StoredMachine> stored(Store& store, std::string_view name) {
  auto all = stored_machines(store);
  if (!all) return tl::unexpected(all.error());
  for (StoredMachine& m : *all) {
    if (m.name == name) return std::move(m);
  }
  return store_error(StoreErrorKind::NotFound, fmt::format("no machine {}", name));
}

nlohmann::json retired_json(const StoredMachine& m) {
  return {{"name", m.name},
          {"settings", nlohmann::json::parse(m.settings, nullptr, false)},
          {"created_at_us", m.created_at_us},
          {"created_by", m.created_by},
          {"retired_at_us", m.retired_at_us},
          {"retired_by", m.retired_by},
          {"retire_reason", m.retire_reason}};
}

}  // namespace

// The retired machines, for `GET /api/machines?retired=1`.
StoreResult<nlohmann::json> retired_machines(ApiCall& c) {
  auto all = stored_machines(c.ctx.store);
  if (!all) return tl::unexpected(all.error());
  nlohmann::json out = nlohmann::json::array();
  for (const StoredMachine& m : *all) {
    if (m.retired_at_us != 0) out.push_back(retired_json(m));
  }
  return out;
}

// POST /api/machines {the [[machine]] keys, "reason"?} (admin): 201 the machine.
HttpResponse api_add_machine(ApiCall& c) {
  auto body = json_body(c.req);
  if (!body) return failure(c, http::status::bad_request, body.error());
  auto reason = take_reason(*body, false);
  if (!reason) return failure(c, http::status::bad_request, reason.error());
  auto m = machine_from_settings(*body);
  if (!m) return failure(c, http::status::bad_request, m.error());
  if (auto refused = device_refused(*m)) return failure(c, http::status::bad_request, *refused);
  const std::string name = m->link.name;
  if (MachineRuntime* there = c.ctx.machines.find(name); there != nullptr)
    return failure(c, http::status::conflict, fmt::format("there is a machine {} already", name));
  if (auto taken = port_taken(c, *m)) return failure(c, http::status::conflict, *taken);
  auto added = add_machine(c.ctx.store, c.actor(), name, body->dump(), *reason);
  if (!added) return store_failure(c, added.error());
  m->from_store = true;
  MachineRuntime& runtime = c.ctx.machines.add(std::move(*m));
  c.ctx.events.publish("machine.added", {{"machine", name}, {"user", c.actor().user}});
  return json_response(c.req, http::status::created, machine_json(c, runtime));
}

// POST /api/machines/{machine} {keys to change (null: back to the default), "reason"?}
// (admin): the machine after the change; its port opened again.
HttpResponse api_change_machine(ApiCall& c) {
  MachineRuntime* runtime = c.ctx.machines.find(c.params[0]);
  if (runtime == nullptr)
    return failure(c, http::status::not_found, fmt::format("no machine {}", c.params[0]));
  auto body = json_body(c.req);
  if (!body) return failure(c, http::status::bad_request, body.error());
  auto reason = take_reason(*body, false);
  if (!reason) return failure(c, http::status::bad_request, reason.error());
  if (body->empty())
    return failure(c, http::status::bad_request, "nothing to change: give the keys to change");
  if (const auto n = body->find("name"); n != body->end() && *n != c.params[0])
    return failure(c, http::status::bad_request,
                   "a machine's name does not change (its jobs and records keep it); add a "
                   "machine of the new name and retire this one");
  if (!runtime->config.from_store)
    return failure(c, http::status::conflict,
                   fmt::format("{} is set in usina-serve.toml: change it there", c.params[0]));
  auto before = stored(c.ctx.store, c.params[0]);
  if (!before) return store_failure(c, before.error());
  const nlohmann::json old_settings = nlohmann::json::parse(before->settings, nullptr, false);
  nlohmann::json settings = old_settings;
  settings.merge_patch(*body);  // null removes a key: its default again
  auto m = machine_from_settings(settings);
  if (!m) return failure(c, http::status::bad_request, m.error());
  if (auto refused = device_refused(*m)) return failure(c, http::status::bad_request, *refused);
  const nlohmann::json changed = changes(machine_settings(runtime->config), machine_settings(*m));
  if (changed.empty()) return json_response(c.req, http::status::ok, machine_json(c, *runtime));
  if (auto ok = c.ctx.machines.may_change(*runtime); !ok) return store_failure(c, ok.error());
  if (auto taken = port_taken(c, *m)) return failure(c, http::status::conflict, *taken);
  auto done =
      change_machine(c.ctx.store, c.actor(), c.params[0], settings.dump(), changed.dump(), *reason);
  if (!done) return store_failure(c, done.error());
  m->from_store = true;
  c.ctx.machines.replace(*runtime, std::move(*m));
  c.ctx.events.publish("machine.changed", {{"machine", c.params[0]}, {"user", c.actor().user}});
  return json_response(c.req, http::status::ok, machine_json(c, *runtime));
}

// POST /api/machines/{machine}/retire {"reason"} (admin): its port closed,
// no longer listed; its history stays under its name.
HttpResponse api_retire_machine(ApiCall& c) {
  MachineRuntime* runtime = c.ctx.machines.find(c.params[0]);
  if (runtime == nullptr)
    return failure(c, http::status::not_found, fmt::format("no machine {}", c.params[0]));
  auto body = json_body(c.req);
  if (!body) return failure(c, http::status::bad_request, body.error());
  auto reason = take_reason(*body, true);
  if (!reason) return failure(c, http::status::bad_request, reason.error());
  if (reason->empty())
    return failure(c, http::status::bad_request, "give the reason the machine is retired");
  if (!runtime->config.from_store)
    return failure(c, http::status::conflict,
                   fmt::format("{} is set in usina-serve.toml: remove it there", c.params[0]));
  if (auto ok = c.ctx.machines.may_change(*runtime); !ok) return store_failure(c, ok.error());
  auto done = retire_machine(c.ctx.store, c.actor(), c.params[0], *reason);
  if (!done) return store_failure(c, done.error());
  c.ctx.machines.retire(*runtime);
  c.ctx.events.publish("machine.retired", {{"machine", c.params[0]}, {"user", c.actor().user}});
  return json_response(c.req, http::status::ok, retired_json(*done));
}

}  // namespace usina::dnc
