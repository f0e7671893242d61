// A simulated control on the other end of a link, for tests and the
// benchmark (research/dnc.md §6.2): a receive buffer of `buffer` bytes that
// the control empties as it runs the program (`execute_rate` bytes a
// second), an XOFF once the buffer holds `high_water` bytes and an XON once
// it is down to `low_water`, and the control's reaction delay: the XOFF
// leaves `xoff_delay` seconds after the buffer reached high water, or once
// `xoff_delay_bytes` more bytes have arrived, whichever comes first (the
// byte form makes the tests independent of the machine's load).
//
// It counts what a real control would suffer: bytes that found the buffer
// full (overflow, a silent loss on a real control), the most bytes that
// arrived after one of its XOFFs, and it hashes everything it received, so
// a test compares it byte for byte with what usina says it sent. It can also
// misbehave: never send the XON (a lost XON), send XONs without XOFF, drop
// the link after N bytes, send its first XON only when started.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/steady_timer.hpp>

#include "dnc/link.hpp"
#include "dnc/sha256.hpp"

namespace usina::dnc {

struct SimCncConfig {
  std::size_t buffer = 256;
  std::size_t high_water = 192;
  std::size_t low_water = 64;
  double xoff_delay = 0.0;           // seconds
  std::size_t xoff_delay_bytes = 0;  // 0: the time alone decides
  double execute_rate = 0.0;         // bytes a second; 0: instantly
  std::uint8_t xon = 0x11;
  std::uint8_t xoff = 0x13;
  bool lose_xon = false;            // never answer with XON
  bool send_initial_xon = false;    // a tape reader starting: DC1 first
  double spurious_xon_every = 0.0;  // seconds; > 0: XON again and again (Haas)
  std::uint64_t drop_link_at = 0;   // close the link once this many bytes arrived
  bool keep_data = false;           // keep the bytes received (small tests)
};

struct SimCncStats {
  std::uint64_t received = 0;
  std::uint64_t overflow = 0;  // bytes lost: they found the buffer full
  std::uint64_t xoff_sent = 0;
  std::uint64_t xon_sent = 0;
  std::uint64_t max_after_xoff = 0;  // most bytes that arrived after one XOFF
  std::size_t max_fill = 0;
  bool link_lost = false;
};

class SimCnc : public std::enable_shared_from_this<SimCnc> {
 public:
  SimCnc(asio::io_context& io, Link& link, SimCncConfig config);

  void start();
  void stop();

  const SimCncStats& stats() const { return stats_; }

  std::string sha256() const { return sha_.hex(); }

  const std::vector<std::uint8_t>& data() const { return data_; }

 private:
  using Clock = std::chrono::steady_clock;

  void read_loop();
  void on_bytes(const std::uint8_t* p, std::size_t n);
  void execute(Clock::time_point now);
  void send(std::uint8_t b);
  void write_next();
  void send_xoff();
  void schedule();
  void spurious_loop();

  asio::io_context& io_;
  Link& link_;
  SimCncConfig config_;
  SimCncStats stats_;
  Sha256 sha_;
  asio::steady_timer xoff_timer_;
  asio::steady_timer xon_timer_;
  asio::steady_timer spurious_timer_;
  std::array<std::uint8_t, 1024> in_{};
  std::vector<std::uint8_t> data_;
  std::vector<std::uint8_t> out_queue_;
  std::array<std::uint8_t, 64> out_{};
  bool writing_ = false;
  double fill_ = 0.0;
  Clock::time_point last_{};
  bool xoff_pending_ = false;   // high water reached, XOFF not yet sent
  std::size_t since_high_ = 0;  // bytes since high water, while pending
  bool xoff_asserted_ = false;  // XOFF sent, XON not yet
  std::uint64_t after_xoff_ = 0;
  bool stopped_ = false;
};

// The largest skid a control of this buffer can take without overflow: the
// room above high water less what arrives while it reacts.
std::size_t safe_skid(const SimCncConfig& c, double bytes_per_second);

}  // namespace usina::dnc
