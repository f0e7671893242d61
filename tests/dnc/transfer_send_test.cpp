// Send and drip feed against the simulated control, on in-process links.
#include "dnc/transfer_send.hpp"

#include <random>

#include <gtest/gtest.h>
#include <sys/resource.h>

#include "dnc/link_memory.hpp"
#include "dnc/sim_cnc.hpp"
#include "dnc_test_util.hpp"

namespace usina::dnc {
namespace {

SendOptions ascii_options(std::uint32_t skid, double rate) {
  SendOptions o;
  o.format = TapeFormat{TapeCode::Ascii, EndOfBlock::Lf, 0, 0, false};
  o.code = TapeCode::Ascii;
  o.flow = Flow::XonXoff;
  o.skid = skid;
  o.bytes_per_second = rate;
  return o;
}

struct JobRun {
  JobReport report;
  SimCncStats sim;
  std::string sim_sha;
  std::vector<std::uint8_t> sim_data;
};

JobRun run_job(SendOptions options, std::unique_ptr<ProgramSource> program, SimCncConfig sim_config,
               std::size_t pipe = 4096) {
  asio::io_context io;
  LinkPair links = memory_link_pair(io, pipe);
  auto sim = std::make_shared<SimCnc>(io, *links.b, sim_config);
  auto sender = std::make_shared<Sender>(io, *links.a, options, std::move(program), JobMode::Drip);
  bool done = false;
  JobRun run;
  sim->start();
  sender->start([&](const JobReport& r) {
    run.report = r;
    done = true;
  });
  test::run_until(io, [&] { return done; });
  // Let the last bytes reach the control before reading its counts.
  if (run.report.state == JobState::Done) {
    test::run_until(
        io, [&] { return sim->stats().received >= run.report.bytes_sent; },
        std::chrono::seconds(5));
  }
  EXPECT_TRUE(done);
  sim->stop();
  run.sim = sim->stats();
  run.sim_sha = sim->sha256();
  run.sim_data = sim->data();
  return run;
}

TEST(Send, AProgramArrivesWholeAndTheHashesAgree) {
  SimCncConfig sim;
  sim.keep_data = true;
  const JobRun r = run_job(ascii_options(64, 0), string_source("O1\nG0 X1\nM30\n"), sim);
  EXPECT_EQ(r.report.state, JobState::Done) << r.report.reason;
  EXPECT_EQ(std::string(r.sim_data.begin(), r.sim_data.end()), "%\nO1\nG0 X1\nM30\n%");
  EXPECT_EQ(r.report.bytes_sent, 16U);
  EXPECT_EQ(r.report.sha256, r.sim_sha);
  EXPECT_EQ(r.report.sha256, sha256_hex(std::string_view("%\nO1\nG0 X1\nM30\n%")));
  EXPECT_EQ(r.report.line, 3U);
}

TEST(Send, ACharacterWithoutCodeFailsTheJobBeforeAnyByte) {
  SendOptions o = ascii_options(64, 0);
  o.format.code = TapeCode::Eia;
  o.code = TapeCode::Eia;
  const JobRun r = run_job(o, string_source("O1\n#1=2\n"), SimCncConfig{});
  EXPECT_EQ(r.report.state, JobState::Failed);
  EXPECT_NE(r.report.reason.find("no eia tape code"), std::string::npos) << r.report.reason;
  EXPECT_EQ(r.sim.received, 0U);
}

// research/dnc.md §6.2: zero overflow for every buffer and reaction delay,
// with the skid the control's room allows; and the bytes after each XOFF
// within that skid.
TEST(DripFeed, ZeroOverflowForEveryBufferAndDelay) {
  const double rate = 100000.0;  // bytes a second on the simulated line
  for (const std::size_t buffer : {64U, 256U, 1024U}) {
    for (const std::size_t delay_bytes : {0U, 4U, 16U}) {
      SimCncConfig sim;
      sim.buffer = buffer;
      sim.high_water = buffer / 2;
      sim.low_water = buffer / 4;
      sim.xoff_delay_bytes = delay_bytes;
      sim.xoff_delay = 0.0;
      sim.execute_rate = rate / 4;  // the control runs slower than the line: XOFFs come
      const std::size_t skid = safe_skid(sim, rate);
      ASSERT_GT(skid, 0U);
      const std::uint64_t size = 4 * buffer + 2000;
      const JobRun r = run_job(ascii_options(static_cast<std::uint32_t>(skid), rate),
                               std::make_unique<test::GeneratedProgram>(size), sim);
      SCOPED_TRACE(testing::Message()
                   << "buffer " << buffer << " delay " << delay_bytes << " skid " << skid);
      EXPECT_EQ(r.report.state, JobState::Done) << r.report.reason;
      EXPECT_EQ(r.sim.overflow, 0U);
      EXPECT_GT(r.sim.xoff_sent, 0U);
      EXPECT_LE(r.sim.max_after_xoff, skid);
      EXPECT_LE(r.report.max_in_flight_at_xoff, static_cast<double>(skid));
      EXPECT_EQ(r.sim.received, r.report.bytes_sent);
      EXPECT_EQ(r.sim_sha, r.report.sha256);
    }
  }
}

// The simulator can see an overflow: a skid larger than the room overruns.
TEST(DripFeed, ASkidLargerThanTheRoomOverflowsTheSimulator) {
  SimCncConfig sim;
  sim.buffer = 64;
  sim.high_water = 60;
  sim.low_water = 16;
  sim.execute_rate = 1000.0;
  const JobRun r =
      run_job(ascii_options(512, 0), std::make_unique<test::GeneratedProgram>(8000), sim);
  EXPECT_GT(r.sim.overflow, 0U);
}

TEST(DripFeed, XonWithoutXoffIsHarmless) {
  SimCncConfig sim;
  sim.spurious_xon_every = 0.001;
  sim.keep_data = true;
  const JobRun r =
      run_job(ascii_options(32, 20000.0), std::make_unique<test::GeneratedProgram>(3000), sim);
  EXPECT_EQ(r.report.state, JobState::Done) << r.report.reason;
  EXPECT_GT(r.report.xon_without_xoff, 0U);
  EXPECT_EQ(r.sim.received, r.report.bytes_sent);
  EXPECT_EQ(r.sim_sha, r.report.sha256);
}

TEST(DripFeed, ALostXonRaisesTheAlarmAndTheJobIsNotResumed) {
  SimCncConfig sim;
  sim.buffer = 256;
  sim.high_water = 128;
  sim.low_water = 32;
  sim.execute_rate = 100.0;
  sim.lose_xon = true;
  SendOptions o = ascii_options(32, 0);
  o.xon_timeout = std::chrono::duration<double>(0.2);
  const JobRun r = run_job(o, std::make_unique<test::GeneratedProgram>(100000), sim);
  EXPECT_EQ(r.report.state, JobState::Interrupted);
  EXPECT_TRUE(r.report.alarm);
  EXPECT_NE(r.report.reason.find("no XON"), std::string::npos) << r.report.reason;
  EXPECT_LT(r.report.bytes_sent, 100000U);
  EXPECT_EQ(r.sim.received, r.report.bytes_sent);
}

TEST(DripFeed, WaitsForTheControlsFirstXon) {
  SimCncConfig sim;
  sim.send_initial_xon = true;
  SendOptions o = ascii_options(64, 0);
  o.wait_for_xon = true;
  const JobRun r = run_job(o, string_source("O1\nM30\n"), sim);
  EXPECT_EQ(r.report.state, JobState::Done);
  SimCncConfig silent;
  o.xon_timeout = std::chrono::duration<double>(0.1);
  const JobRun never = run_job(o, string_source("O1\nM30\n"), silent);
  EXPECT_EQ(never.report.state, JobState::Interrupted);
  EXPECT_EQ(never.report.bytes_sent, 0U);
}

// A link lost at random offsets: the job ends interrupted, with the byte
// count the control received, and the line and block of the last block it
// got whole; nothing is sent again.
TEST(DripFeed, ALostLinkInterruptsAtTheRightByteLineAndBlock) {
  std::mt19937 rng(2024);
  for (int trial = 0; trial < 40; ++trial) {
    const std::uint64_t at = std::uniform_int_distribution<std::uint64_t>(1, 20000)(rng);
    SimCncConfig sim;
    sim.drop_link_at = at;
    sim.keep_data = true;
    const JobRun r =
        run_job(ascii_options(256, 0), std::make_unique<test::GeneratedProgram>(30000), sim, 64);
    SCOPED_TRACE(testing::Message() << "drop at " << at);
    ASSERT_EQ(r.report.state, JobState::Interrupted) << r.report.reason;
    EXPECT_NE(r.report.reason.find("interrupted at byte"), std::string::npos);
    // What the control got is what usina says it sent, up to what was in flight.
    EXPECT_EQ(r.sim.received, at);
    EXPECT_GE(r.report.bytes_sent, at);
    EXPECT_LE(r.report.bytes_sent, at + 256 + 64);
    // The block reported is the last one whole in the bytes sent.
    test::GeneratedProgram program(30000);
    std::string wire = "%\n";
    std::vector<char> buf(30000);
    wire.append(buf.data(), program.read(buf));
    const std::string sent = wire.substr(0, r.report.bytes_sent);
    const std::size_t last_end = sent.rfind('\n');
    const std::size_t last_start = sent.rfind('\n', last_end - 1) + 1;
    const std::string last_block = sent.substr(last_start, last_end - last_start);
    if (last_block.starts_with("N")) {
      EXPECT_TRUE(last_block.starts_with("N" + std::to_string(r.report.block) + " ")) << last_block;
    }
    EXPECT_EQ(r.report.line,
              static_cast<std::uint64_t>(std::count(sent.begin(), sent.end(), '\n') - 1));
  }
}

TEST(DripFeed, StoppedByTheOperator) {
  asio::io_context io;
  LinkPair links = memory_link_pair(io, 256);
  SimCncConfig slow;
  slow.execute_rate = 1000;
  slow.buffer = 128;
  slow.high_water = 64;
  slow.low_water = 16;
  auto sim = std::make_shared<SimCnc>(io, *links.b, slow);
  auto sender =
      std::make_shared<Sender>(io, *links.a, ascii_options(32, 0),
                               std::make_unique<test::GeneratedProgram>(1 << 20), JobMode::Drip);
  JobReport report;
  bool done = false;
  sim->start();
  sender->start([&](const JobReport& r) {
    report = r;
    done = true;
  });
  test::run_until(io, [&] { return sender->report().bytes_sent > 500; });
  sender->stop();
  test::run_until(io, [&] { return done; });
  EXPECT_EQ(report.state, JobState::Interrupted);
  EXPECT_NE(report.reason.find("stopped by the operator"), std::string::npos);
  EXPECT_EQ(PacingTick::of(io).waiting(), 0U) << "a stopped feed still waits for the tick";
}

struct Feeds {
  std::vector<JobReport> reports;
  std::vector<SimCncStats> sims;
  std::uint64_t wakeups = 0;
};

// `count` feeds at once on one loop, each to its own simulated control.
Feeds run_feeds(int count, const SendOptions& options, std::uint64_t size, SimCncConfig sc) {
  asio::io_context io;
  std::vector<LinkPair> links;
  std::vector<std::shared_ptr<SimCnc>> sims;
  std::vector<std::shared_ptr<Sender>> senders;
  Feeds f;
  f.reports.resize(static_cast<std::size_t>(count));
  int left = count;
  for (int i = 0; i < count; ++i) {
    links.push_back(memory_link_pair(io, 4096));
    sims.push_back(std::make_shared<SimCnc>(io, *links.back().b, sc));
    senders.push_back(std::make_shared<Sender>(io, *links.back().a, options,
                                               std::make_unique<test::GeneratedProgram>(size),
                                               JobMode::Drip));
  }
  for (int i = 0; i < count; ++i) {
    sims[static_cast<std::size_t>(i)]->start();
    senders[static_cast<std::size_t>(i)]->start([&f, &left, i](const JobReport& r) {
      f.reports[static_cast<std::size_t>(i)] = r;
      --left;
    });
  }
  test::run_until(io, [&] { return left == 0; });
  EXPECT_EQ(left, 0);
  for (std::size_t i = 0; i < sims.size(); ++i) {
    test::run_until(
        io, [&] { return sims[i]->stats().received >= f.reports[i].bytes_sent; },
        std::chrono::seconds(5));
    f.sims.push_back(sims[i]->stats());
  }
  f.wakeups = PacingTick::of(io).wakeups();
  return f;
}

// Issue 13, "Speed": the feeds of one loop share its pacing timer, so the
// loop wakes fewer times than the feeds write; and every byte still arrives
// with no overflow and no more than the skid after an XOFF.
TEST(DripFeed, FeedsOnOneLoopShareTheirWakeups) {
  SimCncConfig sim;
  sim.buffer = 512;
  sim.high_water = 256;
  sim.low_water = 128;
  sim.execute_rate = 90000.0;  // a little slower than the line: XOFFs come
  const double rate = 100000.0;
  const auto skid = static_cast<std::uint32_t>(safe_skid(sim, rate));
  const Feeds f = run_feeds(16, ascii_options(skid, rate), 60000, sim);
  std::uint64_t writes = 0;
  for (std::size_t i = 0; i < f.reports.size(); ++i) {
    SCOPED_TRACE(testing::Message() << "feed " << i);
    EXPECT_EQ(f.reports[i].state, JobState::Done) << f.reports[i].reason;
    EXPECT_EQ(f.sims[i].received, f.reports[i].bytes_sent);
    EXPECT_EQ(f.sims[i].overflow, 0U);
    EXPECT_LE(f.sims[i].max_after_xoff, skid);
    writes += f.reports[i].writes;
  }
  EXPECT_GT(f.wakeups, 0U);
  EXPECT_LT(f.wakeups, writes);
}

// A chunk is all the room there is once half the skid is free: never less
// than half the skid but for the program's last bytes, so the writes (a
// system call each) are at most two per skid of program.
TEST(DripFeed, EachWriteCarriesAtLeastHalfTheSkid) {
  const std::uint32_t skid = 256;
  SimCncConfig roomy;  // never says XOFF: the wire alone paces the feeds
  roomy.buffer = 1U << 20U;
  roomy.high_water = 1U << 19U;
  roomy.low_water = 1U << 18U;
  const Feeds f = run_feeds(4, ascii_options(skid, 50000.0), 40000, roomy);
  for (const JobReport& r : f.reports) {
    EXPECT_EQ(r.state, JobState::Done) << r.reason;
    EXPECT_GE(r.writes, r.bytes_sent / skid);
    EXPECT_LE(r.writes, r.bytes_sent / (skid / 2) + 1);
  }
}

long max_rss_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

// A 100 MB program, streamed: every byte arrives, the hashes agree, and the
// process grows by far less than the program.
TEST(DripFeed, HundredMegabytesInConstantMemory) {
  const std::uint64_t size = 100ULL << 20U;
  const long before = max_rss_kb();
  const JobRun r = run_job(ascii_options(8192, 0), std::make_unique<test::GeneratedProgram>(size),
                           SimCncConfig{}, 16384);
  const long after = max_rss_kb();
  EXPECT_EQ(r.report.state, JobState::Done) << r.report.reason;
  EXPECT_EQ(r.sim.received, r.report.bytes_sent);
  EXPECT_GE(r.report.bytes_sent, size);
  EXPECT_EQ(r.sim_sha, r.report.sha256);
  EXPECT_LT(after - before, 16 * 1024) << "grew by " << (after - before) << " kB";
}

}  // namespace
}  // namespace usina::dnc

namespace usina::dnc {
namespace {

TEST(DripFeed, AnIsoXoffWithItsParityBitPauses) {
  SimCncConfig sim;
  sim.buffer = 256;
  sim.high_water = 128;
  sim.low_water = 32;
  sim.execute_rate = 20000.0;
  sim.xoff = 0x93;  // DC3 with channel 8 set: ISO on 8 data bits
  sim.xon = 0x11;
  SendOptions o = ascii_options(64, 100000.0);
  o.code = TapeCode::Iso;
  o.format.code = TapeCode::Iso;
  const JobRun r = run_job(o, std::make_unique<test::GeneratedProgram>(4000), sim);
  EXPECT_EQ(r.report.state, JobState::Done) << r.report.reason;
  EXPECT_GT(r.report.xoff_count, 0U);
  EXPECT_EQ(r.sim.overflow, 0U);
}

// A link whose DSR line the test holds.
class DsrLink final : public Link {
 public:
  explicit DsrLink(Link& inner) : inner_(inner) {}

  void async_read_some(std::span<std::uint8_t> b, IoHandler h) override {
    inner_.async_read_some(b, std::move(h));
  }

  void async_write(std::span<const std::uint8_t> b, IoHandler h) override {
    inner_.async_write(b, std::move(h));
  }

  void cancel() override { inner_.cancel(); }

  void close() override { inner_.close(); }

  bool peer_ready() const override { return dsr; }

  std::string describe() const override { return "dsr"; }

  bool dsr = false;

 private:
  Link& inner_;
};

TEST(DripFeed, DtrDsrWaitsWhileDsrIsLow) {
  asio::io_context io;
  LinkPair links = memory_link_pair(io);
  DsrLink ours(*links.a);
  SimCncConfig sc;
  sc.keep_data = true;
  auto sim = std::make_shared<SimCnc>(io, *links.b, sc);
  SendOptions o = ascii_options(64, 0);
  o.flow = Flow::DtrDsr;
  auto sender = std::make_shared<Sender>(io, ours, o, string_source("O1\nM30\n"), JobMode::Send);
  bool done = false;
  sim->start();
  sender->start([&](const JobReport&) { done = true; });
  io.run_for(std::chrono::milliseconds(60));
  EXPECT_EQ(sender->report().bytes_sent, 0U);
  EXPECT_FALSE(done);
  ours.dsr = true;
  test::run_until(io, [&] { return done; });
  EXPECT_EQ(sender->report().state, JobState::Done);
  // "%\nO1\nM30\n%": the frame's `%` and its block end, two blocks, the closing
  // `%` (no leader or trailer) -- ten bytes, as AProgramArrivesWhole counts them.
  const std::string wire = "%\nO1\nM30\n%";
  EXPECT_EQ(sender->report().bytes_sent, wire.size());
  test::run_until(io, [&] { return sim->stats().received >= wire.size(); });
  EXPECT_EQ(std::string(sim->data().begin(), sim->data().end()), wire);
}

}  // namespace
}  // namespace usina::dnc
