#include "dnc/store_machines.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dnc/store_audit.hpp"
#include "dnc/store_names.hpp"

namespace usina::dnc {
namespace {

constexpr std::string_view kColumns =
    "name, settings, created_at, created_by, changed_at, retired_at, retired_by, retire_reason";

StoredMachine row_machine(const SqlRow& row) {
  return StoredMachine{row.text(0),    row.text(1),    row.integer(2), row.text(3),
                       row.integer(4), row.integer(5), row.text(6),    row.text(7)};
}

StoreResult<std::optional<StoredMachine>> find_stored(Store& store, std::string_view name) {
  auto rows =
      store.db().query(fmt::format("SELECT {} FROM machines WHERE name = $1", kColumns), {name});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return std::nullopt;
  return row_machine(rows->front());
}

// The machine in service, in a write transaction already begun.
StoreResult<StoredMachine> in_service(Store& store, std::string_view name) {
  auto found = find_stored(store, name);
  if (!found) return tl::unexpected(found.error());
  if (!*found)
    return store_error(StoreErrorKind::NotFound,
                       fmt::format("no machine {} was added through the API", name));
  if ((*found)->retired_at_us != 0)
    return store_error(StoreErrorKind::Refused, fmt::format("machine {} is retired", name));
  return std::move(**found);
}

StoreResult<void> audit(Store& store, const Actor& actor, std::string_view action,
                        std::string_view name, std::string_view reason, std::string detail) {
  const AuditRecord record{std::string(action), std::string(name), std::string(reason),
                           std::move(detail)};
  if (auto a = append_audit(store, actor, record); !a) return tl::unexpected(a.error());
  return {};
}

}  // namespace

StoreResult<StoredMachine> add_machine(Store& store, const Actor& actor, std::string_view name,
                                       std::string_view settings, std::string_view reason) {
  if (auto ok = check_name("machine", name); !ok) return tl::unexpected(ok.error());
  if (auto ok = check_text("reason", reason, kMaxReasonBytes); !ok)
    return tl::unexpected(ok.error());
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  auto found = find_stored(store, name);
  if (!found) return tl::unexpected(found.error());
  if (*found)
    return store_error(StoreErrorKind::Conflict,
                       fmt::format("a machine named {} was added before{}; give another name", name,
                                   (*found)->retired_at_us != 0 ? " and retired" : ""));
  StoredMachine m;
  m.name = std::string(name);
  m.settings = std::string(settings);
  m.created_at_us = m.changed_at_us = store.now_us();
  m.created_by = actor.user;
  auto r = store.db().query(
      "INSERT INTO machines (name, settings, created_at, created_by, changed_at) "
      "VALUES ($1, $2, $3, $4, $5)",
      {name, settings, m.created_at_us, std::string_view(actor.user), m.changed_at_us});
  if (!r) return tl::unexpected(r.error());
  if (auto a = audit(store, actor, "machine.add", name, reason, std::string(settings)); !a)
    return tl::unexpected(a.error());
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  return m;
}

StoreResult<StoredMachine> change_machine(Store& store, const Actor& actor, std::string_view name,
                                          std::string_view settings, std::string_view changed,
                                          std::string_view reason) {
  if (auto ok = check_text("reason", reason, kMaxReasonBytes); !ok)
    return tl::unexpected(ok.error());
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  auto m = in_service(store, name);
  if (!m) return tl::unexpected(m.error());
  m->settings = std::string(settings);
  m->changed_at_us = store.now_us();
  auto r = store.db().query("UPDATE machines SET settings = $1, changed_at = $2 WHERE name = $3",
                            {settings, m->changed_at_us, name});
  if (!r) return tl::unexpected(r.error());
  if (auto a = audit(store, actor, "machine.change", name, reason, std::string(changed)); !a)
    return tl::unexpected(a.error());
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  return m;
}

StoreResult<StoredMachine> retire_machine(Store& store, const Actor& actor, std::string_view name,
                                          std::string_view reason) {
  if (auto ok = check_text("reason", reason, kMaxReasonBytes); !ok)
    return tl::unexpected(ok.error());
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  auto m = in_service(store, name);
  if (!m) return tl::unexpected(m.error());
  m->retired_at_us = store.now_us();
  m->retired_by = actor.user;
  m->retire_reason = std::string(reason);
  auto r = store.db().query(
      "UPDATE machines SET retired_at = $1, retired_by = $2, retire_reason = $3 WHERE name = $4",
      {m->retired_at_us, std::string_view(actor.user), reason, name});
  if (!r) return tl::unexpected(r.error());
  if (auto a = audit(store, actor, "machine.retire", name, reason, "{}"); !a)
    return tl::unexpected(a.error());
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  return m;
}

StoreResult<std::vector<StoredMachine>> stored_machines(Store& store) {
  auto rows = store.db().query(fmt::format("SELECT {} FROM machines ORDER BY name", kColumns));
  if (!rows) return tl::unexpected(rows.error());
  std::vector<StoredMachine> out;
  for (const SqlRow& row : *rows)
    out.push_back(row_machine(row));
  return out;
}

}  // namespace usina::dnc
