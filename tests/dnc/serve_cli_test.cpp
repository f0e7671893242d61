// The real `usina serve` process, as a shop runs it: --init makes the store
// and its admin; the server reads usina-serve.toml, listens on a port of
// its own choosing (printed on standard error), feeds a simulated control
// on a socat pty pair, and stops cleanly on SIGTERM.
#include "serve_cli.hpp"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <thread>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "api_client.hpp"
#include "dnc/link_serial.hpp"
#include "dnc/sha256.hpp"
#include "dnc/sim_cnc.hpp"

namespace usina::dnc {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace serve_cli;

TEST(ServeCli, AJobRunsEndToEndOverASocatPtyPairAndSigtermStopsTheServer) {
  if (std::system("command -v socat > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "socat is not installed";
  const fs::path dir =
      fs::temp_directory_path() / ("usina_serve_cli_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  write(dir / "pw", "a long password\n");
  const pid_t init = spawn_usina({"serve", "--init", "--data", (dir / "data").string(), "--admin",
                                  "boss", "--password-file", (dir / "pw").string()},
                                 dir / "init.log");
  ASSERT_EQ(wait_exit(init), 0) << slurp(dir / "init.log");
  SocatPair socat{dir};
  ASSERT_TRUE(socat.start());
  // The control: a simulated CNC on its end of the pair, on a loop of its own.
  asio::io_context io;
  LinkConfig control_side;
  control_side.data_bits = 8;
  control_side.parity = Parity::None;
  auto link = open_serial_link(io, (dir / "control").string(), control_side);
  ASSERT_TRUE(link) << link.error();
  SimCncConfig sc;
  sc.keep_data = true;
  auto sim = std::make_shared<SimCnc>(io, **link, sc);
  sim->start();
  auto work = asio::make_work_guard(io);
  std::thread control([&io] { io.run(); });
  write(dir / "usina-serve.toml", config_for(dir / "machine"));
  const pid_t server = spawn_usina({"serve", "--data", (dir / "data").string(), "--config",
                                    (dir / "usina-serve.toml").string(), "--listen", "127.0.0.1:0"},
                                   dir / "serve.log");
  ASSERT_GT(server, 0);
  const unsigned short port = listening_port(dir / "serve.log");
  ASSERT_NE(port, 0) << slurp(dir / "serve.log");
  const test::ApiClient c(port);
  const std::string token = c.log_in("boss", "a long password");
  ASSERT_FALSE(token.empty());
  const std::string text = "%\nO1234 (PART)\nN10 G21 G90\nN20 G0 X10 Y10\nN30 M2\n%\n";
  const test::Reply up = c.post("/api/programs",
                                {{"name", "O1234"},
                                 {"machine_class", "mill"},
                                 {"dialect", "rs274ngc"},
                                 {"text", text},
                                 {"reason", "first cut"}},
                                token);
  ASSERT_EQ(up.status, 201) << up.body;
  const std::string rev = up.json()["revision"];
  EXPECT_EQ(rev, sha256_hex(std::string_view(text)));
  for (const char* state : {"checked", "approved", "released"}) {
    const test::Reply moved = c.post("/api/programs/O1234/revisions/" + rev + "/state",
                                     {{"state", state}, {"reason", "ok"}}, token);
    ASSERT_EQ(moved.status, 200) << state << ": " << moved.body;
  }
  const test::Reply job =
      c.post("/api/machines/mill-1/jobs",
             {{"program", "O1234"}, {"revision", rev}, {"mode", "send"}}, token);
  ASSERT_EQ(job.status, 201) << job.body;
  nlohmann::json state;
  for (int i = 0; i < 1200; ++i) {
    state = c.get("/api/jobs/" + std::to_string(job.json()["job"].get<int>()), token).json();
    if (state["state"] != "queued" && state["state"] != "running") break;
    std::this_thread::sleep_for(50ms);
  }
  const std::string wire = "%\nO1234 (PART)\nN10 G21 G90\nN20 G0 X10 Y10\nN30 M2\n%";
  EXPECT_EQ(state["state"], "done") << state.dump();
  EXPECT_EQ(state["sha256"], sha256_hex(std::string_view(wire)));
  EXPECT_EQ(state["bytes_sent"], wire.size());
  for (int i = 0; i < 200; ++i) {
    std::promise<std::uint64_t> got;
    asio::post(io, [&] { got.set_value(sim->stats().received); });
    if (got.get_future().get() >= wire.size()) break;
    std::this_thread::sleep_for(25ms);
  }
  ASSERT_EQ(::kill(server, SIGTERM), 0);
  EXPECT_EQ(wait_exit(server), 0);
  EXPECT_NE(slurp(dir / "serve.log").find("stopped"), std::string::npos);
  io.stop();
  control.join();
  EXPECT_EQ(sim->sha256(), state["sha256"]);
  EXPECT_EQ(std::string(sim->data().begin(), sim->data().end()), wire);
  sim.reset();
  link->reset();
  fs::remove_all(dir);
}

// kill -9 in the middle of a drip feed: the server cannot write the job's
// end, so the next start shows it interrupted (never resent from zero).
TEST(ServeCli, AFeedCutByKill9IsInterruptedAfterTheRestart) {
  if (std::system("command -v socat > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "socat is not installed";
  const fs::path dir =
      fs::temp_directory_path() / ("usina_serve_kill_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  write(dir / "pw", "a long password\n");
  ASSERT_EQ(wait_exit(spawn_usina({"serve", "--init", "--data", (dir / "data").string(), "--admin",
                                   "boss", "--password-file", (dir / "pw").string()},
                                  dir / "init.log")),
            0);
  SocatPair socat{dir};
  ASSERT_TRUE(socat.start());
  write(dir / "usina-serve.toml", config_for(dir / "machine", 1200));  // 120 bytes a second
  const std::vector<std::string> run{"serve",
                                     "--data",
                                     (dir / "data").string(),
                                     "--config",
                                     (dir / "usina-serve.toml").string(),
                                     "--listen",
                                     "127.0.0.1:0"};
  const pid_t first = spawn_usina(run, dir / "serve.log");
  const unsigned short port = listening_port(dir / "serve.log");
  ASSERT_NE(port, 0) << slurp(dir / "serve.log");
  test::ApiClient c(port);
  const std::string token = c.log_in("boss", "a long password");
  std::string text;
  for (int n = 1; n <= 400; ++n)
    text += "N" + std::to_string(n) + " G1 X" + std::to_string(n % 40) + " F500\n";
  const std::string rev =
      c.post("/api/programs", {{"name", "O77"}, {"text", text}}, token).json()["revision"];
  for (const char* state : {"checked", "approved", "released"})
    c.post("/api/programs/O77/revisions/" + rev + "/state", {{"state", state}}, token);
  const test::Reply job = c.post("/api/machines/mill-1/jobs",
                                 {{"program", "O77"}, {"revision", rev}, {"mode", "drip"}}, token);
  ASSERT_EQ(job.status, 201) << job.body;
  const std::string id = std::to_string(job.json()["job"].get<int>());
  // Queued until the port is open (it opens as the server starts), then running.
  for (int i = 0; i < 600 && c.get("/api/jobs/" + id, token).json()["state"] != "running"; ++i)
    std::this_thread::sleep_for(50ms);
  ASSERT_EQ(c.get("/api/jobs/" + id, token).json()["state"], "running");
  ASSERT_EQ(::kill(first, SIGKILL), 0);
  EXPECT_EQ(wait_exit(first), 128 + SIGKILL);
  const pid_t second = spawn_usina(run, dir / "serve2.log");
  const unsigned short port2 = listening_port(dir / "serve2.log");
  ASSERT_NE(port2, 0) << slurp(dir / "serve2.log");
  test::ApiClient c2(port2);
  const auto after = c2.get("/api/jobs/" + id, c2.log_in("boss", "a long password")).json();
  EXPECT_EQ(after["state"], "interrupted") << after.dump();
  EXPECT_NE(after["reason"].get<std::string>().find("the server stopped"), std::string::npos);
  // The dead server's time is "off" (from its heartbeat), not more feeding.
  const auto day = c2.get("/api/machines/mill-1/utilisation", c2.log_in("boss", "a long password"))
                       .json()["days"][0];
  EXPECT_GT(day["server_off_seconds"].get<double>(), 0.0) << day.dump();
  ::kill(second, SIGTERM);
  EXPECT_EQ(wait_exit(second), 0);
  fs::remove_all(dir);
}

TEST(ServeCli, HelpNamesTheContractsFlags) {
  const fs::path log =
      fs::temp_directory_path() / ("usina_serve_help_" + std::to_string(::getpid()));
  const pid_t pid = spawn_usina({"serve", "--help"}, log);
  ASSERT_EQ(wait_exit(pid), 0);
  const std::string help = slurp(log);
  for (const char* flag : {"--init", "--data", "--admin", "--password-file", "--config", "--listen",
                           "--store", "--verify-audit"})
    EXPECT_NE(help.find(flag), std::string::npos) << flag;
  fs::remove(log);
}

}  // namespace
}  // namespace usina::dnc
