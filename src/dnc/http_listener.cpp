#include "dnc/http_listener.hpp"

#include "dnc/http_session.hpp"

namespace usina::dnc {

namespace asio = boost::asio;
using tcp = asio::ip::tcp;

HttpListener::HttpListener(asio::io_context& io, HttpHandlers handlers, HttpLimits limits)
    : acceptor_(io), handlers_(std::move(handlers)), limits_(limits) {}

std::string HttpListener::listen(const tcp::endpoint& at) {
  boost::system::error_code ec;
  acceptor_.open(at.protocol(), ec);
  if (!ec) acceptor_.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) acceptor_.bind(at, ec);
  if (!ec) acceptor_.listen(asio::socket_base::max_listen_connections, ec);
  return ec ? ec.message() : std::string();
}

void HttpListener::start() {
  accept();
}

void HttpListener::stop() {
  boost::system::error_code ignored;
  acceptor_.close(ignored);
}

tcp::endpoint HttpListener::local_endpoint() const {
  boost::system::error_code ec;
  return acceptor_.local_endpoint(ec);
}

void HttpListener::accept() {
  acceptor_.async_accept(
      [self = shared_from_this()](const boost::system::error_code& ec, tcp::socket socket) {
        if (ec == asio::error::operation_aborted || !self->acceptor_.is_open()) return;
        if (!ec && self->connections < self->limits_.connections) {
          std::make_shared<HttpSession>(std::move(socket), self)->start();
        }
        self->accept();
      });
}

}  // namespace usina::dnc
