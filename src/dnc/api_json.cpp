#include "dnc/api_json.hpp"

#include <fmt/format.h>

namespace usina::dnc {

tl::expected<nlohmann::json, std::string> json_body(const HttpRequest& req) {
  nlohmann::json body = nlohmann::json::parse(req.body(), nullptr, false);
  if (body.is_discarded()) return tl::unexpected(std::string("the body is not valid JSON"));
  if (!body.is_object()) return tl::unexpected(std::string("the body must be a JSON object"));
  return body;
}

tl::expected<std::optional<std::string>, std::string> string_field(const nlohmann::json& body,
                                                                   std::string_view key,
                                                                   bool required) {
  const auto it = body.find(key);
  if (it == body.end() || it->is_null()) {
    if (required) return tl::unexpected(fmt::format("the field \"{}\" is missing", key));
    return std::optional<std::string>();
  }
  if (!it->is_string())
    return tl::unexpected(fmt::format("the field \"{}\" must be a string", key));
  return std::optional<std::string>(it->get<std::string>());
}

tl::expected<std::optional<std::uint64_t>, std::string> count_field(const nlohmann::json& body,
                                                                    std::string_view key) {
  const auto it = body.find(key);
  if (it == body.end() || it->is_null()) return std::optional<std::uint64_t>();
  if (!it->is_number_unsigned())
    return tl::unexpected(fmt::format("the field \"{}\" must be a whole number, 0 or more", key));
  return std::optional<std::uint64_t>(it->get<std::uint64_t>());
}

nlohmann::json revision_json(const Revision& r) {
  nlohmann::json checks = nlohmann::json::parse(r.checks_json, nullptr, false);
  if (checks.is_discarded()) checks = nullptr;
  return {{"revision", r.hash},
          {"state", state_name(r.state)},
          {"size", r.size},
          {"author", r.author},
          {"created_at_us", r.created_at_us},
          {"reason", r.reason},
          {"dialect", r.dialect},
          {"state_at_us", r.state_at_us},
          {"check_ok", r.check_blocking == 0},
          {"check_blocking", r.check_blocking},
          {"checks", std::move(checks)}};
}

nlohmann::json audit_json(const AuditEntry& e) {
  return {{"seq", e.seq},       {"at_us", e.at_us},     {"actor", e.actor},
          {"action", e.action}, {"subject", e.subject}, {"reason", e.reason},
          {"origin", e.origin}, {"detail", e.detail},   {"prev_hash", e.prev_hash},
          {"hash", e.hash}};
}

}  // namespace usina::dnc
