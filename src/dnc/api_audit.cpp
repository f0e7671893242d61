// The audit log, and whether its hash chain holds (`?verify=1`).
#include <charconv>

#include "dnc/api_json.hpp"
#include "dnc/api_router.hpp"

namespace usina::dnc {
namespace {

std::int64_t number_or(const Target& t, std::string_view key, std::int64_t fallback) {
  const auto it = t.query.find(key);
  if (it == t.query.end()) return fallback;
  std::int64_t v = 0;
  const auto [end, ec] =
      std::from_chars(it->second.data(), it->second.data() + it->second.size(), v);
  return ec == std::errc() && end == it->second.data() + it->second.size() && v >= 0 ? v : -1;
}

}  // namespace

HttpResponse api_audit(ApiCall& c) {
  const std::int64_t after = number_or(c.target, "after", 0);
  const std::int64_t limit = number_or(c.target, "limit", 1000);
  if (after < 0 || limit < 0 || limit > 100000) {
    return error_response(c.req, http::status::bad_request,
                          "after and limit must be whole numbers (limit at most 100000)");
  }
  auto entries = read_audit(c.ctx.store, after, static_cast<std::size_t>(limit));
  if (!entries) return error_response(c.req, status_of(entries.error()), entries.error().message);
  nlohmann::json out = {{"entries", nlohmann::json::array()}};
  for (const AuditEntry& e : *entries)
    out["entries"].push_back(audit_json(e));
  const auto verify = c.target.query.find("verify");
  if (verify != c.target.query.end() && verify->second == "1") {
    auto v = verify_audit(c.ctx.store);
    if (!v) return error_response(c.req, status_of(v.error()), v.error().message);
    out["verify"] = {{"ok", v->ok},
                     {"entries", v->entries},
                     {"head", v->head},
                     {"first_bad", v->first_bad},
                     {"problem", v->problem}};
    out["ok"] = v->ok;
  }
  return json_response(c.req, http::status::ok, out);
}

HttpResponse api_events_plain(ApiCall& c) {
  return error_response(c.req, http::status::upgrade_required,
                        "/api/events is a WebSocket: connect with an Upgrade: websocket request");
}

}  // namespace usina::dnc
