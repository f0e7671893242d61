// Reading a request's JSON body and writing the store's records as JSON.
// A body that is not a JSON object, a missing field, a field of the wrong
// type: each is a message for a 400 answer.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>
#include <tl/expected.hpp>

#include "dnc/api_http.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/store_sheets.hpp"

namespace usina::dnc {

tl::expected<nlohmann::json, std::string> json_body(const HttpRequest& req);
// The string field `key`: its value, nullopt when absent and not `required`,
// or a message.
tl::expected<std::optional<std::string>, std::string> string_field(const nlohmann::json& body,
                                                                   std::string_view key,
                                                                   bool required);
tl::expected<std::optional<std::uint64_t>, std::string> count_field(const nlohmann::json& body,
                                                                    std::string_view key);

nlohmann::json revision_json(const Revision& r);
nlohmann::json audit_json(const AuditEntry& e);
// api_sheets.cpp
nlohmann::json sheet_json(const Sheet& s);

}  // namespace usina::dnc
