// Where a machine's link goes (the `port` key): a serial device or pty path
// ("/dev/ttyS0", "/dev/pts/4"), a serial device server in raw-TCP mode that
// usina connects to ("tcp://10.0.0.20:4001"), or one that connects to usina
// ("tcp-listen://0.0.0.0:4001", the server's "TCP client" mode).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include <tl/expected.hpp>

namespace usina::dnc {

struct PortAddress {
  enum class Kind : std::uint8_t { Device, TcpClient, TcpListen };
  Kind kind = Kind::Device;
  std::string path;  // Device
  std::string host;  // TcpClient, TcpListen
  std::uint16_t port = 0;
};

// The address, or what is wrong with it.
tl::expected<PortAddress, std::string> parse_port(std::string_view s);

}  // namespace usina::dnc
