// What the store tests share: a store on each back end (SQLite in a temp
// folder; PostgreSQL in a throw-away cluster this process starts with
// pg_cluster.sh, a fresh database per test), a clock the test moves, cheap
// password hashing, and raw SQL for the tests that tamper with the database.
#pragma once

#include <stdlib.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <sys/wait.h>

#include "dnc/store.hpp"
#include "dnc/store_db.hpp"

namespace usina::dnc::test {

// One PostgreSQL server per test process, stopped when the process ends.
class PgServer {
 public:
  static PgServer& get() {
    static PgServer server;
    return server;
  }

  bool ok() const { return !url_.empty(); }

  const std::string& why_not() const { return why_not_; }

  // A new empty database on the server; its URL.
  std::string fresh_database() {
    const std::string name = "t" + std::to_string(::getpid()) + "_" + std::to_string(++databases_);
    auto admin = open_postgres(url_);
    if (!admin) return {};
    if (!(*admin)->script("CREATE DATABASE " + name)) return {};
    return url_.substr(0, url_.rfind('/') + 1) + name;
  }

  ~PgServer() {
    if (!dir_.empty()) run("stop " + dir_);
  }

  PgServer(const PgServer&) = delete;
  PgServer& operator=(const PgServer&) = delete;

 private:
  PgServer() {
    // ctest's fixture (tests/CMakeLists.txt) shares one cluster with every test.
    if (const char* shared = std::getenv("USINA_TEST_PG_DIR")) {
      std::ifstream in(std::string(shared) + "/url");
      std::getline(in, url_);
      if (url_.starts_with("postgresql://") && open_postgres(url_)) return;
      url_.clear();
    }
    char tmpl[] = "/tmp/usina-pg-XXXXXX";
    if (::mkdtemp(tmpl) == nullptr) {
      why_not_ = "cannot make a temporary folder";
      return;
    }
    dir_ = tmpl;
    std::string out;
    const int status = run("start " + dir_, &out);
    if (status == 0 && out.starts_with("postgresql://")) {
      url_ = out;
    } else if (status == 77) {
      why_not_ =
          "PostgreSQL is not installed (initdb/pg_ctl not found); install Debian's "
          "postgresql package (scripts/setup.sh) to run the PostgreSQL half";
    } else {
      why_not_ = "the throw-away PostgreSQL cluster did not start (tests/dnc/pg_cluster.sh)";
    }
  }

  static int run(const std::string& args, std::string* out = nullptr) {
    const std::string cmd =
        "bash '" USINA_TEST_DIR "/dnc/pg_cluster.sh' " + args + (out ? "" : " >/dev/null");
    std::FILE* p = ::popen(cmd.c_str(), "r");
    if (p == nullptr) return -1;
    char buf[512];
    while (std::fgets(buf, sizeof buf, p) != nullptr) {
      if (out) *out += buf;
    }
    const int status = ::pclose(p);
    if (out) {
      while (!out->empty() && (out->back() == '\n' || out->back() == '\r'))
        out->pop_back();
    }
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  std::string dir_;
  std::string url_;
  std::string why_not_;
  int databases_ = 0;
};

// Removes a folder when the test ends.
struct TempFolder {
  TempFolder() {
    char tmpl[] = "/tmp/usina-store-test-XXXXXX";
    path = ::mkdtemp(tmpl) != nullptr ? tmpl : "";
  }

  ~TempFolder() {
    std::error_code ec;
    if (!path.empty()) std::filesystem::remove_all(path, ec);
  }

  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  std::string path;
};

// A store test, run once per back end (INSTANTIATE with kBackends).
class StoreTest : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override {
    if (GetParam() == Backend::Sqlite) {
      where_ = tmp_.path + "/store";
      return;
    }
    PgServer& pg = PgServer::get();
    if (!pg.ok()) GTEST_SKIP() << pg.why_not();
    where_ = pg.fresh_database();
    ASSERT_FALSE(where_.empty()) << "cannot create a database on the test cluster";
  }

  StoreOptions options() {
    StoreOptions o;
    o.now_us = [this] { return now_us; };
    o.password_ops = 1;  // libsodium's minimum: the tests hash many passwords
    o.password_memory = 8192;
    return o;
  }

  std::unique_ptr<Store> open(StoreOptions o) {
    auto s = Store::open(where_, std::move(o));
    EXPECT_TRUE(s.has_value()) << (s ? "" : s.error().message);
    return s ? std::move(*s) : nullptr;
  }

  std::unique_ptr<Store> open() { return open(options()); }

  // A second connection, for what the store itself would refuse to do.
  std::unique_ptr<Database> raw() {
    auto db = GetParam() == Backend::Sqlite ? open_sqlite(where_) : open_postgres(where_);
    EXPECT_TRUE(db.has_value());
    return db ? std::move(*db) : nullptr;
  }

  // "DROP TRIGGER name" in each back end's spelling.
  void drop_trigger(Database& db, const std::string& name, const std::string& table) {
    const std::string sql = GetParam() == Backend::Sqlite ? "DROP TRIGGER " + name
                                                          : "DROP TRIGGER " + name + " ON " + table;
    ASSERT_TRUE(db.script(sql)) << sql;
  }

  const std::string& where() const { return where_; }

  std::int64_t now_us = 1'780'000'000'000'000;  // 2026-05-28, moved by the tests
  TempFolder tmp_;

 private:
  std::string where_;
};

inline std::string backend_name(const ::testing::TestParamInfo<Backend>& info) {
  return info.param == Backend::Sqlite ? "Sqlite" : "Postgres";
}

#define USINA_STORE_BACKENDS(Suite)                                                      \
  INSTANTIATE_TEST_SUITE_P(                                                              \
      Backends, Suite,                                                                   \
      ::testing::Values(::usina::dnc::Backend::Sqlite, ::usina::dnc::Backend::Postgres), \
      ::usina::dnc::test::backend_name)

}  // namespace usina::dnc::test
