// Raw TCP to a serial device server (Moxa NPort, Digi, ser2net in raw mode):
// usina connects to it (tcp://HOST:PORT), or waits for it to connect
// (tcp-listen://HOST:PORT, the device server's "TCP client" mode; the first
// connection is the machine's). The frame is the device server's own
// setting; usina's flow control, tape code and skid work as on a serial port.
#pragma once

#include "dnc/link.hpp"
#include "dnc/link_port.hpp"

namespace usina::dnc {

void async_open_tcp_link(asio::io_context& io, const PortAddress& address, LinkHandler handler);

}  // namespace usina::dnc
