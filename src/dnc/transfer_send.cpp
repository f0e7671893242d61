#include "dnc/transfer_send.hpp"

#include <algorithm>
#include <cmath>

#include <boost/asio/post.hpp>
#include <fmt/format.h>

namespace usina::dnc {
namespace {

constexpr std::size_t kSlice = 16384;  // program bytes read at a time
constexpr auto kDsrPoll = std::chrono::milliseconds(10);
// How late a feed may be served once its wire could take a chunk: no hurry
// (the wire is still busy) for the DSR poll and the final drain.
constexpr auto kSlack = std::chrono::milliseconds(5);
// A feed is served before its wire is down to this much line time, so a
// loop a little late does not leave the line idle.
constexpr std::chrono::duration<double> kLowMark{0.003};

}  // namespace

std::string_view job_state_name(JobState s) {
  switch (s) {
  case JobState::Queued: return "queued";
  case JobState::Running: return "running";
  case JobState::Done: return "done";
  case JobState::Interrupted: return "interrupted";
  case JobState::Failed: return "failed";
  }
  return "?";
}

SendOptions send_options(const LinkConfig& c) {
  SendOptions o;
  o.format = tape_format(c);
  o.flow = c.flow;
  o.code = c.code;
  o.xon = c.xon;
  o.xoff = c.xoff;
  o.skid = c.skid;
  o.bytes_per_second = bytes_per_second(c);
  o.wait_for_xon = c.wait_for_xon && c.flow == Flow::XonXoff;
  o.xon_timeout = std::chrono::duration<double>(c.xon_timeout);
  return o;
}

Sender::Sender(asio::io_context& io, Link& link, SendOptions options,
               std::unique_ptr<ProgramSource> program, JobMode mode)
    : io_(io),
      link_(link),
      options_(options),
      program_(std::move(program)),
      writer_(options.format),
      pacer_(options.bytes_per_second, options.skid),
      tick_(PacingTick::of(io)),
      watchdog_(io),
      slice_(kSlice) {
  report_.mode = mode;
  report_.bytes_total = program_->size().value_or(0);
}

void Sender::start(DoneHandler done) {
  done_ = std::move(done);
  report_.state = JobState::Running;
  if (options_.wait_for_xon) {
    paused_ = true;  // the tape reader's start: the control's first DC1
    arm_xon_watchdog();
  }
  read_loop();
  pump();
}

void Sender::stop(std::string reason) {
  end(JobState::Interrupted, std::move(reason));
}

bool Sender::is_xon(std::uint8_t b) const {
  // ISO on 8 data bits carries DC1/DC3 with their parity bit (0x93 for DC3).
  return b == options_.xon || (options_.code == TapeCode::Iso && (b & 0x7FU) == options_.xon);
}

bool Sender::is_xoff(std::uint8_t b) const {
  return b == options_.xoff || (options_.code == TapeCode::Iso && (b & 0x7FU) == options_.xoff);
}

void Sender::read_loop() {
  link_.async_read_some(in_, [self = shared_from_this()](const ErrorCode& ec, std::size_t n) {
    if (self->finished_) return;
    if (ec) {
      self->end(JobState::Interrupted, fmt::format("link lost ({})", ec.message()));
      return;
    }
    self->on_bytes(std::span<const std::uint8_t>(self->in_.data(), n));
    if (!self->finished_) self->read_loop();
  });
}

void Sender::on_bytes(std::span<const std::uint8_t> bytes) {
  if (options_.flow != Flow::XonXoff) {
    if (received_) received_(bytes);
    return;
  }
  std::vector<std::uint8_t> data;
  for (const std::uint8_t b : bytes) {
    if (is_xoff(b)) {
      on_xoff();
    } else if (is_xon(b)) {
      on_xon();
    } else {
      data.push_back(b);
    }
  }
  if (received_ && !data.empty()) received_(data);
}

void Sender::on_xoff() {
  if (paused_) return;
  paused_ = true;
  ++report_.xoff_count;
  const double flying = pacer_.in_flight(Clock::now(), link_.output_queue());
  report_.max_in_flight_at_xoff = std::max(report_.max_in_flight_at_xoff, flying);
  // The DC3 after the last `%` is the tape reader's stop, not a pause.
  if (!(program_done_ && staged_at_ == staged_.size())) arm_xon_watchdog();
}

void Sender::on_xon() {
  if (!paused_) {
    ++report_.xon_without_xoff;  // harmless (a control that re-sends XON)
    return;
  }
  paused_ = false;
  watchdog_.cancel();
  pump();
}

void Sender::arm_xon_watchdog() {
  watchdog_.expires_after(std::chrono::duration_cast<Clock::duration>(options_.xon_timeout));
  watchdog_.async_wait([self = shared_from_this()](const ErrorCode& ec) {
    if (ec || self->finished_ || !self->paused_) return;
    self->report_.alarm = true;
    self->end(JobState::Interrupted,
              fmt::format("no XON within {:g} s of the control's XOFF (alarm); the job is not "
                          "resumed",
                          self->options_.xon_timeout.count()));
  });
}

// Keeps at least a skid of rows staged while the program lasts, so that a
// chunk is never cut short at the end of a slice (one more write).
bool Sender::top_up() {
  if (program_done_ || staged_.size() - staged_at_ >= options_.skid) return true;
  staged_.erase(staged_.begin(), staged_.begin() + static_cast<std::ptrdiff_t>(staged_at_));
  staged_at_ = 0;
  marks_.erase(marks_.begin(), marks_.begin() + static_cast<std::ptrdiff_t>(marks_at_));
  marks_at_ = 0;
  while (staged_.size() < options_.skid && !program_done_) {
    if (!stage_slice()) return false;
  }
  return true;
}

// The next slice of the program through the tape writer (the closing `%`
// and trailer after the last); false when the job failed.
bool Sender::stage_slice() {
  const std::size_t n = program_->read(slice_);
  bool ok = true;
  if (n == 0) {
    if (const std::string error = program_->error(); !error.empty()) {
      end(JobState::Failed, error);
      return false;
    }
    ok = writer_.finish(staged_, marks_);
    program_done_ = true;
  } else {
    ok = writer_.write(std::string_view(slice_.data(), n), staged_, marks_);
  }
  if (!ok) end(JobState::Failed, writer_.diagnostic().message);
  return ok;
}

void Sender::pump() {
  if (finished_ || writing_ || waiting_) return;
  if (!top_up()) return;
  if (staged_at_ == staged_.size()) {
    wait_for_drain();
    return;
  }
  if (paused_) return;
  const auto now = Clock::now();
  if (options_.flow == Flow::DtrDsr && !link_.peer_ready()) {
    wait_between(now + kDsrPoll, now + kDsrPoll + kSlack);
    return;
  }
  const std::size_t rest = staged_.size() - staged_at_;
  const std::size_t want = std::min<std::size_t>(rest, std::max<std::size_t>(1, options_.skid / 2));
  // The wire model first: while it has no room the link's own count (a
  // system call each time, 256 machines × 720 a second) cannot give more.
  if (pacer_.room(now, std::nullopt) < want) {
    wait_for_room(want, now, std::nullopt);
    return;
  }
  const std::optional<std::size_t> queued = link_.output_queue();
  const std::size_t room = pacer_.room(now, queued);
  if (room < want) {
    wait_for_room(want, now, queued);
    return;
  }
  write_chunk(std::min(room, rest));
}

// Between `want` bytes of room and the wire down to its low mark: the tick
// serves the feed anywhere in that window, with other feeds, and the chunk
// is all the room there is then (up to the skid, never more).
void Sender::wait_for_room(std::size_t want, Clock::time_point now,
                           std::optional<std::size_t> queued) {
  const double low = std::ceil(options_.bytes_per_second * kLowMark.count());
  const auto low_mark = std::min<std::size_t>(
      std::max<std::size_t>(static_cast<std::size_t>(low), options_.skid / 8), options_.skid / 2);
  wait_between(pacer_.ready_at(want, now, queued),
               pacer_.ready_at(options_.skid - low_mark, now, queued));
}

void Sender::write_chunk(std::size_t n) {
  const std::span<const std::uint8_t> chunk(staged_.data() + staged_at_, n);
  ++report_.writes;
  // At once where the link can (a tty): no trip through the loop per chunk.
  ErrorCode ec;
  const std::optional<std::size_t> now = link_.try_write(chunk, ec);
  if (ec || now.value_or(0) > 0) {
    on_written(ec, now.value_or(0));
    return;
  }
  writing_ = true;
  link_.async_write(chunk, [self = shared_from_this()](const ErrorCode& e, std::size_t k) {
    self->on_written(e, k);
  });
}

void Sender::on_written(const ErrorCode& ec, std::size_t n) {
  writing_ = false;
  if (finished_) return;
  sha_.update(std::span<const std::uint8_t>(staged_.data() + staged_at_, n));
  staged_at_ += n;
  report_.bytes_sent += n;
  pacer_.wrote(n, Clock::now());
  while (marks_at_ < marks_.size() && marks_[marks_at_].wire_end <= report_.bytes_sent) {
    report_.line = marks_[marks_at_].line;
    if (marks_[marks_at_].n_number >= 0) report_.block = marks_[marks_at_].n_number;
    ++marks_at_;
  }
  if (ec) {
    end(JobState::Interrupted, fmt::format("link lost ({})", ec.message()));
    return;
  }
  if (progress_) progress_(report_);
  pump();
}

void Sender::wait_between(Clock::time_point earliest, Clock::time_point latest) {
  waiting_ = true;
  ticket_ = tick_.call_between(earliest, latest, [self = shared_from_this()] {
    self->waiting_ = false;
    self->ticket_ = 0;
    if (self->finished_) return;
    self->pump();
  });
}

// Done when the last byte has left for the wire, not when the link took it.
void Sender::wait_for_drain() {
  const auto now = Clock::now();
  const std::optional<std::size_t> queued = link_.output_queue();
  if (pacer_.in_flight(now, queued) < 0.5) {
    end(JobState::Done, {});
    return;
  }
  const auto drained = pacer_.ready_at(options_.skid, now, queued);
  wait_between(drained, drained + kSlack);
}

void Sender::end(JobState state, std::string reason) {
  if (finished_) return;
  finished_ = true;
  report_.state = state;
  report_.sha256 = sha_.hex();
  if (state == JobState::Interrupted) {
    report_.reason = fmt::format(
        "interrupted at byte {}, line {}{}: {}", report_.bytes_sent, report_.line,
        report_.block >= 0 ? fmt::format(", block N{}", report_.block) : std::string(), reason);
  } else {
    report_.reason = std::move(reason);
  }
  if (ticket_ != 0) tick_.cancel(ticket_);  // lets go of this sender
  ticket_ = 0;
  watchdog_.cancel();
  link_.cancel();
  if (done_) {
    asio::post(io_, [self = shared_from_this()] { self->done_(self->report_); });
  }
}

}  // namespace usina::dnc
