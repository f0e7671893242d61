// Serial ports and ptys: the device opened non-blocking, put in raw mode by
// termios with the machine's frame (baud, data bits, parity, stop bits,
// RTS/CTS), IXON/IXOFF/ICRNL off, DTR and RTS raised when no hardware
// handshake uses them; then read and written through the event loop.
#pragma once

#include <termios.h>

#include <memory>
#include <string>

#include <tl/expected.hpp>

#include "dnc/link.hpp"

namespace usina::dnc {

// The termios of `t` with the machine's frame (rate, data bits, parity,
// stop bits, RTS/CTS) in raw mode; an error for a rate with no constant.
tl::expected<termios, std::string> serial_frame(termios t, const LinkConfig& config);

// Applies the machine's frame to an open tty; a pty takes every flag but
// the speed, which it ignores.
tl::expected<void, std::string> configure_tty(int fd, const LinkConfig& config);

// Opens and configures the device at `path`.
tl::expected<std::unique_ptr<Link>, std::string> open_serial_link(asio::io_context& io,
                                                                  const std::string& path,
                                                                  const LinkConfig& config);

// A link over an already open descriptor (the master side of a pty in
// tests); the link owns it.
std::unique_ptr<Link> descriptor_link(asio::io_context& io, int fd, std::string name,
                                      bool dsr_flow = false);

// A pty pair for tests: the master as a link, the slave's path for a
// machine's `port`. The master gets raw mode too, so nothing is echoed.
struct PtyPair {
  std::unique_ptr<Link> master;
  std::string slave_path;
};

tl::expected<PtyPair, std::string> open_pty_pair(asio::io_context& io);

}  // namespace usina::dnc
