#include "dnc/link_port.hpp"

#include <charconv>

#include <fmt/format.h>

namespace usina::dnc {
namespace {

tl::expected<PortAddress, std::string> parse_host_port(std::string_view rest,
                                                       PortAddress::Kind kind,
                                                       std::string_view scheme) {
  const std::size_t colon = rest.rfind(':');
  if (colon == std::string_view::npos || colon + 1 == rest.size()) {
    return tl::make_unexpected(
        fmt::format("\"{}{}\" has no port: write {}HOST:PORT", scheme, rest, scheme));
  }
  std::string_view host = rest.substr(0, colon);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
    host = host.substr(1, host.size() - 2);  // [::1]
  }
  if (host.empty()) {
    return tl::make_unexpected(fmt::format("\"{}{}\" has no host", scheme, rest));
  }
  const std::string_view digits = rest.substr(colon + 1);
  unsigned port = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), port);
  if (ec != std::errc() || end != digits.data() + digits.size() || port == 0 || port > 65535) {
    return tl::make_unexpected(
        fmt::format("\"{}\" is no TCP port: give a number from 1 to 65535", digits));
  }
  PortAddress a;
  a.kind = kind;
  a.host = std::string(host);
  a.port = static_cast<std::uint16_t>(port);
  return a;
}

}  // namespace

tl::expected<PortAddress, std::string> parse_port(std::string_view s) {
  constexpr std::string_view kTcp = "tcp://";
  constexpr std::string_view kListen = "tcp-listen://";
  if (s.starts_with(kTcp)) {
    return parse_host_port(s.substr(kTcp.size()), PortAddress::Kind::TcpClient, kTcp);
  }
  if (s.starts_with(kListen)) {
    return parse_host_port(s.substr(kListen.size()), PortAddress::Kind::TcpListen, kListen);
  }
  if (s.empty() || s.front() != '/') {
    return tl::make_unexpected(
        fmt::format("\"{}\" is neither a device path (/dev/ttyS0) nor tcp://HOST:PORT nor "
                    "tcp-listen://HOST:PORT",
                    s));
  }
  if (s.find('\0') != std::string_view::npos) {
    return tl::make_unexpected("a device path cannot hold a NUL byte");
  }
  PortAddress a;
  a.path = std::string(s);
  return a;
}

}  // namespace usina::dnc
