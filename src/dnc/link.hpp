// A link to one machine's control: a byte stream in both directions on the
// server's one Boost.Asio event loop (no thread per machine). Serial ports
// and ptys (link_serial), raw TCP to a serial device server (link_tcp) and
// in-process pipes for tests (link_memory) all look the same to a transfer.
//
// Flow control is not the kernel's: XON/XOFF is read in user space (the
// kernel's IXON is unreliable on USB-serial adapters and eats 0x11/0x13 and
// CR from received data, research/dnc.md §2.2), RTS/CTS is the UART's, DSR
// is read before each chunk. What a link can tell a transfer is how many
// bytes it holds that have not reached the wire (output_queue), so the
// bytes in flight after an XOFF stay within the machine's skid.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/system/error_code.hpp>

#include "dnc/link_config.hpp"

namespace usina::dnc {

namespace asio = boost::asio;
using ErrorCode = boost::system::error_code;
using IoHandler = std::function<void(const ErrorCode&, std::size_t)>;

class Link {
 public:
  Link() = default;
  Link(const Link&) = delete;
  Link& operator=(const Link&) = delete;
  virtual ~Link() = default;

  // Reads what has arrived (at least one byte), or ends with an error
  // (end of file, a reset connection, a pty whose other end closed).
  virtual void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) = 0;
  // Writes all of `bytes` (the buffer must live until the handler runs).
  virtual void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) = 0;

  // Writes what the link takes at once, without waiting and without a trip
  // through the loop: the count (0 when it would block), or an error in
  // `ec`. Nothing when the link cannot (the transfer then uses async_write).
  // A drip feed writes a chunk every few milliseconds on every machine; the
  // loop's completion of each async_write is a cost of its own.
  virtual std::optional<std::size_t> try_write(std::span<const std::uint8_t> bytes, ErrorCode& ec) {
    (void)bytes;
    ec.clear();
    return std::nullopt;
  }

  // Ends the pending read and write with operation_aborted; the link stays
  // open (a transfer that ends hands the link back to its station).
  virtual void cancel() = 0;
  // Ends the link; pending operations end with operation_aborted.
  virtual void close() = 0;

  // Bytes the link has accepted that have not yet left for the wire: the
  // tty's output queue (TIOCOUTQ), the socket's unsent bytes (SIOCOUTQ), a
  // memory pipe's unread bytes; nothing when the link cannot tell (a pty,
  // whose TIOCOUTQ is always 0).
  virtual std::optional<std::size_t> output_queue() const { return std::nullopt; }

  // The control is ready to receive: DSR under dtr/dsr flow control; true
  // where the link has no such line.
  virtual bool peer_ready() const { return true; }

  // "/dev/ttyS0", "tcp://10.0.0.20:4001", "memory" (for messages).
  virtual std::string describe() const = 0;
};

// The link, or nothing and what went wrong ("cannot open /dev/ttyS9: No such file").
using LinkHandler = std::function<void(std::unique_ptr<Link>, const std::string& error)>;

// Opens the machine's `port` (a device, tcp://, tcp-listen://) configured
// from `config`; the handler runs on the event loop, with the link or the
// error (a device that cannot be opened or configured, a refused connection).
void async_open_link(asio::io_context& io, const LinkConfig& config, LinkHandler handler);

}  // namespace usina::dnc
