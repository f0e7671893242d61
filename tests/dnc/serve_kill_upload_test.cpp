// kill -9 of the real `usina serve` during uploads (issue 13): a request
// whose body is half sent, and uploads in flight at a random moment. After
// the restart the store holds only whole revisions (each one's bytes hash to
// its name), every upload the server acknowledged, and an audit chain that
// holds. store_crash_test.cpp kills the store's own transaction; this kills
// the whole server with its HTTP reader, checker and store, on SQLite and
// on PostgreSQL.
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <boost/asio/write.hpp>
#include <gtest/gtest.h>

#include "api_client.hpp"
#include "dnc/sha256.hpp"
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

// A scratch folder, and the store's flags: SQLite in the folder, or a fresh
// database on the test's PostgreSQL cluster (tests/dnc/pg_cluster.sh).
struct Shop {
  fs::path dir = fs::temp_directory_path() / ("usina_kill_upload_" + std::to_string(::getpid()));
  std::vector<std::string> flags;

  Shop() {
    fs::remove_all(dir);
    fs::create_directories(dir);
    write(dir / "pw", kPassword + "\n");
    write(dir / "usina-serve.toml", "");
    flags = {"--data", (dir / "data").string()};
  }

  ~Shop() { fs::remove_all(dir); }

  const std::vector<std::string>& store() const { return flags; }

  pid_t serve(const std::string& log) const {
    std::vector<std::string> args{"serve", "--config", (dir / "usina-serve.toml").string(),
                                  "--listen", "127.0.0.1:0"};
    for (const std::string& s : store())
      args.push_back(s);
    return spawn_usina(args, dir / log);
  }
};

// A program of about 200 KB, different for each n.
std::string program(int n) {
  std::string text = "%\nO" + std::to_string(1000 + n) + "\n";
  for (int k = 0; k < 8000; ++k)
    text += "G1 X" + std::to_string((k * 7 + n) % 300) + " Y" + std::to_string(k % 50) + " F800\n";
  return text + "M30\n%\n";
}

// Sends a POST whose body is cut at half; the socket stays open.
boost::asio::ip::tcp::socket half_sent_upload(boost::asio::io_context& io, unsigned short port,
                                              const std::string& token) {
  const std::string body = nlohmann::json{{"name", "HALF"}, {"text", program(999)}}.dump();
  const std::string head =
      "POST /api/programs HTTP/1.1\r\nHost: 127.0.0.1\r\n"
      "Authorization: Bearer " +
      token +
      "\r\nContent-Type: application/json\r\nContent-Length: " + std::to_string(body.size()) +
      "\r\n\r\n";
  boost::asio::ip::tcp::socket s(io);
  s.connect({boost::asio::ip::make_address("127.0.0.1"), port});
  boost::asio::write(s, boost::asio::buffer(head + body.substr(0, body.size() / 2)));
  return s;
}

// Uploads program after program until the server is gone; what it acknowledged.
struct Uploader {
  std::mutex mutex;
  std::vector<std::pair<std::string, std::string>> acknowledged;  // name, revision
  std::atomic<int> count{0};
  std::thread thread;

  void start(unsigned short port, const std::string& token) {
    thread = std::thread([this, port, token] {
      const Api c(port);
      for (int n = 0; n < 10'000; ++n) {
        const std::string name = "O" + std::to_string(1000 + n);
        try {
          const Reply r = c.post("/api/programs", {{"name", name}, {"text", program(n)}}, token);
          if (r.status != 201) return;
          const std::lock_guard lock(mutex);
          acknowledged.emplace_back(name, r.json()["revision"].get<std::string>());
          ++count;
        } catch (const std::exception&) {
          return;  // the server died under the request
        }
      }
    });
  }

  ~Uploader() {
    if (thread.joinable()) thread.join();
  }
};

// Every revision of every program in the library: its bytes hash to its name.
std::set<std::pair<std::string, std::string>> whole_revisions(const Api& c,
                                                              const std::string& token) {
  std::set<std::pair<std::string, std::string>> found;
  const auto page = c.get("/api/programs?limit=1000", token).json();
  for (const auto& p : page["programs"]) {
    const std::string name = p["name"];
    const auto program = c.get("/api/programs/" + name, token).json();
    for (const auto& r : program["revisions"]) {
      const std::string rev = r["revision"];
      const Reply text = c.get("/api/programs/" + name + "/revisions/" + rev + "/text", token);
      EXPECT_EQ(text.status, 200) << name << " " << rev << ": " << text.body;
      EXPECT_EQ(sha256_hex(std::string_view(text.body)), rev) << name;
      found.emplace(name, rev);
    }
  }
  return found;
}

class ServeKillUpload : public ::testing::TestWithParam<Backend> {};

TEST_P(ServeKillUpload, Kill9AmongUploadsLeavesWholeRevisionsAndEveryAcknowledgedOne) {
  Shop shop;
  if (GetParam() == Backend::Postgres) {
    test::PgServer& pg = test::PgServer::get();
    if (!pg.ok()) GTEST_SKIP() << pg.why_not();
    const std::string url = pg.fresh_database();
    ASSERT_FALSE(url.empty()) << "cannot create a database on the test cluster";
    shop.flags = {"--store", url};
  }
  std::vector<std::string> init_args{"serve", "--init",          "--admin",
                                     "boss",  "--password-file", (shop.dir / "pw").string()};
  init_args.insert(init_args.end(), shop.store().begin(), shop.store().end());
  const pid_t init = spawn_usina(init_args, shop.dir / "init.log");
  ASSERT_EQ(wait_exit(init), 0) << slurp(shop.dir / "init.log");
  const pid_t first = shop.serve("serve.log");
  const unsigned short port = listening_port(shop.dir / "serve.log");
  ASSERT_NE(port, 0) << slurp(shop.dir / "serve.log");
  const Api c(port);
  const std::string token = c.log_in("boss", kPassword);
  ASSERT_FALSE(token.empty());
  boost::asio::io_context io;
  auto half = half_sent_upload(io, port, token);
  Uploader uploads;
  uploads.start(port, token);
  // A few uploads through, then the kill at a moment the test cannot choose.
  for (int i = 0; i < 1200 && uploads.count < 3; ++i)
    std::this_thread::sleep_for(25ms);
  ASSERT_GE(uploads.count, 3) << slurp(shop.dir / "serve.log");
  std::mt19937 random(std::random_device{}());
  std::this_thread::sleep_for(std::chrono::milliseconds(random() % 200));
  ASSERT_EQ(::kill(first, SIGKILL), 0);
  EXPECT_EQ(wait_exit(first), 128 + SIGKILL);
  uploads.thread.join();

  const pid_t second = shop.serve("serve2.log");
  const unsigned short port2 = listening_port(shop.dir / "serve2.log");
  ASSERT_NE(port2, 0) << slurp(shop.dir / "serve2.log");
  const Api c2(port2);
  const std::string token2 = c2.log_in("boss", kPassword);
  ASSERT_FALSE(token2.empty());
  const auto found = whole_revisions(c2, token2);
  EXPECT_EQ(c2.get("/api/programs/HALF", token2).status, 404) << "a half-sent upload was stored";
  for (const auto& ack : uploads.acknowledged)
    EXPECT_TRUE(found.contains(ack)) << ack.first << " was acknowledged and is gone";
  // At most the one upload under way when the server died is there unacknowledged.
  EXPECT_LE(found.size(), uploads.acknowledged.size() + 1);
  const auto verify = c2.get("/api/audit?verify=1", token2).json();
  EXPECT_EQ(verify["ok"], true) << verify.dump();
  ::kill(second, SIGTERM);
  EXPECT_EQ(wait_exit(second), 0) << slurp(shop.dir / "serve2.log");
}

INSTANTIATE_TEST_SUITE_P(Backends, ServeKillUpload,
                         ::testing::Values(Backend::Sqlite, Backend::Postgres), test::backend_name);

}  // namespace
}  // namespace usina::dnc
