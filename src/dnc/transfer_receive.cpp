#include "dnc/transfer_receive.hpp"

#include <boost/asio/post.hpp>
#include <fmt/format.h>

namespace usina::dnc {

ReceiveOptions receive_options(const LinkConfig& c) {
  ReceiveOptions o;
  o.code = c.code;
  o.eob = c.eob;
  o.check_parity = c.data_bits == 8 && c.code != TapeCode::Ascii;
  o.idle = std::chrono::duration<double>(c.receive_idle);
  return o;
}

Receiver::Receiver(asio::io_context& io, Link& link, ReceiveOptions options)
    : io_(io),
      link_(link),
      options_(options),
      reader_(options.code, options.eob, options.check_parity, options.max_bytes),
      idle_(io) {}

void Receiver::start(DoneHandler done) {
  done_ = std::move(done);
  if (finished_) {
    asio::post(io_, [self = shared_from_this()] { self->done_(ReceivedProgram{}); });
    return;
  }
  read_loop();
}

void Receiver::feed_first(std::span<const std::uint8_t> rows) {
  on_rows(rows);
}

void Receiver::stop() {
  end(ReceivedProgram::End::Stopped, "stopped by the operator");
}

void Receiver::read_loop() {
  link_.async_read_some(in_, [self = shared_from_this()](const ErrorCode& ec, std::size_t n) {
    if (self->finished_) return;
    if (ec) {
      self->end(ReceivedProgram::End::LinkLost, fmt::format("link lost ({})", ec.message()));
      return;
    }
    self->on_rows(std::span<const std::uint8_t>(self->in_.data(), n));
    if (!self->finished_) self->read_loop();
  });
}

void Receiver::on_rows(std::span<const std::uint8_t> rows) {
  sha_.update(rows);
  const bool closed = reader_.feed(rows);
  if (closed) {
    end(ReceivedProgram::End::Complete, {});
  } else if (reader_.too_large()) {
    end(ReceivedProgram::End::TooLarge,
        fmt::format("the punch is larger than {} bytes; the rest was not read",
                    options_.max_bytes));
  } else {
    arm_idle();
  }
}

// Silence after a punch began ends it; before, the control has not started.
void Receiver::arm_idle() {
  idle_.expires_after(
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(options_.idle));
  idle_.async_wait([self = shared_from_this()](const ErrorCode& ec) {
    if (ec || self->finished_) return;
    self->end(ReceivedProgram::End::Idle,
              fmt::format("no closing % and {:g} s of silence", self->options_.idle.count()));
  });
}

void Receiver::end(ReceivedProgram::End how, std::string reason) {
  if (finished_) return;
  finished_ = true;
  idle_.cancel();
  link_.cancel();
  ReceivedProgram r;
  r.end = how;
  r.text = reader_.text();
  r.name = program_number(r.text);
  r.rows = reader_.rows_read();
  r.bad_rows = reader_.bad_rows();
  r.bad_offsets = reader_.bad_offsets();
  r.sha256 = sha_.hex();
  r.reason = std::move(reason);
  if (r.bad_rows > 0 && r.reason.empty()) {
    r.reason = fmt::format("{} row(s) failed the {} parity check or are no character of the code",
                           r.bad_rows, code_name(options_.code));
  }
  if (done_) {
    asio::post(io_, [self = shared_from_this(), r = std::move(r)] { self->done_(r); });
  }
}

}  // namespace usina::dnc
