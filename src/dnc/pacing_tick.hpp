// One timer for every feed on an event loop (issue 13, "Speed"). A drip
// feed waits between chunks for its wire to drain; with a timer per feed,
// 256 machines at 115200 baud wake the loop some 20,000 times a second, and
// each wake-up costs the server a system call to re-arm the timer, an
// epoll_wait and a context switch — more than the writes themselves.
//
// A feed does not need one exact moment: it may write once enough of its
// skid is free (the earliest), and must write before its wire runs dry (the
// latest). The tick takes such windows and fires once, at the first latest
// among them, for every feed whose earliest has come: the fewest wake-ups
// that keep every line busy (the greedy answer to stabbing intervals), each
// wake-up serving many machines. A late loop makes a line idle for a moment,
// never puts more than the skid in flight: that bound is the feed's.
//
// One per io_context (an asio service: `PacingTick::of(io)`), used from the
// loop's thread only, like the loop's timers.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

namespace usina::dnc {

class PacingTick final : public boost::asio::execution_context::service {
 public:
  using Clock = std::chrono::steady_clock;
  using Handler = std::function<void()>;
  using Ticket = std::uint64_t;

  static boost::asio::execution_context::id id;  // NOLINT: asio's service key

  explicit PacingTick(boost::asio::io_context& io);
  PacingTick(const PacingTick&) = delete;
  PacingTick& operator=(const PacingTick&) = delete;
  ~PacingTick() override = default;

  // The loop's tick (made on first use).
  static PacingTick& of(boost::asio::io_context& io);

  // Runs `handler` once, from the loop, not before `earliest` and, when the
  // loop keeps up, by `latest` (a `latest` before `earliest` counts as
  // `earliest`). The ticket cancels it.
  Ticket call_between(Clock::time_point earliest, Clock::time_point latest, Handler handler);
  // The handler is dropped without running; false if it ran or was dropped.
  bool cancel(Ticket ticket);

  std::size_t waiting() const { return waits_.size(); }

  // Times the tick fired (for the tests and the bench).
  std::uint64_t wakeups() const { return wakeups_; }

 private:
  struct Wait {
    Ticket ticket = 0;
    Clock::time_point earliest;
    Clock::time_point latest;
    Handler handler;
  };

  void shutdown() override;
  void arm();
  void fire();
  void take_due(Clock::time_point now, std::vector<Wait>& due);

  boost::asio::steady_timer timer_;
  std::vector<Wait> waits_;
  std::vector<Wait> due_;  // the waits served by this wake-up (kept for its capacity)
  Ticket next_ticket_ = 1;
  std::uint64_t wakeups_ = 0;
  std::uint64_t generation_ = 0;  // tells a cancelled timer wait from the armed one
  Clock::time_point armed_at_ = Clock::time_point::max();
  bool firing_ = false;
};

}  // namespace usina::dnc
