// The links themselves: a pty opened as a serial port (termios raw, the
// real code path), a socat pty pair, raw TCP in both directions.
#include "dnc/link.hpp"

#include <termios.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <thread>

#include <boost/asio/ip/tcp.hpp>
#include <gtest/gtest.h>
#include <sys/socket.h>

#include "dnc/link_serial.hpp"
#include "dnc/sim_cnc.hpp"
#include "dnc/transfer_send.hpp"
#include "dnc_test_util.hpp"

namespace usina::dnc {
namespace {

LinkConfig pty_machine(const std::string& path) {
  LinkConfig c;
  c.name = "pty";
  c.port = path;
  c.baud = 115200;
  c.code = TapeCode::Iso;
  c.leader = 4;
  c.trailer = 4;
  c.skid = 64;
  return c;
}

std::unique_ptr<Link> open_now(asio::io_context& io, const LinkConfig& c, std::string* error) {
  std::unique_ptr<Link> link;
  bool done = false;
  async_open_link(io, c, [&](std::unique_ptr<Link> l, const std::string& e) {
    link = std::move(l);
    *error = e;
    done = true;
  });
  test::run_until(io, [&] { return done; });
  return link;
}

// A pty pair with its slave opened as the machine's serial port (the real
// code path); a failure to open either fails the test that asked.
struct PtyLink {
  std::optional<PtyPair> pair;
  std::unique_ptr<Link> link;
};

void open_pty_link(asio::io_context& io, PtyLink& out) {
  auto pair = open_pty_pair(io);
  ASSERT_TRUE(pair) << pair.error();
  out.pair = std::move(*pair);
  std::string error;
  out.link = open_now(io, pty_machine(out.pair->slave_path), &error);
  ASSERT_TRUE(out.link) << error;
}

struct Fed {
  JobReport report;
  SimCncStats sim;
  std::string sim_sha;
};

Fed feed(asio::io_context& io, Link& ours, Link& theirs, const LinkConfig& c,
         std::unique_ptr<ProgramSource> program, SimCncConfig sc = {}) {
  auto sim = std::make_shared<SimCnc>(io, theirs, sc);
  auto sender =
      std::make_shared<Sender>(io, ours, send_options(c), std::move(program), JobMode::Drip);
  Fed f;
  bool done = false;
  sim->start();
  sender->start([&](const JobReport& r) {
    f.report = r;
    done = true;
  });
  test::run_until(io, [&] { return done; });
  if (f.report.state == JobState::Done) {
    test::run_until(
        io, [&] { return sim->stats().received >= f.report.bytes_sent; }, std::chrono::seconds(5));
  }
  sim->stop();
  f.sim = sim->stats();
  f.sim_sha = sim->sha256();
  return f;
}

TEST(SerialLink, APtyTakesTheRawFrameWithIxonOff) {
  asio::io_context io;
  PtyLink p;
  ASSERT_NO_FATAL_FAILURE(open_pty_link(io, p));  // the link sets the slave's termios
  const int fd = ::open(p.pair->slave_path.c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(fd, 0);
  termios t{};
  ASSERT_EQ(::tcgetattr(fd, &t), 0);
  EXPECT_EQ(t.c_iflag & (IXON | IXOFF | ICRNL), 0U);
  EXPECT_EQ(t.c_lflag & (ICANON | ECHO), 0U);
  // A pty keeps no frame (data bits, parity, stop bits are the UART's).
  ::close(fd);
}

// The control and usina share one event loop here, and a pty delivers at
// once whatever was written: when the machine is loaded and the loop stalls,
// usina's pacing (by the baud rate's clock) can have sent several chunks
// before the control reads any, a burst no UART would deliver. The control
// has room for such a burst (4 KB, some 350 ms of line); what the test holds
// usina to is the handshake: XOFF is sent, and at most the skid arrives
// after one.
TEST(SerialLink, ADripFeedOverAPtyArrivesWhole) {
  asio::io_context io;
  auto pair = open_pty_pair(io);
  ASSERT_TRUE(pair) << pair.error();
  std::string error;
  const LinkConfig c = pty_machine(pair->slave_path);
  auto link = open_now(io, c, &error);
  ASSERT_TRUE(link) << error;
  SimCncConfig sc;
  sc.buffer = 4096;
  sc.high_water = 256;
  sc.low_water = 64;
  sc.execute_rate = 8000;
  const Fed f =
      feed(io, *link, *pair->master, c, std::make_unique<test::GeneratedProgram>(8000), sc);
  EXPECT_EQ(f.report.state, JobState::Done) << f.report.reason;
  EXPECT_EQ(f.sim.received, f.report.bytes_sent);
  EXPECT_EQ(f.sim_sha, f.report.sha256);
  EXPECT_GT(f.sim.xoff_sent, 0U);
  EXPECT_EQ(f.sim.overflow, 0U);
  EXPECT_LE(f.sim.max_after_xoff, c.skid) << "max fill " << f.sim.max_fill;
}

TEST(SerialLink, ClosingThePtyMasterInterruptsTheFeed) {
  asio::io_context io;
  auto pair = open_pty_pair(io);
  ASSERT_TRUE(pair) << pair.error();
  std::string error;
  const LinkConfig c = pty_machine(pair->slave_path);
  auto link = open_now(io, c, &error);
  ASSERT_TRUE(link) << error;
  SimCncConfig sc;
  sc.drop_link_at = 5000;
  const Fed f =
      feed(io, *link, *pair->master, c, std::make_unique<test::GeneratedProgram>(100000), sc);
  EXPECT_EQ(f.report.state, JobState::Interrupted) << f.report.reason;
  EXPECT_GE(f.report.bytes_sent, 5000U);
  EXPECT_EQ(f.sim.received, 5000U);
}

// Linux's pty keeps no output queue (TIOCOUTQ is always 0), so a pty link
// says it cannot tell rather than have a feed ask before every chunk; a
// socket's count still answers.
TEST(SerialLink, APtyDoesNotCountItsOutputAndASocketDoes) {
  asio::io_context io;
  PtyLink p;
  ASSERT_NO_FATAL_FAILURE(open_pty_link(io, p));
  auto& pair = p.pair;
  auto& link = p.link;
  EXPECT_FALSE(link->output_queue());
  EXPECT_FALSE(pair->master->output_queue());
  std::array<int, 2> fds{};
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, fds.data()), 0);
  auto socket_link = descriptor_link(io, fds[0], "socket");
  EXPECT_TRUE(socket_link->output_queue());
  ::close(fds[1]);
}

// A chunk is written at once where the link can; a full pty says 0 (the
// feed then waits through the loop) instead of blocking the loop; a pty
// whose other end closed is an error.
TEST(SerialLink, TryWriteWritesAtOnceNeverBlocksAndReportsALostPeer) {
  asio::io_context io;
  PtyLink p;
  ASSERT_NO_FATAL_FAILURE(open_pty_link(io, p));
  auto& pair = p.pair;
  auto& link = p.link;
  const std::string text = "%\nO1\n";
  ErrorCode ec;
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(text.data());
  EXPECT_EQ(link->try_write(std::span(bytes, text.size()), ec), text.size());
  EXPECT_FALSE(ec) << ec.message();
  std::array<std::uint8_t, 64> got{};
  std::size_t read = 0;
  pair->master->async_read_some(got, [&](const ErrorCode& e, std::size_t n) {
    EXPECT_FALSE(e) << e.message();
    read = n;
  });
  test::run_until(io, [&] { return read > 0; });
  EXPECT_EQ(std::string(got.begin(), got.begin() + static_cast<std::ptrdiff_t>(read)), text);

  const std::vector<std::uint8_t> block(4096, 'X');
  std::optional<std::size_t> took;
  for (int i = 0; i < 10000; ++i) {  // nobody reads the master: the pty fills
    took = link->try_write(block, ec);
    if (ec || took.value_or(0) == 0) break;
  }
  EXPECT_FALSE(ec) << ec.message();
  EXPECT_EQ(took, 0U);

  pair->master->close();
  took = link->try_write(std::span(bytes, text.size()), ec);
  EXPECT_TRUE(ec);
  EXPECT_FALSE(took);
}

TEST(SerialLink, AMissingDeviceIsAnErrorNamingIt) {
  asio::io_context io;
  std::string error;
  auto link = open_now(io, pty_machine("/dev/usina-no-such-tty"), &error);
  EXPECT_FALSE(link);
  EXPECT_NE(error.find("/dev/usina-no-such-tty"), std::string::npos) << error;
}

// socat's pty pair, as research/dnc.md §6 plans: usina on one end as on a
// serial port, the simulated control on the other.
TEST(SerialLink, ASocatPtyPairCarriesAFeed) {
  if (std::system("command -v socat > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "socat is not installed";
  const auto dir =
      std::filesystem::temp_directory_path() / ("usina-socat-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string a = (dir / "a").string();
  const std::string b = (dir / "b").string();
  const std::string cmd = "socat pty,raw,echo=0,link=" + a + " pty,raw,echo=0,link=" + b + " 2> " +
                          (dir / "log").string() + " & echo $! > " + (dir / "pid").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  for (int i = 0; i < 200 && !(std::filesystem::exists(a) && std::filesystem::exists(b)); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(25));
  ASSERT_TRUE(std::filesystem::exists(a) && std::filesystem::exists(b));
  {
    asio::io_context io;
    std::string error;
    LinkConfig ca = pty_machine(a);
    auto ours = open_now(io, ca, &error);
    ASSERT_TRUE(ours) << error;
    LinkConfig cb = pty_machine(b);
    auto theirs = open_now(io, cb, &error);
    ASSERT_TRUE(theirs) << error;
    const Fed f = feed(io, *ours, *theirs, ca, std::make_unique<test::GeneratedProgram>(8000));
    EXPECT_EQ(f.report.state, JobState::Done) << f.report.reason;
    EXPECT_EQ(f.sim.received, f.report.bytes_sent);
    EXPECT_EQ(f.sim_sha, f.report.sha256);
  }
  // socat removes its links as it exits: wait for it, so the folder is not
  // emptied under its feet (remove_all threw when a link vanished first).
  const std::string kill = "p=$(cat " + (dir / "pid").string() +
                           "); kill $p && while kill -0 $p 2> /dev/null; do sleep 0.01; done";
  EXPECT_EQ(std::system(kill.c_str()), 0);
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  EXPECT_FALSE(ec) << ec.message();
}

// A device server that usina connects to, and one that connects to usina.
TEST(TcpLink, ClientAndListeningModesCarryAFeed) {
  using tcp = asio::ip::tcp;
  asio::io_context io;
  tcp::acceptor acceptor(io, tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
  const auto port = acceptor.local_endpoint().port();
  LinkConfig c = pty_machine("tcp://127.0.0.1:" + std::to_string(port));
  std::unique_ptr<Link> ours;
  std::unique_ptr<Link> theirs;
  async_open_link(io, c, [&](std::unique_ptr<Link> l, const std::string& e) {
    EXPECT_TRUE(l) << e;
    ours = std::move(l);
  });
  // The "device server" side: a plain accepted socket, wrapped by a second
  // usina link in listening mode is tested below.
  tcp::socket server_side(io);
  bool accepted = false;
  acceptor.async_accept(server_side, [&](const ErrorCode& ec) { accepted = !ec; });
  test::run_until(io, [&] { return ours && accepted; });
  ASSERT_TRUE(ours && accepted);
  const int fd = ::dup(server_side.native_handle());
  theirs = descriptor_link(io, fd, "device server");
  const Fed f = feed(io, *ours, *theirs, c, std::make_unique<test::GeneratedProgram>(8000));
  EXPECT_EQ(f.report.state, JobState::Done) << f.report.reason;
  EXPECT_EQ(f.sim_sha, f.report.sha256);

  // Listening: usina waits, the device server connects.
  tcp::acceptor probe(io, tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
  const auto listen_port = probe.local_endpoint().port();
  probe.close();
  LinkConfig l = pty_machine("tcp-listen://127.0.0.1:" + std::to_string(listen_port));
  std::unique_ptr<Link> listened;
  async_open_link(io, l, [&](std::unique_ptr<Link> link, const std::string& e) {
    EXPECT_TRUE(link) << e;
    listened = std::move(link);
  });
  tcp::socket device(io);
  device.async_connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), listen_port),
                       [](const ErrorCode& ec) { EXPECT_FALSE(ec) << ec.message(); });
  test::run_until(io, [&] { return listened != nullptr; });
  ASSERT_TRUE(listened);
  auto device_link = descriptor_link(io, ::dup(device.native_handle()), "device");
  const Fed g = feed(io, *listened, *device_link, l, string_source("O7\nG0 X1\nM30\n"));
  EXPECT_EQ(g.report.state, JobState::Done) << g.report.reason;
  EXPECT_EQ(g.sim_sha, g.report.sha256);
}

TEST(TcpLink, ARefusedConnectionIsAnError) {
  asio::io_context io;
  asio::ip::tcp::acceptor probe(io,
                                asio::ip::tcp::endpoint(asio::ip::make_address("127.0.0.1"), 0));
  const auto port = probe.local_endpoint().port();
  probe.close();
  std::string error;
  auto link = open_now(io, pty_machine("tcp://127.0.0.1:" + std::to_string(port)), &error);
  EXPECT_FALSE(link);
  EXPECT_NE(error.find("cannot connect"), std::string::npos) << error;
}

}  // namespace
}  // namespace usina::dnc
