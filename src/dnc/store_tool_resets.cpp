#include "dnc/store_tool_resets.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dnc/store_audit.hpp"
#include "dnc/store_names.hpp"

namespace usina::dnc {

StoreResult<ToolReset> reset_tool(Store& store, const Actor& actor, std::string_view machine,
                                  std::int64_t tool, std::string_view reason) {
  if (tool < 0 || tool > kMaxToolNumber) {
    return store_error(StoreErrorKind::Invalid,
                       fmt::format("tool {} is no tool number: 0 to {}", tool, kMaxToolNumber));
  }
  if (auto ok = check_text("reason", reason, kMaxReasonBytes); !ok)
    return tl::unexpected(ok.error());
  ToolReset reset{tool, store.now_us(), actor.user, std::string(reason)};
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  auto r = store.db().query(
      "INSERT INTO tool_resets (machine, tool, at, by_user, reason) VALUES ($1, $2, $3, $4, $5)",
      {machine, tool, reset.at_us, std::string_view(reset.by), reason});
  if (!r) return tl::unexpected(r.error());
  const nlohmann::json detail = {{"machine", machine}, {"tool", tool}};
  const AuditRecord record{"tool.reset", fmt::format("{}/T{}", machine, tool), std::string(reason),
                           detail.dump()};
  if (auto a = append_audit(store, actor, record); !a) return tl::unexpected(a.error());
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  return reset;
}

StoreResult<std::map<std::int64_t, ToolReset>> last_tool_resets(Store& store,
                                                                std::string_view machine,
                                                                std::int64_t up_to_us) {
  // Oldest first: a later reset of a tool replaces the one before.
  auto rows = store.db().query(
      "SELECT tool, at, by_user, reason FROM tool_resets WHERE machine = $1 AND at <= $2 "
      "ORDER BY at, id",
      {machine, up_to_us});
  if (!rows) return tl::unexpected(rows.error());
  std::map<std::int64_t, ToolReset> out;
  for (const SqlRow& row : *rows) {
    const std::int64_t tool = row.integer(0);
    out[tool] = ToolReset{tool, row.integer(1), row.text(2), row.text(3)};
  }
  return out;
}

}  // namespace usina::dnc
