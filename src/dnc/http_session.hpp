// One HTTP connection of the listener (http_listener.hpp): requests read one
// after the other on a keep-alive connection, each answered before the next.
// On a TLS listener the connection's TLS handshake comes first (within the
// read timeout); a client that does not speak TLS there is dropped.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include "dnc/http_listener.hpp"
#include "dnc/http_stream.hpp"

namespace usina::dnc {

class HttpSession : public std::enable_shared_from_this<HttpSession> {
 public:
  HttpSession(boost::asio::ip::tcp::socket socket, std::shared_ptr<HttpListener> listener);
  ~HttpSession();

  HttpSession(const HttpSession&) = delete;
  HttpSession& operator=(const HttpSession&) = delete;

  void start();

 private:
  void handshake();
  void read();
  void on_read(const boost::beast::error_code& ec);
  void answer(HttpResponse res, bool drain);
  void answer_streamed(HttpResponse head, StreamedBody body);
  void write_piece(std::shared_ptr<StreamedBody> body, bool keep_alive);
  void drain();
  void drain_more();
  void close();

  HttpStream stream_;
  boost::beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::shared_ptr<HttpListener> listener_;
  std::string origin_;
  std::array<char, 8192> sink_{};
};

}  // namespace usina::dnc
