#include "dnc/station.hpp"

namespace usina::dnc {

std::string_view station_state_name(StationState s) {
  switch (s) {
  case StationState::Offline: return "offline";
  case StationState::Idle: return "idle";
  case StationState::Receiving: return "receiving";
  case StationState::Sending: return "sending";
  }
  return "?";
}

Station::Station(asio::io_context& io, LinkConfig config, StationEvents events,
                 std::chrono::duration<double> reopen_after)
    : io_(io),
      config_(std::move(config)),
      events_(std::move(events)),
      reopen_after_(reopen_after),
      reopen_(io) {}

void Station::set_state(StationState s) {
  if (s == state_) return;
  state_ = s;
  if (events_.state) events_.state(s);
}

void Station::start() {
  open();
}

void Station::start(std::unique_ptr<Link> link) {
  link_ = std::move(link);
  to_idle();
}

void Station::shutdown() {
  shut_ = true;
  reopen_.cancel();
  if (sender_) sender_->stop();
  if (receiver_) receiver_->stop();
  if (link_) link_->close();
  set_state(StationState::Offline);
}

void Station::open() {
  async_open_link(
      io_, config_,
      [self = shared_from_this()](std::unique_ptr<Link> link, const std::string& error) {
        if (self->shut_) return;
        if (!link) {
          if (self->events_.link_error) self->events_.link_error(error);
          self->lost();
          return;
        }
        self->link_ = std::move(link);
        self->to_idle();
      });
}

void Station::to_idle() {
  sender_.reset();
  receiver_.reset();
  set_state(StationState::Idle);
  listen();
}

// Idle: whatever arrives is the start of a punch.
void Station::listen() {
  const std::uint64_t generation = ++listen_generation_;
  link_->async_read_some(
      in_, [self = shared_from_this(), generation](const ErrorCode& ec, std::size_t n) {
        if (self->shut_ || generation != self->listen_generation_ ||
            self->state_ != StationState::Idle) {
          return;  // a job took the link meanwhile
        }
        if (ec) {
          self->lost();
          return;
        }
        self->on_punch_start(n);
      });
}

void Station::on_punch_start(std::size_t n) {
  set_state(StationState::Receiving);
  receiver_ = std::make_shared<Receiver>(io_, *link_, receive_options(config_));
  receiver_->feed_first(std::span<const std::uint8_t>(in_.data(), n));
  receiver_->start([self = shared_from_this()](const ReceivedProgram& r) { self->on_received(r); });
}

void Station::on_received(const ReceivedProgram& received) {
  receiver_.reset();
  if (received.end == ReceivedProgram::End::LinkLost) {
    if (events_.punched && !received.text.empty()) events_.punched(received);
    lost();
    return;
  }
  if (events_.request && received.good()) {
    set_state(StationState::Sending);
    const bool request = answer_remote_request(
        io_, *link_, config_, received, events_.request,
        [self = shared_from_this()](const JobReport& r) {
          if (self->events_.request_answered) self->events_.request_answered(r);
          if (r.state == JobState::Interrupted && r.reason.find("link lost") != std::string::npos) {
            self->lost();
          } else {
            self->to_idle();
          }
        });
    if (request) return;
  }
  if (events_.punched) events_.punched(received);
  to_idle();
}

bool Station::submit(std::unique_ptr<ProgramSource> program, JobMode mode, Sender::DoneHandler done,
                     std::string* why) {
  if (state_ != StationState::Idle) {
    if (why != nullptr)
      *why = std::string("the machine is ") + std::string(station_state_name(state_));
    return false;
  }
  ++listen_generation_;
  link_->cancel();  // the idle read
  set_state(StationState::Sending);
  sender_ = std::make_shared<Sender>(io_, *link_, send_options(config_), std::move(program), mode);
  sender_->start([self = shared_from_this(), done = std::move(done)](const JobReport& r) {
    if (done) done(r);
    if (self->shut_) return;
    if (r.state == JobState::Interrupted && r.reason.find("link lost") != std::string::npos) {
      self->lost();
    } else {
      self->to_idle();
    }
  });
  return true;
}

void Station::stop_job() {
  if (sender_) sender_->stop();
}

void Station::lost() {
  sender_.reset();
  receiver_.reset();
  if (link_) link_->close();
  set_state(StationState::Offline);
  if (shut_ || config_.port.empty()) return;
  reopen_.expires_after(
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(reopen_after_));
  reopen_.async_wait([self = shared_from_this()](const ErrorCode& ec) {
    if (!ec && !self->shut_) self->open();
  });
}

}  // namespace usina::dnc
