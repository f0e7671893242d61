// A real HTTP client for the server's tests (Beast, synchronous, one
// connection a request): what a shop's script would do with curl.
#pragma once

#include <cctype>
#include <map>
#include <string>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

namespace usina::test {

namespace beast = boost::beast;
namespace bhttp = boost::beast::http;

struct Reply {
  int status = 0;
  std::string body;
  std::string retry_after;
  std::map<std::string, std::string> headers;  // by lower-case name

  // The header's value, empty when there is none; `name` in lower case.
  std::string header(const std::string& name) const {
    const auto it = headers.find(name);
    return it == headers.end() ? "" : it->second;
  }

  nlohmann::json json() const { return nlohmann::json::parse(body, nullptr, false); }
};

// The request of a call: a JSON body, a bearer token when given.
inline bhttp::request<bhttp::string_body> api_request(bhttp::verb method, const std::string& target,
                                                      const std::string& body,
                                                      const std::string& token) {
  bhttp::request<bhttp::string_body> req{method, target, 11};
  req.set(bhttp::field::host, "127.0.0.1");
  if (!token.empty()) req.set(bhttp::field::authorization, "Bearer " + token);
  if (!body.empty()) req.set(bhttp::field::content_type, "application/json");
  req.body() = body;
  req.prepare_payload();
  return req;
}

// Writes `req` on `stream` (plain or TLS) and reads the reply.
template <typename Stream>
Reply round_trip(Stream& stream, const bhttp::request<bhttp::string_body>& req) {
  bhttp::write(stream, req);
  beast::flat_buffer buffer;
  bhttp::response_parser<bhttp::string_body> parser;
  parser.body_limit(1ull << 30);
  bhttp::read(stream, buffer, parser);
  Reply r;
  r.status = static_cast<int>(parser.get().result_int());
  r.body = parser.get().body();
  if (auto it = parser.get().find(bhttp::field::retry_after); it != parser.get().end())
    r.retry_after = std::string(it->value());
  for (const auto& field : parser.get()) {
    std::string name(field.name_string());
    for (char& ch : name)
      ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    r.headers[name] = std::string(field.value());
  }
  return r;
}

// get, post and log_in of a client whose `call` makes one request.
template <typename Client>
class ApiVerbs {
 public:
  Reply get(const std::string& target, const std::string& token = "") const {
    return client().call(bhttp::verb::get, target, "", token);
  }

  Reply post(const std::string& target, const nlohmann::json& body,
             const std::string& token = "") const {
    return client().call(bhttp::verb::post, target, body.dump(), token);
  }

  // The token of a login, empty when it failed.
  std::string log_in(const std::string& user, const std::string& password) const {
    const Reply r = post("/api/login", {{"user", user}, {"password", password}});
    const auto j = r.json();
    return r.status == 200 && j.contains("token") ? j["token"].get<std::string>() : "";
  }

 private:
  const Client& client() const { return static_cast<const Client&>(*this); }
};

class ApiClient : public ApiVerbs<ApiClient> {
 public:
  explicit ApiClient(unsigned short port) : port_(port) {}

  Reply call(bhttp::verb method, const std::string& target, const std::string& body = "",
             const std::string& token = "") const {
    boost::asio::io_context io;
    beast::tcp_stream stream(io);
    stream.connect(
        boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), port_));
    const Reply r = round_trip(stream, api_request(method, target, body, token));
    beast::error_code ignored;
    stream.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_both, ignored);
    return r;
  }

  unsigned short port() const { return port_; }

 private:
  unsigned short port_;
};

}  // namespace usina::test
