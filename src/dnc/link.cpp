#include "dnc/link.hpp"

#include <boost/asio/post.hpp>

#include "dnc/link_port.hpp"
#include "dnc/link_serial.hpp"
#include "dnc/link_tcp.hpp"

namespace usina::dnc {

void async_open_link(asio::io_context& io, const LinkConfig& config, LinkHandler handler) {
  const auto address = parse_port(config.port);
  if (!address) {
    asio::post(
        io, [handler = std::move(handler), error = address.error()] { handler(nullptr, error); });
    return;
  }
  if (address->kind != PortAddress::Kind::Device) {
    async_open_tcp_link(io, *address, std::move(handler));
    return;
  }
  auto link = open_serial_link(io, address->path, config);
  // The handler always runs from the loop, never inside this call.
  asio::post(io, [handler = std::move(handler), link = std::move(link)]() mutable {
    if (!link) {
      handler(nullptr, link.error());
      return;
    }
    handler(std::move(*link), std::string());
  });
}

}  // namespace usina::dnc
