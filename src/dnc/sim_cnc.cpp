#include "dnc/sim_cnc.hpp"

#include <algorithm>
#include <cmath>

namespace usina::dnc {

SimCnc::SimCnc(asio::io_context& io, Link& link, SimCncConfig config)
    : io_(io), link_(link), config_(config), xoff_timer_(io), xon_timer_(io), spurious_timer_(io) {}

std::size_t safe_skid(const SimCncConfig& c, double bytes_per_second) {
  const double reacting = c.xoff_delay_bytes > 0 ? static_cast<double>(c.xoff_delay_bytes)
                                                 : std::ceil(c.xoff_delay * bytes_per_second);
  const double room = static_cast<double>(c.buffer) - static_cast<double>(c.high_water) - reacting;
  return room < 1.0 ? 0 : static_cast<std::size_t>(room);
}

void SimCnc::start() {
  last_ = Clock::now();
  read_loop();
  if (config_.send_initial_xon) send(config_.xon);
  if (config_.spurious_xon_every > 0.0) spurious_loop();
}

void SimCnc::stop() {
  stopped_ = true;
  xoff_timer_.cancel();
  xon_timer_.cancel();
  spurious_timer_.cancel();
}

void SimCnc::read_loop() {
  link_.async_read_some(in_, [self = shared_from_this()](const ErrorCode& ec, std::size_t n) {
    if (ec) {
      self->stats_.link_lost = true;
      self->stop();
      return;
    }
    self->on_bytes(self->in_.data(), n);
    if (!self->stopped_) self->read_loop();
  });
}

// The control runs its program: the buffer empties at execute_rate.
void SimCnc::execute(Clock::time_point now) {
  const double dt = std::chrono::duration<double>(now - last_).count();
  last_ = now;
  if (config_.execute_rate <= 0.0) {
    fill_ = 0.0;
    return;
  }
  fill_ = std::max(0.0, fill_ - dt * config_.execute_rate);
}

void SimCnc::on_bytes(const std::uint8_t* p, std::size_t n) {
  if (config_.drop_link_at > 0) {
    const std::uint64_t left =
        config_.drop_link_at - std::min(config_.drop_link_at, stats_.received);
    n = static_cast<std::size_t>(std::min<std::uint64_t>(n, left));
  }
  execute(Clock::now());
  sha_.update(std::span<const std::uint8_t>(p, n));
  if (config_.keep_data) data_.insert(data_.end(), p, p + n);
  // Most reads find the buffer far from high water: counted at once.
  const double free_below_high = static_cast<double>(config_.high_water) - fill_;
  if (!xoff_pending_ && !xoff_asserted_ && static_cast<double>(n) + 1.0 < free_below_high) {
    stats_.received += n;
    fill_ = config_.execute_rate <= 0.0 ? 0.0 : fill_ + static_cast<double>(n);
    stats_.max_fill = std::max(stats_.max_fill, static_cast<std::size_t>(fill_));
    n = 0;
  }
  for (std::size_t i = 0; i < n; ++i) {
    ++stats_.received;
    if (xoff_asserted_) stats_.max_after_xoff = std::max(stats_.max_after_xoff, ++after_xoff_);
    if (fill_ + 1.0 > static_cast<double>(config_.buffer)) {
      ++stats_.overflow;
    } else {
      fill_ += 1.0;
    }
    if (config_.execute_rate <= 0.0) fill_ = 0.0;
    stats_.max_fill = std::max(stats_.max_fill, static_cast<std::size_t>(fill_));
    if (xoff_pending_ && config_.xoff_delay_bytes > 0 &&
        ++since_high_ >= config_.xoff_delay_bytes) {
      send_xoff();
    }
    if (!xoff_pending_ && !xoff_asserted_ && fill_ >= static_cast<double>(config_.high_water)) {
      xoff_pending_ = true;
      since_high_ = 0;
      if (config_.xoff_delay <= 0.0 && config_.xoff_delay_bytes == 0) {
        send_xoff();
      } else if (config_.xoff_delay > 0.0) {
        xoff_timer_.expires_after(std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(config_.xoff_delay)));
        xoff_timer_.async_wait([self = shared_from_this()](const ErrorCode& ec) {
          if (!ec && !self->stopped_ && self->xoff_pending_) self->send_xoff();
        });
      }
    }
  }
  if (config_.drop_link_at > 0 && stats_.received >= config_.drop_link_at) {
    stats_.link_lost = true;
    stop();
    link_.close();
  }
}

void SimCnc::send_xoff() {
  xoff_pending_ = false;
  xoff_timer_.cancel();
  xoff_asserted_ = true;
  after_xoff_ = 0;
  ++stats_.xoff_sent;
  send(config_.xoff);
  schedule();
}

// Wakes when the buffer should be down to low water, to send the XON.
void SimCnc::schedule() {
  if (config_.lose_xon || stopped_) return;
  execute(Clock::now());
  if (fill_ <= static_cast<double>(config_.low_water)) {
    xoff_asserted_ = false;
    ++stats_.xon_sent;
    send(config_.xon);
    return;
  }
  const double wait = (fill_ - static_cast<double>(config_.low_water)) / config_.execute_rate;
  xon_timer_.expires_after(
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(wait)));
  xon_timer_.async_wait([self = shared_from_this()](const ErrorCode& ec) {
    if (!ec) self->schedule();
  });
}

void SimCnc::spurious_loop() {
  spurious_timer_.expires_after(std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(config_.spurious_xon_every)));
  spurious_timer_.async_wait([self = shared_from_this()](const ErrorCode& ec) {
    if (ec || self->stopped_) return;
    if (!self->xoff_asserted_) self->send(self->config_.xon);
    self->spurious_loop();
  });
}

void SimCnc::send(std::uint8_t b) {
  out_queue_.push_back(b);
  write_next();
}

void SimCnc::write_next() {
  if (writing_ || out_queue_.empty() || stopped_) return;
  const std::size_t n = std::min(out_queue_.size(), out_.size());
  std::copy_n(out_queue_.begin(), n, out_.begin());
  out_queue_.erase(out_queue_.begin(), out_queue_.begin() + static_cast<std::ptrdiff_t>(n));
  writing_ = true;
  link_.async_write(std::span<const std::uint8_t>(out_.data(), n),
                    [self = shared_from_this()](const ErrorCode& ec, std::size_t) {
                      self->writing_ = false;
                      if (ec) {
                        self->stats_.link_lost = true;
                        return;
                      }
                      self->write_next();
                    });
}

}  // namespace usina::dnc
