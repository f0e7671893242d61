#include "dnc/api_http.hpp"

#include <boost/beast/version.hpp>

namespace usina::dnc {
namespace {

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// %-decoding; `+` is a space only in a query.
std::optional<std::string> decode(std::string_view s, bool query) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    if (c == '%') {
      if (i + 2 >= s.size()) return std::nullopt;
      const int hi = hex_digit(s[i + 1]);
      const int lo = hex_digit(s[i + 2]);
      if (hi < 0 || lo < 0) return std::nullopt;
      c = static_cast<char>(hi * 16 + lo);
      i += 2;
    } else if (c == '+' && query) {
      c = ' ';
    }
    if (c == '\0') return std::nullopt;
    out += c;
  }
  return out;
}

bool split_path(std::string_view path, std::vector<std::string>& out) {
  if (path.empty() || path.front() != '/') return false;
  path.remove_prefix(1);
  while (!path.empty()) {
    const std::size_t slash = path.find('/');
    auto part = decode(path.substr(0, slash), false);
    if (!part || part->empty() || *part == "." || *part == ".." ||
        part->find('/') != std::string::npos)
      return false;
    out.push_back(std::move(*part));
    if (slash == std::string_view::npos) break;
    path.remove_prefix(slash + 1);
    if (path.empty()) return false;  // a trailing slash
  }
  return true;
}

bool split_query(std::string_view q, std::map<std::string, std::string, std::less<>>& out) {
  while (!q.empty()) {
    const std::size_t amp = q.find('&');
    const std::string_view pair = q.substr(0, amp);
    const std::size_t eq = pair.find('=');
    auto key = decode(pair.substr(0, eq), true);
    auto value = decode(eq == std::string_view::npos ? "" : pair.substr(eq + 1), true);
    if (!key || !value) return false;
    if (!key->empty()) out[*key] = *value;
    if (amp == std::string_view::npos) break;
    q.remove_prefix(amp + 1);
  }
  return true;
}

}  // namespace

HttpResponse json_response(const HttpRequest& req, http::status status,
                           const nlohmann::json& body) {
  HttpResponse res{status, req.version()};
  res.set(http::field::server, "usina");
  res.set(http::field::content_type, "application/json");
  res.set(http::field::cache_control, "no-store");
  res.keep_alive(req.keep_alive());
  res.body() = body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  res.prepare_payload();
  return res;
}

HttpResponse error_response(const HttpRequest& req, http::status status, std::string_view message) {
  return json_response(req, status, {{"error", std::string(message)}});
}

http::status status_of(const StoreError& e) {
  switch (e.kind) {
  case StoreErrorKind::NotFound: return http::status::not_found;
  case StoreErrorKind::Invalid: return http::status::bad_request;
  case StoreErrorKind::TooLarge: return http::status::payload_too_large;
  case StoreErrorKind::Refused: return http::status::conflict;
  case StoreErrorKind::Conflict: return http::status::conflict;
  case StoreErrorKind::Damaged: return http::status::internal_server_error;
  case StoreErrorKind::Backend: return http::status::internal_server_error;
  }
  return http::status::internal_server_error;
}

std::optional<Target> parse_target(std::string_view target) {
  Target t;
  const std::size_t question = target.find('?');
  if (!split_path(target.substr(0, question), t.segments)) return std::nullopt;
  if (question != std::string_view::npos && !split_query(target.substr(question + 1), t.query))
    return std::nullopt;
  return t;
}

std::string bearer_token(const HttpRequest& req) {
  const auto it = req.find(http::field::authorization);
  if (it == req.end()) return {};
  const std::string_view value(it->value().data(), it->value().size());
  constexpr std::string_view kBearer = "Bearer ";
  if (value.size() <= kBearer.size() || value.substr(0, kBearer.size()) != kBearer) return {};
  return std::string(value.substr(kBearer.size()));
}

}  // namespace usina::dnc
