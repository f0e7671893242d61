// Receiving a program the control punches: the rows read through the tape
// reader until the closing `%`, or until the line has been silent for
// `receive_idle` seconds after something arrived (a control that punches no
// closing `%`), or the link is lost, or more than `max_bytes` arrived. The
// result is the text (LF line ends), its name from its O number, whether it
// was complete and every bad row; storing it (a draft revision with a diff
// against the released one) is the store's job.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/steady_timer.hpp>

#include "dnc/link.hpp"
#include "dnc/sha256.hpp"
#include "dnc/tape_reader.hpp"

namespace usina::dnc {

struct ReceiveOptions {
  TapeCode code = TapeCode::Iso;
  EndOfBlock eob = EndOfBlock::Lf;
  bool check_parity = true;  // false on 7 data bits: the UART checked it
  std::chrono::duration<double> idle{10.0};
  std::size_t max_bytes = 64U << 20U;
};

ReceiveOptions receive_options(const LinkConfig& c);

struct ReceivedProgram {
  enum class End : std::uint8_t { Complete, Idle, LinkLost, TooLarge, Stopped };
  End end = End::Complete;
  std::string text;
  std::string name;            // "O1234", empty without an O number
  std::uint64_t rows = 0;      // rows read, leader and DC codes included
  std::uint64_t bad_rows = 0;  // parity errors and rows of no character
  std::vector<std::uint64_t> bad_offsets;
  std::string sha256;  // of the rows as they arrived
  std::string reason;  // for every end but Complete

  bool good() const { return end == End::Complete && bad_rows == 0; }
};

class Receiver : public std::enable_shared_from_this<Receiver> {
 public:
  using DoneHandler = std::function<void(const ReceivedProgram&)>;

  Receiver(asio::io_context& io, Link& link, ReceiveOptions options);

  void start(DoneHandler done);
  // Rows that arrived before the receive started (the first of a punch,
  // read by the station while it was idle).
  void feed_first(std::span<const std::uint8_t> rows);
  void stop();

 private:
  void read_loop();
  void on_rows(std::span<const std::uint8_t> rows);
  void arm_idle();
  void end(ReceivedProgram::End how, std::string reason);

  asio::io_context& io_;
  Link& link_;
  ReceiveOptions options_;
  TapeReader reader_;
  Sha256 sha_;
  asio::steady_timer idle_;
  std::array<std::uint8_t, 1024> in_{};
  DoneHandler done_;
  bool finished_ = false;
};

}  // namespace usina::dnc
