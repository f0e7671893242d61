// Many machines drip-fed at once from one process and one event loop
// (issue 13, "Speed"): each machine a simulated control on a pty pair or an
// in-process pipe, each fed a program long enough to last the run at the
// line's rate. Prints the bytes delivered, overflows, hash mismatches, the
// CPU used (user + system, as a share of one core over the wall time) and
// the peak memory. No assertion on times: the figures are for the report.
// With pty links the simulated controls run on a second thread and event
// loop, as a second program would, so the server's own share (the thread of
// the senders) is measured apart from the controls'.
//
//   dnc_feed_bench [--machines 256] [--baud 115200] [--seconds 10] [--skid 32]
//                  [--link memory|pty] [--buffer 4096]
#include <time.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <boost/asio/executor_work_guard.hpp>
#include <fmt/format.h>
#include <sys/resource.h>

#include "dnc/link_config.hpp"
#include "dnc/link_memory.hpp"
#include "dnc/link_serial.hpp"
#include "dnc/pacing_tick.hpp"
#include "dnc/sim_cnc.hpp"
#include "dnc/transfer_send.hpp"

namespace {

using namespace usina::dnc;

struct Options {
  int machines = 256;
  std::uint32_t baud = 115200;
  double seconds = 10.0;
  std::uint32_t skid = 32;
  std::string link = "memory";
  std::size_t buffer = 4096;
};

// Lines "N.. G1 X.. Y.. F1200" made as they are read: constant memory. Each
// line is formatted into a fixed buffer: the generator stands in for a file
// read (a copy of 16 KB), and an allocation per line would be the bench's
// cost counted as the server's.
class Generated final : public ProgramSource {
 public:
  explicit Generated(std::uint64_t bytes) : total_(bytes) {}

  std::size_t read(std::span<char> out) override {
    std::size_t n = 0;
    while (n < out.size() && made_ < total_) {
      if (at_ == size_) next_line();
      const std::size_t take =
          std::min<std::uint64_t>({size_ - at_, out.size() - n, total_ - made_});
      std::memcpy(out.data() + n, line_.data() + at_, take);
      n += take;
      at_ += take;
      made_ += take;
    }
    return n;
  }

 private:
  void next_line() {
    ++number_;
    const auto r = fmt::format_to_n(line_.data(), line_.size(), "N{} G1 X{}.5 Y-{}.25 F1200\n",
                                    number_, number_ % 1000, number_ % 777);
    size_ = r.out - line_.data();
    at_ = 0;
  }

  std::uint64_t total_;
  std::uint64_t made_ = 0;
  std::uint64_t number_ = 0;
  std::array<char, 64> line_{};
  std::size_t size_ = 0;
  std::size_t at_ = 0;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const char* v = argv[i + 1];
    if (key == "--machines") o.machines = std::atoi(v);
    if (key == "--baud") o.baud = static_cast<std::uint32_t>(std::atol(v));
    if (key == "--seconds") o.seconds = std::atof(v);
    if (key == "--skid") o.skid = static_cast<std::uint32_t>(std::atol(v));
    if (key == "--link") o.link = v;
    if (key == "--buffer") o.buffer = static_cast<std::size_t>(std::atol(v));
  }
  return o;
}

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

// The CPU time of the calling thread.
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) / 1e9;
}

long max_rss_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

struct Machine {
  std::unique_ptr<Link> ours;
  std::unique_ptr<Link> theirs;
  std::shared_ptr<SimCnc> sim;
  std::shared_ptr<Sender> sender;
  JobReport report;
  bool done = false;
};

LinkConfig machine_config(const Options& o, int i) {
  LinkConfig c;
  c.name = fmt::format("m{}", i);
  c.baud = o.baud;
  c.data_bits = 8;
  c.parity = Parity::None;
  c.stop_bits = 1;
  c.code = TapeCode::Iso;
  c.skid = o.skid;
  return c;
}

// The server's end on `io`, the control's on `controls` (pty links; a
// memory pair lives on `io` alone).
bool open_links(asio::io_context& io, asio::io_context& controls, const Options& o,
                const LinkConfig& c, Machine& m) {
  if (o.link == "pty") {
    auto pair = open_pty_pair(controls);
    if (!pair) return false;
    auto ours = open_serial_link(io, pair->slave_path, c);
    if (!ours) return false;
    m.ours = std::move(*ours);
    m.theirs = std::move(pair->master);
    return true;
  }
  LinkPair links = memory_link_pair(io, 4096);
  m.ours = std::move(links.a);
  m.theirs = std::move(links.b);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  asio::io_context io;
  asio::io_context controls;  // the simulated controls' loop (pty links)
  asio::io_context& control_io = o.link == "pty" ? controls : io;
  std::vector<Machine> machines(static_cast<std::size_t>(o.machines));
  const double rate = bytes_per_second(machine_config(o, 0));
  const auto program_bytes = static_cast<std::uint64_t>(rate * o.seconds);
  SimCncConfig sc;
  sc.buffer = o.buffer;
  sc.high_water = o.buffer - o.skid - 16;
  sc.low_water = o.buffer / 4;
  sc.execute_rate = rate * 0.97;  // a control a little slower than its line: XOFF now and then
  for (int i = 0; i < o.machines; ++i) {
    Machine& m = machines[static_cast<std::size_t>(i)];
    const LinkConfig c = machine_config(o, i);
    if (!open_links(io, controls, o, c, m)) {
      std::fprintf(stderr, "cannot open the links of machine %d\n", i);
      return 2;
    }
    m.sim = std::make_shared<SimCnc>(control_io, *m.theirs, sc);
    m.sender = std::make_shared<Sender>(io, *m.ours, send_options(c),
                                        std::make_unique<Generated>(program_bytes), JobMode::Drip);
  }
  for (Machine& m : machines)
    m.sim->start();
  auto keep = asio::make_work_guard(controls);
  double controls_cpu = 0.0;
  std::thread control_thread([&controls, &controls_cpu] {
    const double c0 = thread_cpu_seconds();
    controls.run();
    controls_cpu = thread_cpu_seconds() - c0;
  });
  const double cpu0 = cpu_seconds();
  const double server0 = thread_cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  int left = o.machines;
  for (Machine& m : machines) {
    m.sender->start([&m, &left](const JobReport& r) {
      m.report = r;
      m.done = true;
      --left;
    });
  }
  // Counted down by the machines as they finish (not a walk over all of
  // them after every handler: that was the bench's own cost).
  while (left > 0)
    io.run_one_for(std::chrono::milliseconds(100));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_seconds() - cpu0;
  const double server_cpu = thread_cpu_seconds() - server0;
  // The last bytes reach the controls.
  io.run_for(std::chrono::milliseconds(200));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  keep.reset();
  controls.stop();
  control_thread.join();
  std::uint64_t sent = 0, received = 0, overflow = 0, xoffs = 0, writes = 0;
  int not_done = 0, mismatched = 0;
  for (Machine& m : machines) {
    sent += m.report.bytes_sent;
    received += m.sim->stats().received;
    overflow += m.sim->stats().overflow;
    xoffs += m.sim->stats().xoff_sent;
    writes += m.report.writes;
    not_done += m.report.state == JobState::Done ? 0 : 1;
    mismatched += m.report.sha256 == m.sim->sha256() ? 0 : 1;
  }
  fmt::print(
      "machines {} link {} baud {} skid {} buffer {}\n"
      "program {} bytes each, line rate {:.0f} bytes/s\n"
      "wall {:.2f} s, cpu {:.2f} s = {:.1f} % of one core\n"
      "server thread{} {:.2f} s = {:.1f} % of one core; controls thread {:.2f} s\n"
      "bytes sent {} received {} overflow {} xoff {} not done {} hash mismatches {}\n"
      "writes {} ({:.0f} bytes each), pacing wake-ups {}\n"
      "max rss {:.1f} MB\n",
      o.machines, o.link, o.baud, o.skid, o.buffer, program_bytes, rate, wall, cpu,
      100.0 * cpu / wall, o.link == "pty" ? "" : " (with the controls: memory links)", server_cpu,
      100.0 * server_cpu / wall, controls_cpu, sent, received, overflow, xoffs, not_done,
      mismatched, writes,
      writes > 0 ? static_cast<double>(sent) / static_cast<double>(writes) : 0.0,
      PacingTick::of(io).wakeups(), static_cast<double>(max_rss_kb()) / 1024.0);
  return (not_done == 0 && mismatched == 0 && overflow == 0 && sent == received) ? 0 : 1;
}
