#include "dnc/link_tcp.hpp"

#include <utility>

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <fmt/format.h>
#include <linux/sockios.h>
#include <sys/ioctl.h>

namespace usina::dnc {
namespace {

using tcp = asio::ip::tcp;

class TcpLink final : public Link {
 public:
  TcpLink(tcp::socket socket, std::string name)
      : socket_(std::move(socket)), name_(std::move(name)) {
    ErrorCode ignored;
    // A drip feed writes small chunks; Nagle would hold them back.
    socket_.set_option(tcp::no_delay(true), ignored);
    // For try_write: asio's own asynchronous operations do not depend on it.
    socket_.non_blocking(true, ignored);
  }

  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    socket_.async_read_some(asio::buffer(buffer.data(), buffer.size()), std::move(handler));
  }

  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    asio::async_write(socket_, asio::buffer(bytes.data(), bytes.size()), std::move(handler));
  }

  std::optional<std::size_t> try_write(std::span<const std::uint8_t> bytes,
                                       ErrorCode& ec) override {
    const std::size_t n = socket_.write_some(asio::buffer(bytes.data(), bytes.size()), ec);
    if (ec == asio::error::would_block || ec == asio::error::try_again) {
      ec.clear();
      return 0;
    }
    if (ec) return std::nullopt;
    return n;
  }

  void cancel() override {
    ErrorCode ignored;
    socket_.cancel(ignored);
  }

  void close() override {
    ErrorCode ignored;
    socket_.shutdown(tcp::socket::shutdown_both, ignored);
    socket_.close(ignored);
  }

  std::optional<std::size_t> output_queue() const override {
    int n = 0;
    auto& s = const_cast<tcp::socket&>(socket_);  // native_handle is not const in Asio
    if (!s.is_open() || ::ioctl(s.native_handle(), SIOCOUTQ, &n) != 0 || n < 0) return std::nullopt;
    return static_cast<std::size_t>(n);
  }

  std::string describe() const override { return name_; }

 private:
  tcp::socket socket_;
  std::string name_;
};

void connect(asio::io_context& io, const PortAddress& address, LinkHandler handler) {
  auto resolver = std::make_shared<tcp::resolver>(io);
  auto socket = std::make_shared<tcp::socket>(io);
  const std::string name = fmt::format("tcp://{}:{}", address.host, address.port);
  resolver->async_resolve(
      address.host, std::to_string(address.port),
      [resolver, socket, name, handler = std::move(handler)](
          const ErrorCode& ec, const tcp::resolver::results_type& endpoints) mutable {
        if (ec) {
          handler(nullptr, fmt::format("cannot resolve {}: {}", name, ec.message()));
          return;
        }
        asio::async_connect(
            *socket, endpoints,
            [socket, name, handler = std::move(handler)](const ErrorCode& e, const tcp::endpoint&) {
              if (e) {
                handler(nullptr, fmt::format("cannot connect to {}: {}", name, e.message()));
                return;
              }
              handler(std::make_unique<TcpLink>(std::move(*socket), name), {});
            });
      });
}

void listen(asio::io_context& io, const PortAddress& address, LinkHandler handler) {
  ErrorCode ec;
  const auto ip = asio::ip::make_address(address.host, ec);
  if (ec) {
    handler(nullptr, fmt::format("\"{}\" is no IP address to listen on", address.host));
    return;
  }
  auto acceptor = std::make_shared<tcp::acceptor>(io);
  const tcp::endpoint endpoint(ip, address.port);
  acceptor->open(endpoint.protocol(), ec);
  if (!ec) acceptor->set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor->bind(endpoint, ec);
  if (!ec) acceptor->listen(1, ec);
  const std::string name = fmt::format("tcp-listen://{}:{}", address.host, address.port);
  if (ec) {
    handler(nullptr, fmt::format("cannot listen on {}: {}", name, ec.message()));
    return;
  }
  acceptor->async_accept(
      [acceptor, name, handler = std::move(handler)](const ErrorCode& e, tcp::socket socket) {
        ErrorCode ignored;
        acceptor->close(ignored);  // one device server a machine
        if (e) {
          handler(nullptr, fmt::format("no connection on {}: {}", name, e.message()));
          return;
        }
        handler(std::make_unique<TcpLink>(std::move(socket), name), {});
      });
}

}  // namespace

void async_open_tcp_link(asio::io_context& io, const PortAddress& address, LinkHandler handler) {
  if (address.kind == PortAddress::Kind::TcpListen) {
    listen(io, address, std::move(handler));
  } else {
    connect(io, address, std::move(handler));
  }
}

}  // namespace usina::dnc
