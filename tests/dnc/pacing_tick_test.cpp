// The one pacing timer of an event loop: windows, coalesced wake-ups,
// cancellation, handlers that wait again.
#include "dnc/pacing_tick.hpp"

#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "dnc_test_util.hpp"

namespace usina::dnc {
namespace {

using Clock = PacingTick::Clock;
using std::chrono::milliseconds;

TEST(PacingTick, OneTickPerLoop) {
  boost::asio::io_context io;
  boost::asio::io_context other;
  EXPECT_EQ(&PacingTick::of(io), &PacingTick::of(io));
  EXPECT_NE(&PacingTick::of(io), &PacingTick::of(other));
}

TEST(PacingTick, AHandlerRunsNotBeforeItsEarliest) {
  boost::asio::io_context io;
  PacingTick& tick = PacingTick::of(io);
  const auto earliest = Clock::now() + milliseconds(30);
  Clock::time_point ran{};
  tick.call_between(earliest, earliest + milliseconds(20), [&] { ran = Clock::now(); });
  EXPECT_EQ(tick.waiting(), 1U);
  test::run_until(io, [&] { return ran != Clock::time_point{}; });
  EXPECT_GE(ran, earliest);
  EXPECT_EQ(tick.waiting(), 0U);
}

TEST(PacingTick, ALatestBeforeTheEarliestCountsAsTheEarliest) {
  boost::asio::io_context io;
  const auto earliest = Clock::now() + milliseconds(30);
  Clock::time_point ran{};
  PacingTick::of(io).call_between(earliest, earliest - milliseconds(20),
                                  [&] { ran = Clock::now(); });
  test::run_until(io, [&] { return ran != Clock::time_point{}; });
  EXPECT_GE(ran, earliest);
}

// Two feeds whose windows overlap are served by one wake-up, at the first
// latest: by then the second's earliest has come too.
TEST(PacingTick, OverlappingWindowsShareOneWakeup) {
  boost::asio::io_context io;
  PacingTick& tick = PacingTick::of(io);
  const auto now = Clock::now();
  int ran = 0;
  tick.call_between(now + milliseconds(10), now + milliseconds(40), [&] { ++ran; });
  tick.call_between(now + milliseconds(30), now + milliseconds(80), [&] { ++ran; });
  tick.call_between(now, now + milliseconds(60), [&] { ++ran; });
  test::run_until(io, [&] { return ran == 3; });
  EXPECT_EQ(ran, 3);
  EXPECT_EQ(tick.wakeups(), 1U);
}

TEST(PacingTick, SeparateWindowsRunInTheirOrder) {
  boost::asio::io_context io;
  PacingTick& tick = PacingTick::of(io);
  const auto now = Clock::now();
  std::vector<int> order;
  Clock::time_point second_ran{};
  tick.call_between(now + milliseconds(200), now + milliseconds(210), [&] {
    order.push_back(2);
    second_ran = Clock::now();
  });
  tick.call_between(now, now + milliseconds(5), [&] { order.push_back(1); });
  test::run_until(io, [&] { return order.size() == 2; });
  EXPECT_EQ(order, (std::vector<int>{1, 2}));
  EXPECT_GE(second_ran, now + milliseconds(200));
}

TEST(PacingTick, ACancelledWaitNeverRunsAndLetsGoOfItsHandler) {
  boost::asio::io_context io;
  PacingTick& tick = PacingTick::of(io);
  auto held = std::make_shared<int>(0);
  std::weak_ptr<int> watch = held;
  bool ran = false;
  const auto now = Clock::now();
  const auto ticket = tick.call_between(now, now + milliseconds(20),
                                        [&ran, held = std::move(held)] { ran = true; });
  EXPECT_TRUE(tick.cancel(ticket));
  EXPECT_TRUE(watch.expired());
  EXPECT_FALSE(tick.cancel(ticket));
  bool other = false;
  tick.call_between(now + milliseconds(40), now + milliseconds(50), [&] { other = true; });
  test::run_until(io, [&] { return other; });
  EXPECT_FALSE(ran);
  EXPECT_FALSE(tick.cancel(12345));
}

// A handler may wait again (the feed's next chunk) and may cancel a wait
// that is due in the same wake-up (a feed stopping another's job).
TEST(PacingTick, AHandlerMayWaitAgainOrCancelAnotherDueNow) {
  boost::asio::io_context io;
  PacingTick& tick = PacingTick::of(io);
  const auto now = Clock::now();
  PacingTick::Ticket second = 0;
  bool second_ran = false;
  bool again_ran = false;
  tick.call_between(now, now + milliseconds(10), [&] {
    EXPECT_TRUE(tick.cancel(second));
    tick.call_between(Clock::now(), Clock::now() + milliseconds(10), [&] { again_ran = true; });
  });
  second = tick.call_between(now, now + milliseconds(10), [&] { second_ran = true; });
  test::run_until(io, [&] { return again_ran; });
  EXPECT_TRUE(again_ran);
  EXPECT_FALSE(second_ran);
  EXPECT_EQ(tick.waiting(), 0U);
}

// A sooner wait re-arms the tick; a later one rides on the armed tick.
TEST(PacingTick, ASoonerWaitIsNotHeldBackByALaterOne) {
  boost::asio::io_context io;
  PacingTick& tick = PacingTick::of(io);
  const auto now = Clock::now();
  bool late = false;
  bool soon = false;
  tick.call_between(now + milliseconds(5000), now + milliseconds(6000), [&] { late = true; });
  tick.call_between(now, now + milliseconds(10), [&] { soon = true; });
  test::run_until(
      io, [&] { return soon; }, std::chrono::seconds(3));
  EXPECT_TRUE(soon);
  EXPECT_FALSE(late);
  EXPECT_EQ(tick.waiting(), 1U);
}

TEST(PacingTick, TheLoopGoingAwayLetsGoOfTheWaits) {
  auto held = std::make_shared<int>(0);
  std::weak_ptr<int> watch = held;
  {
    boost::asio::io_context io;
    PacingTick::of(io).call_between(Clock::now() + milliseconds(100),
                                    Clock::now() + milliseconds(200), [held = std::move(held)] {});
    EXPECT_FALSE(watch.expired());
  }
  EXPECT_TRUE(watch.expired());
}

}  // namespace
}  // namespace usina::dnc
