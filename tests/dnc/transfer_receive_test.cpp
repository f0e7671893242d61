// Receiving a punch, and answering a remote request through the server's
// callback, on in-process links.
#include "dnc/transfer_receive.hpp"

#include <boost/asio/write.hpp>
#include <gtest/gtest.h>

#include "dnc/link_memory.hpp"
#include "dnc/sim_cnc.hpp"
#include "dnc/tape_code.hpp"
#include "dnc/tape_writer.hpp"
#include "dnc/transfer_request.hpp"
#include "dnc_test_util.hpp"

namespace usina::dnc {
namespace {

std::vector<std::uint8_t> punched(std::string_view text, const LinkConfig& c) {
  TapeWriter w(tape_format(c));
  std::vector<std::uint8_t> rows{kDc2};
  std::vector<BlockMark> marks;
  EXPECT_TRUE(w.write(text, rows, marks));
  EXPECT_TRUE(w.finish(rows, marks));
  rows.push_back(kDc4);
  return rows;
}

LinkConfig iso8() {
  LinkConfig c;
  c.name = "m1";
  c.data_bits = 8;
  c.parity = Parity::None;
  c.code = TapeCode::Iso;
  return c;
}

ReceivedProgram receive(const std::vector<std::uint8_t>& rows, ReceiveOptions o,
                        bool close_after = false) {
  asio::io_context io;
  LinkPair links = memory_link_pair(io);
  auto receiver = std::make_shared<Receiver>(io, *links.a, o);
  ReceivedProgram got;
  bool done = false;
  receiver->start([&](const ReceivedProgram& r) {
    got = r;
    done = true;
  });
  links.b->async_write(rows, [&](const ErrorCode&, std::size_t) {
    if (close_after) links.b->close();
  });
  test::run_until(io, [&] { return done; });
  EXPECT_TRUE(done);
  return got;
}

TEST(Receive, APunchIsReadNamedAndHashed) {
  const LinkConfig c = iso8();
  const auto rows = punched("%\nO1234 (BRACKET)\nG0 X1\nM30\n%\n", c);
  const ReceivedProgram r = receive(rows, receive_options(c));
  EXPECT_EQ(r.end, ReceivedProgram::End::Complete);
  EXPECT_TRUE(r.good());
  EXPECT_EQ(r.text, "O1234 (BRACKET)\nG0 X1\nM30\n");
  EXPECT_EQ(r.name, "O1234");
}

TEST(Receive, AParityErrorKeepsTheProgramButMarksIt) {
  const LinkConfig c = iso8();
  auto rows = punched("O1\nG0 X12\nM30\n", c);
  rows[24] ^= 0x01;  // in "O1"
  const ReceivedProgram r = receive(rows, receive_options(c));
  EXPECT_FALSE(r.good());
  EXPECT_EQ(r.bad_rows, 1U);
  EXPECT_NE(r.reason.find("parity"), std::string::npos);
}

TEST(Receive, SilenceEndsAPunchWithoutClosingPercent) {
  ReceiveOptions o = receive_options(iso8());
  o.code = TapeCode::Ascii;
  o.check_parity = false;
  o.idle = std::chrono::duration<double>(0.05);
  const std::string text = "%\nO5\nG0 X1\n";
  const ReceivedProgram r = receive(std::vector<std::uint8_t>(text.begin(), text.end()), o);
  EXPECT_EQ(r.end, ReceivedProgram::End::Idle);
  EXPECT_EQ(r.text, "O5\nG0 X1\n");
}

TEST(Receive, ALostLinkEndsThePunch) {
  const std::string text = "%\nO5\nG0";
  const ReceivedProgram r =
      receive(std::vector<std::uint8_t>(text.begin(), text.end()), receive_options(iso8()), true);
  EXPECT_EQ(r.end, ReceivedProgram::End::LinkLost);
}

// The control punches O9999 (PRG=...), the server's callback answers, and
// the program goes back on the same link; a refusal goes back as a short
// program that says why.
struct Served {
  SimCncStats sim;
  std::string data;
  JobReport report;
  RemoteRequest asked;
};

Served serve(std::string_view request, bool grant) {
  asio::io_context io;
  LinkPair links = memory_link_pair(io);
  LinkConfig c = iso8();
  c.code = TapeCode::Ascii;
  c.leader = 0;
  c.trailer = 0;
  ReceivedProgram received;
  received.text = std::string(request);
  Served s;
  SimCncConfig sc;
  sc.keep_data = true;
  auto sim = std::make_shared<SimCnc>(io, *links.b, sc);
  sim->start();
  bool done = false;
  const RequestHandler handler = [&](const LinkConfig& machine, const RemoteRequest& r,
                                     AnswerFunction answer) {
    EXPECT_EQ(machine.name, "m1");
    s.asked = r;
    if (grant) {
      answer(RequestAnswer{string_source("O1234\nG0 X1\nM30\n"), {}});
    } else {
      answer(RequestAnswer{nullptr, "program " + r.program + " is not released"});
    }
  };
  const bool is_request =
      answer_remote_request(io, *links.a, c, received, handler, [&](const JobReport& r) {
        s.report = r;
        done = true;
      });
  EXPECT_TRUE(is_request);
  test::run_until(io, [&] { return done; });
  test::run_until(
      io, [&] { return sim->stats().received >= s.report.bytes_sent; }, std::chrono::seconds(5));
  s.sim = sim->stats();
  s.data.assign(sim->data().begin(), sim->data().end());
  return s;
}

TEST(RemoteRequestServed, TheReleasedProgramIsSent) {
  const Served s = serve("O9999\n(PRG=1234 /BL 20)\n", true);
  EXPECT_EQ(s.asked.program, "1234");
  EXPECT_EQ(s.asked.start_block, 20U);
  EXPECT_EQ(s.report.state, JobState::Done);
  EXPECT_EQ(s.data, "%\nO1234\nG0 X1\nM30\n%");
}

TEST(RemoteRequestServed, ARefusalIsAResponseProgram) {
  const Served s = serve("O9999\n(PRG=77)\n", false);
  EXPECT_EQ(s.data, "%\nO9999\n(USINA PROGRAM 77 IS NOT RELEASED)\nM30\n%");
}

TEST(RemoteRequestServed, AnUnreadableRequestNeverReachesTheHandler) {
  const Served s = serve("O9999\n(PRG=../x)\n", true);
  EXPECT_TRUE(s.asked.program.empty());
  EXPECT_NE(s.data.find("REQUEST REFUSED"), std::string::npos) << s.data;
}

}  // namespace
}  // namespace usina::dnc
