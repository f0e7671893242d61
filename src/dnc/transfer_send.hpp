// Sending a program to a control: whole (the control stores it) or as a drip
// feed (the control runs it as it arrives, behind the tape reader; any
// size). Both are one engine: the program read a slice at a time, through
// the tape writer, onto the link in chunks that keep at most `skid` bytes in
// flight, paused by the control's XOFF and resumed by its XON, DSR watched
// under dtr/dsr, the SHA-256 of the bytes on the wire computed as they go.
//
// The job ends:
//   done         every byte accepted by the link and drained to the wire;
//   interrupted  the link was lost (read or write failed), the operator
//                stopped it, or no XON came within xon_timeout after an XOFF
//                (an alarm) — at byte/line/block, and never restarted here:
//                the next step is an operator's;
//   failed       nothing could be sent (a character without a tape code, an
//                unreadable program) — the bytes sent so far are reported.
// An XON without an XOFF (a Haas re-sending XON every 5 s) is harmless.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <boost/asio/steady_timer.hpp>

#include "dnc/line_pacer.hpp"
#include "dnc/link.hpp"
#include "dnc/pacing_tick.hpp"
#include "dnc/program_source.hpp"
#include "dnc/sha256.hpp"
#include "dnc/tape_writer.hpp"

namespace usina::dnc {

enum class JobMode : std::uint8_t { Send, Drip };
enum class JobState : std::uint8_t { Queued, Running, Done, Interrupted, Failed };

std::string_view job_state_name(JobState s);  // the contract's words: "queued", "running", ...

struct SendOptions {
  TapeFormat format;
  Flow flow = Flow::XonXoff;
  TapeCode code = TapeCode::Iso;
  std::uint8_t xon = 0x11;
  std::uint8_t xoff = 0x13;
  std::uint32_t skid = 32;
  double bytes_per_second = 0.0;  // the line's rate; 0: paced by the link's queue alone
  bool wait_for_xon = false;
  std::chrono::duration<double> xon_timeout{600.0};
};

SendOptions send_options(const LinkConfig& c);

struct JobReport {
  JobMode mode = JobMode::Send;
  JobState state = JobState::Queued;
  std::string reason;             // why it ended other than done
  bool alarm = false;             // no XON came: the machine needs a look
  std::uint64_t bytes_sent = 0;   // rows the link accepted
  std::uint64_t bytes_total = 0;  // 0 until known (the program's size is of its text, not rows)
  std::uint64_t line = 0;         // lines of the program fully sent
  std::int64_t block = -1;        // N of the last block fully sent, -1 before one
  std::string sha256;             // of the bytes sent
  std::uint32_t xoff_count = 0;
  std::uint32_t xon_without_xoff = 0;
  double max_in_flight_at_xoff = 0.0;  // never above skid
  std::uint64_t writes = 0;            // chunks handed to the link (a system call each)
};

class Sender : public std::enable_shared_from_this<Sender> {
 public:
  using DoneHandler = std::function<void(const JobReport&)>;
  using BytesHandler = std::function<void(std::span<const std::uint8_t>)>;

  Sender(asio::io_context& io, Link& link, SendOptions options,
         std::unique_ptr<ProgramSource> program, JobMode mode);

  // Starts the job; `done` runs once, on the loop, when it ends.
  void start(DoneHandler done);
  // The operator's stop (or the server's, with its reason): the job ends
  // interrupted.
  void stop(std::string reason = "stopped by the operator");

  // Bytes from the control that are not flow control (DPRNT output, ...).
  void on_received(BytesHandler h) { received_ = std::move(h); }

  // Called after each chunk the link accepted.
  void on_progress(DoneHandler h) { progress_ = std::move(h); }

  const JobReport& report() const { return report_; }

 private:
  using Clock = LinePacer::Clock;

  void read_loop();
  void on_bytes(std::span<const std::uint8_t> bytes);
  void on_xoff();
  void on_xon();
  void pump();
  bool top_up();
  bool stage_slice();
  void write_chunk(std::size_t n);
  void on_written(const ErrorCode& ec, std::size_t n);
  void wait_for_room(std::size_t want, Clock::time_point now, std::optional<std::size_t> queued);
  void wait_between(Clock::time_point earliest, Clock::time_point latest);
  void wait_for_drain();
  void arm_xon_watchdog();
  void end(JobState state, std::string reason);
  bool is_xon(std::uint8_t b) const;
  bool is_xoff(std::uint8_t b) const;

  asio::io_context& io_;
  Link& link_;
  SendOptions options_;
  std::unique_ptr<ProgramSource> program_;
  TapeWriter writer_;
  LinePacer pacer_;
  Sha256 sha_;
  PacingTick& tick_;  // the loop's one pacing timer, shared by every feed
  PacingTick::Ticket ticket_ = 0;
  asio::steady_timer watchdog_;
  JobReport report_;
  DoneHandler done_;
  DoneHandler progress_;
  BytesHandler received_;

  std::vector<std::uint8_t> staged_;  // rows encoded; from staged_at_ on not yet written
  std::size_t staged_at_ = 0;
  std::vector<BlockMark> marks_;  // block ends among the staged rows
  std::size_t marks_at_ = 0;
  std::vector<char> slice_;
  std::array<std::uint8_t, 256> in_{};
  bool program_done_ = false;
  bool writing_ = false;
  bool waiting_ = false;
  bool paused_ = false;
  bool finished_ = false;
};

}  // namespace usina::dnc
