// The server's whole road, upload to a job done at the control, on both
// stores: SQLite and the throw-away PostgreSQL cluster (store_fixture.hpp).
#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "dnc/link_serial.hpp"
#include "dnc/sha256.hpp"
#include "dnc/sim_cnc.hpp"
#include "server_fixture.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

namespace srv = ::usina::test;

class ApiOnBothStores : public test::StoreTest {};

TEST_P(ApiOnBothStores, AReleasedProgramIsSentAndTheJobIsDoneWithItsHash) {
  srv::RunningServer s;
  if (GetParam() == Backend::Postgres) s.use_store(where());
  auto pair = open_pty_pair(s.io());
  ASSERT_TRUE(pair) << pair.error();
  SimCncConfig sc;
  auto sim = std::make_shared<SimCnc>(s.io(), *pair->master, sc);
  sim->start();
  ServerConfig config;
  ServerMachine m;
  m.link.name = "mill-1";
  m.link.port = pair->slave_path;
  m.link.baud = 115200;
  m.link.code = TapeCode::Ascii;
  m.link.data_bits = 8;
  m.link.parity = Parity::None;
  m.link.leader = 0;
  m.link.trailer = 0;
  config.machines.push_back(m);
  s.start(config);
  const srv::ApiClient c = s.client();
  const std::string prog = c.log_in("prog", srv::kPassword);
  const std::string appr = c.log_in("appr", srv::kPassword);
  const std::string text = "G0 X1\nG1 X2 F100\nM2\n";
  const std::string rev =
      c.post("/api/programs", {{"name", "O900"}, {"text", text}}, prog).json()["revision"];
  EXPECT_EQ(rev, sha256_hex(std::string_view(text)));
  const auto move = [&](const std::string& token, const char* state) {
    return c.post("/api/programs/O900/revisions/" + rev + "/state", {{"state", state}}, token)
        .status;
  };
  EXPECT_EQ(move(prog, "checked"), 200);
  EXPECT_EQ(move(appr, "approved"), 200);
  EXPECT_EQ(move(appr, "released"), 200);
  const auto job = c.post("/api/machines/mill-1/jobs",
                          {{"program", "O900"}, {"revision", rev}, {"mode", "drip"}}, prog);
  ASSERT_EQ(job.status, 201) << job.body;
  nlohmann::json got;
  for (int i = 0; i < 2400; ++i) {
    got = c.get("/api/jobs/" + std::to_string(job.json()["job"].get<int>()), prog).json();
    if (got["state"] == "done" || got["state"] == "failed" || got["state"] == "interrupted") break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_EQ(got["state"], "done") << got.dump();
  EXPECT_EQ(got["sha256"], sha256_hex(std::string_view("%\nG0 X1\nG1 X2 F100\nM2\n%")));
  const auto audit = c.get("/api/audit?verify=1", appr).json();
  EXPECT_EQ(audit["ok"], true);
  EXPECT_EQ(c.get("/api/machines/mill-1", prog).json()["part_count"], 1);
}

USINA_STORE_BACKENDS(ApiOnBothStores);

}  // namespace
}  // namespace usina::dnc
