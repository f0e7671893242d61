// The byte stream under an HTTP connection: plain TCP, or TLS on TCP
// (`usina serve --tls-cert/--tls-key`, http_tls.hpp). A connection is one or
// the other for its whole life; the WebSocket of `GET /api/events` takes the
// stream over as it is, so WSS runs on the same TLS session as the upgrade.
#pragma once

#include <utility>
#include <variant>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl/context.hpp>
#include <boost/beast/core/stream_traits.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/ssl/ssl_stream.hpp>

namespace usina::dnc {

using PlainStream = boost::beast::tcp_stream;
using TlsStream = boost::beast::ssl_stream<boost::beast::tcp_stream>;

// A struct (not the variant itself) so that headers can name it without
// OpenSSL's: `struct HttpStream;`.
struct HttpStream {
  explicit HttpStream(boost::asio::ip::tcp::socket s)
      : v(std::in_place_type<PlainStream>, std::move(s)) {}

  HttpStream(boost::asio::ip::tcp::socket s, boost::asio::ssl::context& tls)
      : v(std::in_place_type<TlsStream>, std::move(s), tls) {}

  bool tls() const { return std::holds_alternative<TlsStream>(v); }

  std::variant<PlainStream, TlsStream> v;
};

// The TCP stream at the bottom (timeouts, the peer's address, closing).
inline boost::beast::tcp_stream& tcp_of(HttpStream& s) {
  return std::visit(
      [](auto& stream) -> boost::beast::tcp_stream& {
        return boost::beast::get_lowest_layer(stream);
      },
      s.v);
}

}  // namespace usina::dnc
