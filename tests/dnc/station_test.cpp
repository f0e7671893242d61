#include "dnc/station.hpp"

#include <gtest/gtest.h>

#include "dnc/link_memory.hpp"
#include "dnc/sim_cnc.hpp"
#include "dnc_test_util.hpp"

namespace usina::dnc {
namespace {

LinkConfig machine() {
  LinkConfig c;
  c.name = "m1";
  c.code = TapeCode::Ascii;
  c.data_bits = 8;
  c.parity = Parity::None;
  c.leader = 0;
  c.trailer = 0;
  c.receive_idle = 0.2;
  return c;
}

void punch(Link& control, const std::string& rows) {
  auto keep = std::make_shared<std::string>(rows);
  control.async_write(std::span<const std::uint8_t>(
                          reinterpret_cast<const std::uint8_t*>(keep->data()), keep->size()),
                      [keep](const ErrorCode&, std::size_t) {});
}

TEST(Station, APunchWhileIdleIsReceivedAndHandedOn) {
  asio::io_context io;
  LinkPair links = memory_link_pair(io);
  std::vector<ReceivedProgram> punches;
  StationEvents events;
  events.punched = [&](const ReceivedProgram& r) { punches.push_back(r); };
  auto station = std::make_shared<Station>(io, machine(), events);
  station->start(std::move(links.a));
  punch(*links.b, "\x12%\nO4321\nG0 X1\nM30\n%\x14");
  test::run_until(io, [&] { return !punches.empty() && station->state() == StationState::Idle; });
  ASSERT_EQ(punches.size(), 1U);
  EXPECT_EQ(punches[0].name, "O4321");
  EXPECT_EQ(punches[0].text, "O4321\nG0 X1\nM30\n");
  EXPECT_EQ(station->state(), StationState::Idle);
}

TEST(Station, ARemoteRequestIsAnsweredOnTheSameLink) {
  asio::io_context io;
  LinkPair links = memory_link_pair(io);
  StationEvents events;
  std::string asked;
  JobReport answered;
  events.request = [&](const LinkConfig&, const RemoteRequest& r, AnswerFunction answer) {
    asked = r.program;
    answer(RequestAnswer{string_source("O1234\nM30\n"), {}});
  };
  events.request_answered = [&](const JobReport& r) { answered = r; };
  auto station = std::make_shared<Station>(io, machine(), events);
  station->start(std::move(links.a));
  punch(*links.b, "%\nO9999\n(PRG=1234)\n%");
  std::string got;
  std::array<std::uint8_t, 256> buf{};
  std::function<void(const ErrorCode&, std::size_t)> reader = [&](const ErrorCode& ec,
                                                                  std::size_t n) {
    if (ec) return;
    got.append(reinterpret_cast<const char*>(buf.data()), n);
    links.b->async_read_some(buf, reader);
  };
  links.b->async_read_some(buf, reader);
  test::run_until(io, [&] { return answered.state == JobState::Done && got.size() >= 13; });
  EXPECT_EQ(asked, "1234");
  EXPECT_EQ(got, "%\nO1234\nM30\n%");
}

TEST(Station, AJobTakesTheLinkAndGivesItBack) {
  asio::io_context io;
  LinkPair links = memory_link_pair(io);
  std::vector<StationState> states;
  StationEvents events;
  events.state = [&](StationState s) { states.push_back(s); };
  auto station = std::make_shared<Station>(io, machine(), events);
  station->start(std::move(links.a));
  auto sim = std::make_shared<SimCnc>(io, *links.b, SimCncConfig{});
  sim->start();
  JobReport report;
  std::string why;
  ASSERT_TRUE(station->submit(
      string_source("O1\nM30\n"), JobMode::Drip, [&](const JobReport& r) { report = r; }, &why));
  EXPECT_FALSE(station->submit(string_source("O2\n"), JobMode::Send, nullptr, &why));
  EXPECT_EQ(why, "the machine is sending");
  test::run_until(
      io, [&] { return report.state == JobState::Done && station->state() == StationState::Idle; });
  EXPECT_EQ(report.state, JobState::Done);
  EXPECT_EQ(station->state(), StationState::Idle);
  const std::vector<StationState> want{StationState::Idle, StationState::Sending,
                                       StationState::Idle};
  EXPECT_EQ(states, want);
}

TEST(Station, ALostLinkMakesTheMachineOfflineAndTheJobInterrupted) {
  asio::io_context io;
  LinkPair links = memory_link_pair(io, 64);
  StationEvents events;
  auto station = std::make_shared<Station>(io, machine(), events);
  station->start(std::move(links.a));
  SimCncConfig sc;
  sc.drop_link_at = 1000;
  auto sim = std::make_shared<SimCnc>(io, *links.b, sc);
  sim->start();
  JobReport report;
  std::string why;
  ASSERT_TRUE(station->submit(
      std::make_unique<test::GeneratedProgram>(50000), JobMode::Drip,
      [&](const JobReport& r) { report = r; }, &why));
  test::run_until(io, [&] { return station->state() == StationState::Offline; });
  EXPECT_EQ(report.state, JobState::Interrupted);
  EXPECT_EQ(station->state(), StationState::Offline);
  EXPECT_FALSE(station->submit(string_source("O2\n"), JobMode::Send, nullptr, &why));
  station->shutdown();
}

}  // namespace
}  // namespace usina::dnc
