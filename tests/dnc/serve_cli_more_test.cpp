// The real `usina serve` binary, beyond serve_cli_test.cpp (issue 13):
// --verify-audit on a good and a tampered store, SIGTERM in the middle of a
// drip feed, the PostgreSQL store, and a link lost during a feed.
#include <signal.h>
#include <sqlite3.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "api_client.hpp"
#include "dnc/link_serial.hpp"
#include "dnc/sha256.hpp"
#include "dnc/sim_cnc.hpp"
#include "serve_cli.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace serve_cli;
using Api = usina::test::ApiClient;
using Reply = usina::test::Reply;

const std::string kPassword = "a long password";

// A scratch folder with the admin's password file, removed at the end.
struct Shop {
  fs::path dir;

  explicit Shop(const std::string& name)
      : dir(fs::temp_directory_path() /
            ("usina_serve_more_" + name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(dir);
    fs::create_directories(dir);
    write(dir / "pw", kPassword + "\n");
  }

  ~Shop() { fs::remove_all(dir); }

  // `usina serve ARGS... STORE`, its exit status; its output in dir/LOG.
  int run(std::vector<std::string> args, const std::vector<std::string>& store,
          const std::string& log) const {
    args.insert(args.begin(), "serve");
    args.insert(args.end(), store.begin(), store.end());
    return wait_exit(spawn_usina(args, dir / log));
  }

  int init(const std::vector<std::string>& store) const {
    return run({"--init", "--admin", "boss", "--password-file", (dir / "pw").string()}, store,
               "init.log");
  }

  std::vector<std::string> data() const { return {"--data", (dir / "data").string()}; }

  // The server on port 0 with dir/usina-serve.toml; its pid.
  pid_t serve(const std::vector<std::string>& store, const std::string& log) const {
    std::vector<std::string> args{"serve", "--config", (dir / "usina-serve.toml").string(),
                                  "--listen", "127.0.0.1:0"};
    args.insert(args.end(), store.begin(), store.end());
    return spawn_usina(args, dir / log);
  }
};

// Four hundred lines: about 5 KB, some 45 s at 1200 baud.
std::string long_program() {
  std::string text;
  for (int n = 1; n <= 400; ++n)
    text += "N" + std::to_string(n) + " G1 X" + std::to_string(n % 40) + " F500\n";
  return text;
}

// Uploads `text` as program `name` and releases it; its revision.
std::string released(const Api& c, const std::string& token, const std::string& name,
                     const std::string& text) {
  const Reply up = c.post("/api/programs", {{"name", name}, {"text", text}}, token);
  EXPECT_EQ(up.status, 201) << up.body;
  if (up.status != 201) return {};
  const std::string rev = up.json()["revision"];
  for (const char* state : {"checked", "approved", "released"}) {
    const Reply moved = c.post("/api/programs/" + name + "/revisions/" + rev + "/state",
                               {{"state", state}, {"reason", "ok"}}, token);
    EXPECT_EQ(moved.status, 200) << state << ": " << moved.body;
  }
  return rev;
}

// A drip feed of `name` to mill-1, once some of its bytes are on the wire; its id.
std::string feeding(const Api& c, const std::string& token, const std::string& name,
                    const std::string& rev) {
  const Reply job = c.post("/api/machines/mill-1/jobs",
                           {{"program", name}, {"revision", rev}, {"mode", "drip"}}, token);
  EXPECT_EQ(job.status, 201) << job.body;
  if (job.status != 201) return {};
  const std::string id = std::to_string(job.json()["job"].get<int>());
  for (int i = 0; i < 600; ++i) {
    const auto j = c.get("/api/jobs/" + id, token).json();
    if (j["state"] == "running" && j["bytes_sent"].get<std::uint64_t>() > 0) break;
    std::this_thread::sleep_for(50ms);
  }
  return id;
}

// The job's state once it is neither queued nor running (or after 60 s).
nlohmann::json ended(const Api& c, const std::string& token, const std::string& id) {
  nlohmann::json j;
  for (int i = 0; i < 1200; ++i) {
    j = c.get("/api/jobs/" + id, token).json();
    if (j["state"] != "queued" && j["state"] != "running") break;
    std::this_thread::sleep_for(50ms);
  }
  return j;
}

// The audit entries whose action is `action` and whose subject is job `id`'s.
std::vector<nlohmann::json> job_entries(const Api& c, const std::string& token,
                                        const std::string& action, const std::string& id) {
  std::vector<nlohmann::json> found;
  const Reply log = c.get("/api/audit?limit=1000", token);
  EXPECT_EQ(log.status, 200) << log.body;
  const nlohmann::json all = log.json();  // held: the loop walks a part of it
  for (const auto& e : all["entries"]) {
    if (e["action"] == action && e["subject"].get<std::string>().starts_with("job " + id + " "))
      found.push_back(e);
  }
  return found;
}

// mill-1 once its state is `state` (or after 20 s).
nlohmann::json mill_when(const Api& c, const std::string& token, const std::string& state) {
  nlohmann::json mill;
  for (int i = 0; i < 400; ++i) {
    mill = c.get("/api/machines/mill-1", token).json();
    if (mill["state"] == state) break;
    std::this_thread::sleep_for(50ms);
  }
  return mill;
}

// A simulated CNC on the control's end of socat's pair, on a loop of its own.
class Control {
 public:
  bool start(const fs::path& port) {
    LinkConfig side;
    side.data_bits = 8;
    side.parity = Parity::None;
    auto link = open_serial_link(io_, port.string(), side);
    if (!link) return false;
    link_ = std::move(*link);
    SimCncConfig sc;
    sc.keep_data = true;
    sim_ = std::make_shared<SimCnc>(io_, *link_, sc);
    sim_->start();
    thread_ = std::thread([this] { io_.run(); });
    return true;
  }

  std::uint64_t received() {
    std::promise<std::uint64_t> got;
    asio::post(io_, [&] { got.set_value(sim_->stats().received); });
    return got.get_future().get();
  }

  // The control goes away: its end of the pty is closed.
  void close() {
    work_.reset();
    io_.stop();
    if (thread_.joinable()) thread_.join();
    sim_.reset();
    link_.reset();
  }

  ~Control() { close(); }

 private:
  asio::io_context io_;
  asio::executor_work_guard<asio::io_context::executor_type> work_ = asio::make_work_guard(io_);
  std::unique_ptr<Link> link_;
  std::shared_ptr<SimCnc> sim_;
  std::thread thread_;
};

bool have_socat() {
  return std::system("command -v socat > /dev/null 2>&1") == 0;
}

// The count --verify-audit printed ("audit log: N entries"), -1 when none.
long printed_entries(const std::string& said) {
  std::smatch m;
  const std::regex count("audit log: ([0-9]+) entries, the chain holds");
  return std::regex_search(said, m, count) ? std::stol(m[1]) : -1;
}

long sqlite_count(sqlite3* db, const char* sql) {
  sqlite3_stmt* st = nullptr;
  long n = -1;
  if (sqlite3_prepare_v2(db, sql, -1, &st, nullptr) == SQLITE_OK && sqlite3_step(st) == SQLITE_ROW)
    n = static_cast<long>(sqlite3_column_int64(st, 0));
  sqlite3_finalize(st);
  return n;
}

TEST(ServeCliMore, VerifyAuditCountsAGoodChainAndNamesTheTamperedEntry) {
  const Shop shop("verify");
  ASSERT_EQ(shop.init(shop.data()), 0) << slurp(shop.dir / "init.log");
  // Some entries beyond the admin's: two programs imported from a folder.
  fs::create_directories(shop.dir / "in");
  write(shop.dir / "in" / "O1.nc", "%\nO1\nG0 X1\nM2\n%\n");
  write(shop.dir / "in" / "O2.nc", "%\nO2\nG0 X2\nM2\n%\n");
  ASSERT_EQ(shop.run({"--import", (shop.dir / "in").string(), "--user", "boss"}, shop.data(),
                     "import.log"),
            0)
      << slurp(shop.dir / "import.log");
  ASSERT_EQ(shop.run({"--verify-audit"}, shop.data(), "good.log"), 0)
      << slurp(shop.dir / "good.log");
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open((shop.dir / "data" / "usina.db").c_str(), &db), SQLITE_OK);
  const long entries = sqlite_count(db, "SELECT COUNT(*) FROM audit");
  EXPECT_GE(entries, 3);
  EXPECT_EQ(printed_entries(slurp(shop.dir / "good.log")), entries) << slurp(shop.dir / "good.log");
  // Someone with the file drops the guard and rewrites entry 2's reason.
  char* error = nullptr;
  const int rc = sqlite3_exec(db,
                              "DROP TRIGGER audit_no_update;"
                              "UPDATE audit SET reason = 'nothing to see' WHERE seq = 2;",
                              nullptr, nullptr, &error);
  EXPECT_EQ(rc, SQLITE_OK) << (error ? error : "");
  sqlite3_free(error);
  EXPECT_EQ(sqlite3_changes(db), 1);
  sqlite3_close(db);
  EXPECT_EQ(shop.run({"--verify-audit"}, shop.data(), "bad.log"), 1) << slurp(shop.dir / "bad.log");
  const std::string said = slurp(shop.dir / "bad.log");
  EXPECT_NE(said.find("BROKEN at entry 2"), std::string::npos) << said;
  EXPECT_EQ(printed_entries(said), -1) << said;
}

// A shop's server drip-feeding O77 to a control over socat at 1200 baud:
// where the SIGTERM and the lost-link tests start.
struct FeedUnderWay {
  explicit FeedUnderWay(const char* name) : shop(name), socat{shop.dir} {}

  // Starts each part; a part that does not start fails the test.
  void start() {
    ASSERT_EQ(shop.init(shop.data()), 0) << slurp(shop.dir / "init.log");
    ASSERT_TRUE(socat.start());
    ASSERT_TRUE(control.start(shop.dir / "control"));
    write(shop.dir / "usina-serve.toml", config_for(shop.dir / "machine", 1200));
    server = shop.serve(shop.data(), "serve.log");
    const unsigned short port = listening_port(shop.dir / "serve.log");
    ASSERT_NE(port, 0) << slurp(shop.dir / "serve.log");
    api.emplace(port);
    token = api->log_in("boss", kPassword);
    id = feeding(*api, token, "O77", released(*api, token, "O77", long_program()));
    ASSERT_FALSE(id.empty());
  }

  const Shop shop;
  SocatPair socat;
  Control control;
  pid_t server = -1;
  std::optional<Api> api;
  std::string token;
  std::string id;
};

TEST(ServeCliMore, SigtermDuringADripFeedEndsItInterruptedWithItsAuditEntry) {
  if (!have_socat()) GTEST_SKIP() << "socat is not installed";
  FeedUnderWay f("sigterm");
  ASSERT_NO_FATAL_FAILURE(f.start());
  const Shop& shop = f.shop;
  const Api& c = *f.api;
  const std::string& token = f.token;
  const std::string& id = f.id;
  Control& control = f.control;
  const pid_t first = f.server;
  ASSERT_EQ(c.get("/api/jobs/" + id, token).json()["state"], "running");
  ASSERT_EQ(::kill(first, SIGTERM), 0);
  EXPECT_EQ(wait_exit(first), 0) << slurp(shop.dir / "serve.log");
  const std::uint64_t got = control.received();
  const pid_t second = shop.serve(shop.data(), "serve2.log");
  const unsigned short port2 = listening_port(shop.dir / "serve2.log");
  ASSERT_NE(port2, 0) << slurp(shop.dir / "serve2.log");
  const Api c2(port2);
  const std::string token2 = c2.log_in("boss", kPassword);
  const auto after = c2.get("/api/jobs/" + id, token2).json();
  EXPECT_EQ(after["state"], "interrupted") << after.dump();
  const std::string reason = after["reason"];
  EXPECT_NE(reason.find("the server was stopped (SIGTERM)"), std::string::npos) << reason;
  EXPECT_GT(after["bytes_sent"].get<std::uint64_t>(), 0u);
  EXPECT_LT(after["bytes_sent"].get<std::uint64_t>(), after["bytes_total"].get<std::uint64_t>());
  EXPECT_LE(got, after["bytes_sent"].get<std::uint64_t>());
  // One end, written by the stopping server (the restart found nothing to mark).
  const auto ends = job_entries(c2, token2, "job.interrupted", id);
  ASSERT_EQ(ends.size(), 1u) << c2.get("/api/audit", token2).body;
  EXPECT_EQ(ends[0]["reason"], reason);
  ::kill(second, SIGTERM);
  EXPECT_EQ(wait_exit(second), 0);
}

// The same store questions on each back end; the PostgreSQL one against the
// test cluster (tests/dnc/pg_cluster.sh).
class ServeCliStore : public ::testing::TestWithParam<Backend> {};

TEST_P(ServeCliStore, InitServeLoginUploadStopAnswerTheSame) {
  const Shop shop("store");
  std::vector<std::string> store = shop.data();
  std::string url;
  if (GetParam() == Backend::Postgres) {
    test::PgServer& pg = test::PgServer::get();
    if (!pg.ok()) GTEST_SKIP() << pg.why_not();
    url = pg.fresh_database();
    ASSERT_FALSE(url.empty()) << "cannot create a database on the test cluster";
    store = {"--store", url};
  }
  ASSERT_EQ(shop.init(store), 0) << slurp(shop.dir / "init.log");
  EXPECT_EQ(shop.init(store), 2) << "a second admin on a store that has one";
  write(shop.dir / "usina-serve.toml", "");
  const pid_t server = shop.serve(store, "serve.log");
  const unsigned short port = listening_port(shop.dir / "serve.log");
  ASSERT_NE(port, 0) << slurp(shop.dir / "serve.log");
  const Api c(port);
  EXPECT_TRUE(c.log_in("boss", "not the password").empty());
  const std::string token = c.log_in("boss", kPassword);
  ASSERT_FALSE(token.empty());
  const std::string text = "%\nO1234 (PART)\nN10 G21 G90\nN20 G0 X10 Y10\nN30 M2\n%\n";
  const std::string rev = released(c, token, "O1234", text);
  EXPECT_EQ(rev, sha256_hex(std::string_view(text)));
  const Reply again = c.post("/api/programs", {{"name", "O1234"}, {"text", text}}, token);
  EXPECT_EQ(again.status, 200) << again.body;
  const Reply program = c.get("/api/programs/O1234", token);
  EXPECT_EQ(program.status, 200) << program.body;
  EXPECT_NE(program.body.find(rev), std::string::npos) << program.body;
  EXPECT_EQ(c.get("/api/programs/O9999", token).status, 404);
  const auto verify = c.get("/api/audit?verify=1", token).json();
  EXPECT_EQ(verify["ok"], true) << verify.dump();
  ASSERT_EQ(::kill(server, SIGTERM), 0);
  EXPECT_EQ(wait_exit(server), 0) << slurp(shop.dir / "serve.log");
  // The admin, the revision and its three moves: the same count on each store.
  ASSERT_EQ(shop.run({"--verify-audit"}, store, "verify.log"), 0) << slurp(shop.dir / "verify.log");
  EXPECT_EQ(printed_entries(slurp(shop.dir / "verify.log")),
            verify["verify"]["entries"].get<long>())
      << slurp(shop.dir / "verify.log");
  // The entries are where the flags said: in the database, not some folder.
  auto db = url.empty() ? open_sqlite((shop.dir / "data").string()) : open_postgres(url);
  ASSERT_TRUE(db);
  auto rows = (*db)->query("SELECT COUNT(*) FROM audit");
  ASSERT_TRUE(rows);
  EXPECT_EQ(rows->front().integer(0), verify["verify"]["entries"].get<long>());
}

INSTANTIATE_TEST_SUITE_P(Backends, ServeCliStore,
                         ::testing::Values(Backend::Sqlite, Backend::Postgres), test::backend_name);

TEST(ServeCliMore, ALinkLostDuringAFeedEndsTheJobInterruptedAndNothingRestartsIt) {
  if (!have_socat()) GTEST_SKIP() << "socat is not installed";
  FeedUnderWay f("lost");
  ASSERT_NO_FATAL_FAILURE(f.start());
  const Shop& shop = f.shop;
  const Api& c = *f.api;
  const std::string& token = f.token;
  const std::string& id = f.id;
  Control& control = f.control;
  SocatPair& socat = f.socat;
  const pid_t server = f.server;
  // The cable is pulled: socat goes, and with it both ends of the pair.
  // (Closing only the control's end is not seen: socat keeps reading the
  // server's bytes and the feed runs to its end, as over a cable with no
  // handshake lines.)
  control.close();
  socat.stop();
  const auto job = ended(c, token, id);
  EXPECT_EQ(job["state"], "interrupted") << job.dump();
  const std::string reason = job.value("reason", "");
  EXPECT_NE(reason.find("link lost"), std::string::npos) << reason;
  EXPECT_NE(reason.find("interrupted at byte"), std::string::npos) << reason;
  EXPECT_GT(job["bytes_sent"].get<std::uint64_t>(), 0u);
  EXPECT_LT(job["bytes_sent"].get<std::uint64_t>(), job["bytes_total"].get<std::uint64_t>());
  EXPECT_FALSE(job["line"].is_null()) << job.dump();
  const auto ends = job_entries(c, token, "job.interrupted", id);
  ASSERT_EQ(ends.size(), 1u) << c.get("/api/audit", token).body;
  EXPECT_EQ(ends[0]["reason"], reason);
  // The cable is plugged back in: the station reopens its port (it tries
  // every 10 s) and is idle; the job is not sent again, nor a new one made.
  fs::remove(shop.dir / "control");
  fs::remove(shop.dir / "machine");
  SocatPair again{shop.dir};
  ASSERT_TRUE(again.start());
  Control back;
  ASSERT_TRUE(back.start(shop.dir / "control"));
  nlohmann::json mill = mill_when(c, token, "idle");
  ASSERT_EQ(mill["state"], "idle") << mill.dump();
  std::this_thread::sleep_for(2s);
  mill = c.get("/api/machines/mill-1", token).json();
  EXPECT_TRUE(mill["job"].is_null()) << mill.dump();
  EXPECT_TRUE(mill["queue"].empty()) << mill.dump();
  EXPECT_EQ(back.received(), 0u);
  const auto later = c.get("/api/jobs/" + id, token).json();
  EXPECT_EQ(later["state"], "interrupted");
  EXPECT_EQ(later["bytes_sent"], job["bytes_sent"]);
  EXPECT_EQ(c.get("/api/jobs/" + std::to_string(std::stoi(id) + 1), token).status, 404);
  EXPECT_EQ(job_entries(c, token, "job.create", id).size(), 1u);
  ::kill(server, SIGTERM);
  EXPECT_EQ(wait_exit(server), 0) << slurp(shop.dir / "serve.log");
}

}  // namespace
}  // namespace usina::dnc
