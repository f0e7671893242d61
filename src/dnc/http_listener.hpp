// The server's HTTP/1.1 side (Boost.Beast on the one event loop): accepts
// connections, reads requests within a body limit (past it: 413, with the
// rest of the upload drained so the client reads the answer), hands each to
// the API and writes its answer; a WebSocket upgrade is handed on whole.
// Slow clients are timed out; the count of connections is bounded.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

#include "dnc/api_http.hpp"

namespace boost::asio::ssl {
class context;
}

namespace usina::dnc {

struct HttpStream;  // http_stream.hpp

struct HttpHandlers {
  // Writes the answer of a request taken by `later` (on the loop, once).
  using Answer = std::function<void(HttpResponse)>;
  // A request answered later (its work done off the loop): true when it is
  // taken, and `answer` is then called once, on the loop. Empty, or false:
  // `request` answers it at once.
  std::function<bool(const HttpRequest&, const std::string& origin, Answer& answer)> later;
  // The answer to a request from `origin` (the client's address, "127.0.0.1").
  std::function<HttpResponse(const HttpRequest&, const std::string& origin)> request;
  // The streamed body of the answer `request` just gave, if it has one
  // (called right after it, on the loop); empty: no answer streams.
  std::function<std::optional<StreamedBody>()> take_stream;
  // A WebSocket upgrade: takes the stream (plain or TLS), or answers with an error.
  std::function<std::optional<HttpResponse>(HttpStream&, const HttpRequest&)> upgrade;
};

struct HttpLimits {
  std::uint64_t body_bytes = 64ull << 20;
  std::uint32_t header_bytes = 16 * 1024;
  std::chrono::seconds read_timeout{60};
  std::size_t connections = 512;
};

class HttpListener : public std::enable_shared_from_this<HttpListener> {
 public:
  HttpListener(boost::asio::io_context& io, HttpHandlers handlers, HttpLimits limits);

  // Binds and listens; an error message when it cannot.
  std::string listen(const boost::asio::ip::tcp::endpoint& at);

  // Every connection speaks TLS with `ctx` (http_tls.hpp); before start().
  void use_tls(std::shared_ptr<boost::asio::ssl::context> ctx) { tls_ = std::move(ctx); }

  boost::asio::ssl::context* tls() const { return tls_.get(); }

  void start();
  void stop();

  boost::asio::ip::tcp::endpoint local_endpoint() const;

  const HttpHandlers& handlers() const { return handlers_; }

  const HttpLimits& limits() const { return limits_; }

  std::size_t connections = 0;  // open now (sessions count themselves)

 private:
  void accept();

  boost::asio::ip::tcp::acceptor acceptor_;
  HttpHandlers handlers_;
  HttpLimits limits_;
  std::shared_ptr<boost::asio::ssl::context> tls_;  // null: plain HTTP
};

}  // namespace usina::dnc
