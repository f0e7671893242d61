// The HTTP vocabulary of usina's API (docs/dnc-server.md): Beast's request
// and response with string bodies, JSON answers, errors as
// `{"error": message}` with their status, the path split into segments and
// the query string into its parameters.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <boost/beast/http.hpp>
#include <nlohmann/json.hpp>

#include "dnc/store_error.hpp"

namespace usina::dnc {

namespace http = boost::beast::http;
using HttpRequest = http::request<http::string_body>;
using HttpResponse = http::response<http::string_body>;

// A body written after its head, piece by piece, so that an answer of any
// size holds one piece in memory (GET /api/export). The head carries the
// Content-Length of the whole body. `next` gives the following piece: empty
// at the end, nothing when the body cannot go on (the connection is then
// closed short of its length, which the client sees as a cut transfer).
struct StreamedBody {
  std::function<std::optional<std::string>()> next;
};

HttpResponse json_response(const HttpRequest& req, http::status status, const nlohmann::json& body);
HttpResponse error_response(const HttpRequest& req, http::status status, std::string_view message);

// The status a store error answers with (NotFound 404, Invalid 400,
// TooLarge 413, Refused and Conflict 409, Damaged and Backend 500).
http::status status_of(const StoreError& e);

struct Target {
  std::vector<std::string> segments;  // "/api/programs/O1" -> api, programs, O1 (decoded)
  std::map<std::string, std::string, std::less<>> query;
};

// Nothing when the target is malformed (a bad %-escape, a NUL, an empty
// segment or a dot segment: names are never paths).
std::optional<Target> parse_target(std::string_view target);

// The bearer token of the Authorization header, empty when there is none.
std::string bearer_token(const HttpRequest& req);

}  // namespace usina::dnc
