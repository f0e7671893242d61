#include "dnc/http_session.hpp"

#include <boost/asio/ssl/stream_base.hpp>
#include <boost/beast/websocket/rfc6455.hpp>
#include <fmt/format.h>

namespace usina::dnc {

namespace beast = boost::beast;
namespace asio = boost::asio;

namespace {

std::string origin_of(const asio::ip::tcp::socket& s) {
  boost::system::error_code ec;
  const auto peer = s.remote_endpoint(ec);
  if (ec) return "unknown";
  // The address alone: the login limits count failures per origin, and a
  // client gets a new port with each connection.
  return peer.address().to_string();
}

// What a request that could not be read answers: 413 past the body limit,
// 431 past the header limit, 400 with the parser's reason for the rest.
http::status status_of_read_error(const beast::error_code& ec) {
  if (ec == http::error::body_limit) return http::status::payload_too_large;
  if (ec == http::error::header_limit) return http::status::request_header_fields_too_large;
  return http::status::bad_request;
}

}  // namespace

HttpSession::HttpSession(asio::ip::tcp::socket socket, std::shared_ptr<HttpListener> listener)
    : stream_(listener->tls() != nullptr ? HttpStream(std::move(socket), *listener->tls())
                                         : HttpStream(std::move(socket))),
      listener_(std::move(listener)) {
  origin_ = origin_of(tcp_of(stream_).socket());
  ++listener_->connections;
}

HttpSession::~HttpSession() {
  --listener_->connections;
}

void HttpSession::start() {
  if (stream_.tls()) return handshake();
  read();
}

// A client that sends no TLS ClientHello (plain HTTP on the HTTPS port) fails
// here and is closed without an answer: nothing is ever said in the clear.
void HttpSession::handshake() {
  tcp_of(stream_).expires_after(listener_->limits().read_timeout);
  std::get<TlsStream>(stream_.v).async_handshake(
      asio::ssl::stream_base::server, buffer_.data(),
      [self = shared_from_this()](const beast::error_code& ec, std::size_t used) {
        if (ec) return self->close();
        self->buffer_.consume(used);
        self->read();
      });
}

void HttpSession::read() {
  parser_.emplace();
  parser_->body_limit(listener_->limits().body_bytes);
  parser_->header_limit(listener_->limits().header_bytes);
  tcp_of(stream_).expires_after(listener_->limits().read_timeout);
  std::visit(
      [this](auto& stream) {
        http::async_read(stream, buffer_, *parser_,
                         [self = shared_from_this()](const beast::error_code& ec, std::size_t) {
                           self->on_read(ec);
                         });
      },
      stream_.v);
}

void HttpSession::on_read(const beast::error_code& ec) {
  if (ec == http::error::end_of_stream || ec == beast::error::timeout ||
      ec == asio::error::operation_aborted || ec == asio::error::connection_reset ||
      ec == asio::error::eof || ec == asio::ssl::error::stream_truncated) {
    close();
    return;
  }
  if (ec) {
    HttpRequest blank;
    blank.version(11);
    const auto status = status_of_read_error(ec);
    const std::string why =
        status == http::status::payload_too_large
            ? fmt::format("the request is larger than the server's limit of {} bytes",
                          listener_->limits().body_bytes)
            : fmt::format("the request cannot be read: {}", ec.message());
    answer(error_response(blank, status, why), true);
    return;
  }
  HttpRequest req = parser_->release();
  if (beast::websocket::is_upgrade(req)) {
    auto refused = listener_->handlers().upgrade(stream_, req);
    if (refused) answer(std::move(*refused), false);
    return;  // the socket now belongs to the WebSocket (or is answered and closed)
  }
  if (const auto& later = listener_->handlers().later) {
    HttpHandlers::Answer reply = [self = shared_from_this()](HttpResponse res) {
      self->answer(std::move(res), false);
    };
    if (later(req, origin_, reply)) return;  // the session waits, reading nothing
  }
  HttpResponse res = listener_->handlers().request(req, origin_);
  if (const auto& take = listener_->handlers().take_stream) {
    if (auto body = take()) return answer_streamed(std::move(res), std::move(*body));
  }
  answer(std::move(res), false);
}

// `drain`: the request was not read to its end; answer, stop sending, and
// read what the client still sends, so it gets the answer instead of a reset.
void HttpSession::answer(HttpResponse res, bool drain_after) {
  if (drain_after) res.keep_alive(false);
  auto shared = std::make_shared<HttpResponse>(std::move(res));
  tcp_of(stream_).expires_after(listener_->limits().read_timeout);
  std::visit(
      [&](auto& stream) {
        http::async_write(stream, *shared,
                          [self = shared_from_this(), shared, drain_after](
                              const beast::error_code& ec, std::size_t) {
                            if (ec) return self->close();
                            if (drain_after) return self->drain();
                            if (!shared->keep_alive()) return self->close();
                            self->read();
                          });
      },
      stream_.v);
}

// The head (with the whole body's Content-Length), then the body a piece at
// a time: the next piece is asked for only when the one before is written,
// so a slow client holds one piece of the server's memory.
void HttpSession::answer_streamed(HttpResponse res, StreamedBody body) {
  auto head = std::make_shared<http::response<http::empty_body>>(std::move(res.base()));
  auto writer = std::make_shared<http::response_serializer<http::empty_body>>(*head);
  auto source = std::make_shared<StreamedBody>(std::move(body));
  tcp_of(stream_).expires_after(listener_->limits().read_timeout);
  std::visit(
      [&](auto& stream) {
        http::async_write_header(stream, *writer,
                                 [self = shared_from_this(), head, writer, source](
                                     const beast::error_code& ec, std::size_t) {
                                   if (ec) return self->close();
                                   self->write_piece(source, head->keep_alive());
                                 });
      },
      stream_.v);
}

void HttpSession::write_piece(std::shared_ptr<StreamedBody> body, bool keep_alive) {
  auto piece = body->next();
  if (!piece) return close();  // short of the announced length: the client sees it cut
  if (piece->empty()) return keep_alive ? read() : close();
  auto bytes = std::make_shared<std::string>(std::move(*piece));
  tcp_of(stream_).expires_after(listener_->limits().read_timeout);
  std::visit(
      [&](auto& stream) {
        asio::async_write(stream, asio::buffer(*bytes),
                          [self = shared_from_this(), bytes, body, keep_alive](
                              const beast::error_code& ec, std::size_t) {
                            if (ec) return self->close();
                            self->write_piece(body, keep_alive);
                          });
      },
      stream_.v);
}

void HttpSession::drain() {
  boost::system::error_code ignored;
  tcp_of(stream_).socket().shutdown(asio::ip::tcp::socket::shutdown_send, ignored);
  tcp_of(stream_).expires_after(std::chrono::seconds(5));  // for the whole drain
  drain_more();
}

void HttpSession::drain_more() {
  std::visit(
      [this](auto& stream) {
        stream.async_read_some(asio::buffer(sink_), [self = shared_from_this()](
                                                        const beast::error_code& ec, std::size_t) {
          if (ec) return self->close();
          self->drain_more();
        });
      },
      stream_.v);
}

void HttpSession::close() {
  boost::system::error_code ignored;
  // A TLS connection is closed without close_notify: every answer carries
  // its length, so the client knows it has it all.
  tcp_of(stream_).socket().shutdown(asio::ip::tcp::socket::shutdown_both, ignored);
  tcp_of(stream_).close();
}

}  // namespace usina::dnc
