// A real HTTP client for the server's tests (Beast, synchronous, one
// connection a request): what a shop's script would do with curl.
#pragma once

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

  nlohmann::json json() const { return nlohmann::json::parse(body, nullptr, false); }
};

class ApiClient {
 public:
  explicit ApiClient(unsigned short port) : port_(port) {}

  Reply call(bhttp::verb method, const std::string& target, const std::string& body = "",
             const std::string& token = "") const {
    boost::asio::io_context io;
    beast::tcp_stream stream(io);
    stream.connect(
        boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), port_));
    bhttp::request<bhttp::string_body> req{method, target, 11};
    req.set(bhttp::field::host, "127.0.0.1");
    if (!token.empty()) req.set(bhttp::field::authorization, "Bearer " + token);
    if (!body.empty()) req.set(bhttp::field::content_type, "application/json");
    req.body() = body;
    req.prepare_payload();
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
    beast::error_code ignored;
    stream.socket().shutdown(boost::asio::ip::tcp::socket::shutdown_both, ignored);
    return r;
  }

  Reply get(const std::string& target, const std::string& token = "") const {
    return call(bhttp::verb::get, target, "", token);
  }

  Reply post(const std::string& target, const nlohmann::json& body,
             const std::string& token = "") const {
    return call(bhttp::verb::post, target, body.dump(), token);
  }

  // The token of a login, empty when it failed.
  std::string log_in(const std::string& user, const std::string& password) const {
    const Reply r = post("/api/login", {{"user", user}, {"password", password}});
    const auto j = r.json();
    return r.status == 200 && j.contains("token") ? j["token"].get<std::string>() : "";
  }

  unsigned short port() const { return port_; }

 private:
  unsigned short port_;
};

}  // namespace usina::test
