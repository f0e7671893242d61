#include "dnc/store_parts.hpp"

namespace usina::dnc {
namespace {

SqlValue optional_int(const std::optional<std::int64_t>& v) {
  return v ? SqlValue(*v) : SqlValue(std::monostate{});
}

std::optional<std::int64_t> optional_of(const SqlRow& r, std::size_t i) {
  return r.is_null(i) ? std::nullopt : std::optional<std::int64_t>(r.integer(i));
}

// The program and revision of the machine's last job that ran to its end:
// what the control runs when it prints a part.
StoreResult<std::pair<std::string, std::string>> last_program(Store& store,
                                                              std::string_view machine) {
  auto rows = store.db().query(
      "SELECT program, revision FROM jobs WHERE machine = $1 AND state = 'done' "
      "ORDER BY id DESC LIMIT 1",
      {machine});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return std::pair<std::string, std::string>{};
  return std::pair{rows->front().text(0), rows->front().text(1)};
}

}  // namespace

StoreResult<void> record_control_part(Store& store, ControlPart p) {
  if (p.program.empty()) {
    auto last = last_program(store, p.machine);
    if (!last) return tl::unexpected(last.error());
    p.program = last->first;
    p.revision = last->second;
  }
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return b;
  auto r = store.db().query(
      "INSERT INTO control_parts (machine, at, cycle_us, control_count, program, revision) "
      "VALUES ($1, $2, $3, $4, $5, $6)",
      {std::string_view(p.machine), p.at_us, optional_int(p.cycle_us),
       optional_int(p.control_count), std::string_view(p.program), std::string_view(p.revision)});
  if (!r) return tl::unexpected(r.error());
  return tx.commit();
}

StoreResult<void> set_last_control_cycle(Store& store, std::string_view machine,
                                         std::int64_t cycle_us) {
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return b;
  auto r = store.db().query(
      "UPDATE control_parts SET cycle_us = $2 WHERE id = "
      "(SELECT MAX(id) FROM control_parts WHERE machine = $1)",
      {machine, cycle_us});
  if (!r) return tl::unexpected(r.error());
  return tx.commit();
}

StoreResult<void> record_control_message(Store& store, std::string_view machine,
                                         std::string_view text, std::int64_t at_us) {
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return b;
  auto r = store.db().query(
      "INSERT INTO control_messages (machine, text, at) VALUES ($1, $2, $3) "
      "ON CONFLICT (machine) DO UPDATE SET text = excluded.text, at = excluded.at",
      {machine, text, at_us});
  if (!r) return tl::unexpected(r.error());
  return tx.commit();
}

StoreResult<ControlTotals> control_totals(Store& store, std::string_view machine) {
  ControlTotals t;
  auto count =
      store.db().query("SELECT COUNT(*), MAX(id) FROM control_parts WHERE machine = $1", {machine});
  if (!count) return tl::unexpected(count.error());
  t.parts = count->front().integer(0);
  if (t.parts > 0) {
    auto last = store.db().query("SELECT at, cycle_us FROM control_parts WHERE id = $1",
                                 {count->front().integer(1)});
    if (!last) return tl::unexpected(last.error());
    t.last_part_at_us = last->front().integer(0);
    t.last_cycle_us = optional_of(last->front(), 1);
    auto printed = store.db().query(
        "SELECT control_count FROM control_parts WHERE machine = $1 AND control_count IS NOT NULL "
        "ORDER BY id DESC LIMIT 1",
        {machine});
    if (!printed) return tl::unexpected(printed.error());
    if (!printed->empty()) t.control_count = printed->front().integer(0);
  }
  auto message =
      store.db().query("SELECT text FROM control_messages WHERE machine = $1", {machine});
  if (!message) return tl::unexpected(message.error());
  if (!message->empty()) t.last_message = message->front().text(0);
  return t;
}

StoreResult<std::vector<ControlPart>> control_parts(Store& store, std::string_view machine,
                                                    std::int64_t from_us, std::int64_t to_us) {
  auto rows = store.db().query(
      "SELECT at, cycle_us, control_count, program, revision FROM control_parts "
      "WHERE machine = $1 AND at >= $2 AND at < $3 ORDER BY id",
      {machine, from_us, to_us});
  if (!rows) return tl::unexpected(rows.error());
  std::vector<ControlPart> out;
  for (const SqlRow& r : *rows) {
    out.push_back(ControlPart{std::string(machine), r.integer(0), optional_of(r, 1),
                              optional_of(r, 2), r.text(3), r.text(4)});
  }
  return out;
}

}  // namespace usina::dnc
