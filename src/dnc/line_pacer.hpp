// How many bytes a transfer may hand its link now so that no more than the
// machine's skid are ever in flight — accepted by the link (kernel queue,
// UART FIFO, device server) but not yet on the wire. A control's XOFF stops
// only what usina has not written; the bytes in flight still arrive, so
// they are what the control's buffer must have room for after its XOFF
// (research/dnc.md §2.2, "skid").
//
// The wire is modelled as a queue drained at the line's rate: writing n
// bytes at t moves the moment it empties to max(that, t) + n / rate. The
// link's own count of queued bytes (TIOCOUTQ, SIOCOUTQ), where it has one,
// is taken when it is larger (a slower device server, a UART held by CTS;
// a pty has none: link_serial.cpp).
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>

namespace usina::dnc {

class LinePacer {
 public:
  using Clock = std::chrono::steady_clock;

  // `bytes_per_second` 0: no model (only the link's count bounds the flight).
  LinePacer(double bytes_per_second, std::uint32_t skid);

  // Bytes in flight at `now`.
  double in_flight(Clock::time_point now, std::optional<std::size_t> queued) const;
  // Bytes that may be written at `now`.
  std::size_t room(Clock::time_point now, std::optional<std::size_t> queued) const;
  // When `want` bytes of room will be free (at the earliest `now` + 100 µs).
  Clock::time_point ready_at(std::size_t want, Clock::time_point now,
                             std::optional<std::size_t> queued) const;
  void wrote(std::size_t n, Clock::time_point now);

  std::uint32_t skid() const { return skid_; }

 private:
  double rate_;
  std::uint32_t skid_;
  Clock::time_point wire_empty_at_{};
};

}  // namespace usina::dnc
