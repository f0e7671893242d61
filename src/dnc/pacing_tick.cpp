#include "dnc/pacing_tick.hpp"

#include <algorithm>
#include <utility>

namespace usina::dnc {

boost::asio::execution_context::id PacingTick::id;

PacingTick::PacingTick(boost::asio::io_context& io)
    : boost::asio::execution_context::service(io), timer_(io) {}

PacingTick& PacingTick::of(boost::asio::io_context& io) {
  return boost::asio::use_service<PacingTick>(io);
}

PacingTick::Ticket PacingTick::call_between(Clock::time_point earliest, Clock::time_point latest,
                                            Handler handler) {
  const Ticket ticket = next_ticket_++;
  latest = std::max(latest, earliest);
  waits_.push_back(Wait{ticket, earliest, latest, std::move(handler)});
  // An armed tick that comes by this latest serves this wait too: no
  // re-arming (a system call) for it.
  if (!firing_ && latest < armed_at_) arm();
  return ticket;
}

bool PacingTick::cancel(Ticket ticket) {
  const auto of_ticket = [ticket](const Wait& w) { return w.ticket == ticket; };
  if (const auto it = std::find_if(waits_.begin(), waits_.end(), of_ticket); it != waits_.end()) {
    if (&*it != &waits_.back()) *it = std::move(waits_.back());
    waits_.pop_back();
    return true;  // the tick may still fire for nothing once; not worth a re-arm
  }
  // Due in the tick now firing, not yet run (cancelled by an earlier handler).
  if (const auto it = std::find_if(due_.begin(), due_.end(), of_ticket);
      it != due_.end() && it->handler) {
    it->handler = nullptr;
    return true;
  }
  return false;
}

void PacingTick::arm() {
  if (waits_.empty()) return;  // a tick still armed fires once for nothing
  const auto first =
      std::min_element(waits_.begin(), waits_.end(),
                       [](const Wait& a, const Wait& b) { return a.latest < b.latest; });
  if (first->latest == armed_at_) return;
  armed_at_ = first->latest;
  const std::uint64_t generation = ++generation_;
  timer_.expires_at(armed_at_);
  timer_.async_wait([this, generation](const boost::system::error_code& ec) {
    // A wait replaced by a sooner one may have completed before it was
    // cancelled: only the armed one fires.
    if (ec || generation != generation_) return;
    fire();
  });
}

void PacingTick::take_due(Clock::time_point now, std::vector<Wait>& due) {
  auto it = waits_.begin();
  while (it != waits_.end()) {
    if (it->earliest <= now) {
      due.push_back(std::move(*it));
      if (&*it != &waits_.back()) *it = std::move(waits_.back());
      waits_.pop_back();
    } else {
      ++it;
    }
  }
}

void PacingTick::fire() {
  armed_at_ = Clock::time_point::max();
  ++wakeups_;
  firing_ = true;
  take_due(Clock::now(), due_);
  // By index: a handler may add waits (to waits_, not due_) or cancel one
  // of due_ (its handler emptied).
  for (std::size_t i = 0; i < due_.size(); ++i) {
    Handler handler = std::move(due_[i].handler);
    due_[i].handler = nullptr;
    if (handler) handler();
  }
  due_.clear();
  firing_ = false;
  arm();
}

void PacingTick::shutdown() {
  // The handlers hold their feeds; the loop is going away with them.
  waits_.clear();
  due_.clear();
}

}  // namespace usina::dnc
