// `usina serve` in-process for the API tests: a store in a scratch folder
// with a user of each role, the server on 127.0.0.1 port 0, its event loop
// on a thread of its own; the tests speak HTTP to it (api_client.hpp).
#pragma once

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <memory>
#include <string>
#include <thread>

#include <boost/asio/post.hpp>
#include <gtest/gtest.h>

#include "api_client.hpp"
#include "dnc/server.hpp"
#include "dnc/store_db.hpp"
#include "dnc/store_users.hpp"

namespace usina::test {

inline const std::string kPassword = "correct horse 1";

inline dnc::StoreOptions fast_store() {
  dnc::StoreOptions o;
  o.password_ops = 1;  // libsodium's minimum: the tests log in often
  o.password_memory = 8192;
  return o;
}

// A new database on ctest's shared PostgreSQL cluster (USINA_TEST_PG_DIR,
// tests/CMakeLists.txt); its URL, empty when there is none.
inline std::string fresh_pg_database() {
  const char* dir = std::getenv("USINA_TEST_PG_DIR");
  if (dir == nullptr) return {};
  std::ifstream in(std::string(dir) + "/url");
  std::string url;
  std::getline(in, url);
  auto admin = dnc::open_postgres(url);
  if (!admin) return {};
  static int made = 0;
  const std::string name = "s" + std::to_string(::getpid()) + "_" + std::to_string(++made);
  if (!(*admin)->script("CREATE DATABASE " + name)) return {};
  return url.substr(0, url.rfind('/') + 1) + name;
}

class RunningServer {
 public:
  RunningServer() {
    static int made = 0;
    dir_ = (std::filesystem::temp_directory_path() /
            ("usina_serve_" + std::to_string(::getpid()) + "_" + std::to_string(++made)))
               .string();
    std::filesystem::remove_all(dir_);
  }

  ~RunningServer() {
    stop();
    server_.reset();
    std::filesystem::remove_all(dir_);
  }

  RunningServer(const RunningServer&) = delete;
  RunningServer& operator=(const RunningServer&) = delete;

  boost::asio::io_context& io() { return io_; }

  // The store: a postgresql:// URL instead of the scratch folder.
  void use_store(std::string where) { where_ = std::move(where); }

  const std::string& dir() const { return dir_; }

  // Where the store is: the scratch folder, or the PostgreSQL URL.
  const std::string& where() const { return where_.empty() ? dir_ : where_; }

  // Opens the store (users of every role on a new one) and starts serving.
  void start(dnc::ServerConfig config = {}, dnc::StoreOptions options = fast_store()) {
    // ctest's dnc.http.postgres runs the HTTP suites again with the store
    // in PostgreSQL (a fresh database each server), as a plant would.
    if (where_.empty() && std::getenv("USINA_TEST_SERVER_STORE") != nullptr) {
      where_ = fresh_pg_database();
      ASSERT_FALSE(where_.empty()) << "no database on the cluster of USINA_TEST_PG_DIR";
    }
    auto s = dnc::Server::open(io_, where_.empty() ? dir_ : where_, std::move(config), options);
    ASSERT_TRUE(s) << s.error();
    server_ = std::move(*s);
    add_users();
    const std::string error = server_->start("127.0.0.1:0");
    ASSERT_EQ(error, "");
    port_ = server_->endpoint().port();
    thread_ = std::thread([this] { io_.run(); });
  }

  // Stops the server the way SIGTERM does, and waits for it.
  void stop() {
    if (!thread_.joinable()) return;
    boost::asio::post(
        io_, [this] { server_->stop("the test stopped the server", [this] { io_.stop(); }); });
    thread_.join();
  }

  // Runs `f` on the server's loop and waits for it (what the loop owns is read there).
  template <typename F>
  auto on_loop(F f) -> decltype(f()) {
    std::packaged_task<decltype(f())()> task(std::move(f));
    auto result = task.get_future();
    boost::asio::post(io_, [&task] { task(); });
    return result.get();
  }

  ApiClient client() const { return ApiClient(port_); }

  dnc::Server& server() { return *server_; }

 private:
  void add_users() {
    dnc::Store& store = server_->store();
    if (dnc::find_user(store, "boss")) return;
    ASSERT_TRUE(dnc::create_first_admin(store, "boss", kPassword));
    const dnc::Actor by{"boss", "test"};
    ASSERT_TRUE(dnc::create_user(store, "prog", dnc::Role::Programmer, kPassword, by));
    ASSERT_TRUE(dnc::create_user(store, "appr", dnc::Role::Approver, kPassword, by));
    ASSERT_TRUE(dnc::create_user(store, "oper", dnc::Role::Operator, kPassword, by));
  }

  std::string dir_;
  std::string where_;
  boost::asio::io_context io_;
  std::unique_ptr<dnc::Server> server_;
  std::thread thread_;
  unsigned short port_ = 0;
};

}  // namespace usina::test
