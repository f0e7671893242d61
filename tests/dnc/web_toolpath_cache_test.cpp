// The tool-path route off the event loop (web_toolpath_service.hpp,
// docs/web.md "The tool-path cache"): a stream is computed once on the
// pool and then served from the bounded cache; the loop answers other
// routes while a run is in progress; requests for a run in progress join it.
#include "dnc/web_toolpath_cache.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "dnc/web_toolpath_service.hpp"
#include "pool_gate.hpp"
#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

using test::Gate;
using test::ReleaseOnExit;

ToolpathStream bytes_of(std::size_t n) {
  return std::make_shared<const std::string>(n, 'x');
}

TEST(WebToolpathCache, TheLeastRecentlyUsedGoesFirstPastTheByteBound) {
  ToolpathCache cache({.bytes = 300, .entries = 10});
  cache.put("a", bytes_of(100));
  cache.put("b", bytes_of(100));
  cache.put("c", bytes_of(100));
  ASSERT_NE(cache.find("a"), nullptr);  // a is now the most recent
  cache.put("d", bytes_of(100));
  EXPECT_EQ(cache.find("b"), nullptr);
  EXPECT_NE(cache.find("a"), nullptr);
  EXPECT_NE(cache.find("c"), nullptr);
  EXPECT_NE(cache.find("d"), nullptr);
  EXPECT_EQ(cache.bytes(), 300u);
  EXPECT_EQ(cache.evicted(), 1u);
}

TEST(WebToolpathCache, TheCountOfStreamsIsBoundedToo) {
  ToolpathCache cache({.bytes = 1000, .entries = 2});
  cache.put("a", bytes_of(1));
  cache.put("b", bytes_of(1));
  cache.put("c", bytes_of(1));
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.find("a"), nullptr);
}

TEST(WebToolpathCache, AStreamLargerThanTheBoundIsNotKept) {
  ToolpathCache cache({.bytes = 100, .entries = 10});
  cache.put("small", bytes_of(50));
  cache.put("big", bytes_of(101));
  EXPECT_EQ(cache.find("big"), nullptr);
  EXPECT_NE(cache.find("small"), nullptr);  // not evicted for one it would not keep
  EXPECT_EQ(cache.bytes(), 50u);
}

TEST(WebToolpathCache, TheKeyHoldsTheRevisionTheDialectAndTheBudget) {
  EXPECT_NE(toolpath_key("ab", "romi", 100), toolpath_key("ab", "fanuc", 100));
  EXPECT_NE(toolpath_key("ab", "romi", 100), toolpath_key("ab", "romi", 101));
  EXPECT_NE(toolpath_key("ab", "romi", 100), toolpath_key("ac", "romi", 100));
}

// An answer with the header that says where the stream came from.
struct Got {
  int status = 0;
  std::string from;  // X-Toolpath-Cache
  std::string body;
};

Got get_toolpath(unsigned short port, const std::string& target, const std::string& token) {
  boost::asio::io_context io;
  test::beast::tcp_stream stream(io);
  stream.connect(boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), port));
  test::bhttp::request<test::bhttp::string_body> req{test::bhttp::verb::get, target, 11};
  req.set(test::bhttp::field::host, "127.0.0.1");
  req.set(test::bhttp::field::authorization, "Bearer " + token);
  test::bhttp::write(stream, req);
  test::beast::flat_buffer buffer;
  test::bhttp::response_parser<test::bhttp::string_body> parser;
  parser.body_limit(1ull << 30);
  test::bhttp::read(stream, buffer, parser);
  Got g;
  g.status = static_cast<int>(parser.get().result_int());
  if (auto it = parser.get().find("X-Toolpath-Cache"); it != parser.get().end())
    g.from = std::string(it->value());
  g.body = parser.get().body();
  return g;
}

std::string long_program(int blocks) {
  std::string text = "G0 X0 Y0\nG1 F1000\n";
  for (int i = 0; i < blocks; ++i)
    text += fmt::format("X{:.3f} Y{:.3f}\n", std::cos(i * 0.001) * i * 0.01,
                        std::sin(i * 0.001) * i * 0.01);
  return text + "M2\n";
}

struct Uploaded {
  std::string oper;
  std::string route;
};

Uploaded upload(test::RunningServer& server, int blocks) {
  const test::ApiClient client = server.client();
  const std::string prog = client.log_in("prog", test::kPassword);
  const test::Reply up =
      client.post("/api/programs", {{"name", "O1"}, {"text", long_program(blocks)}}, prog);
  EXPECT_EQ(up.status, 201) << up.body;
  const std::string rev = up.json().value("revision", "");
  return {client.log_in("oper", test::kPassword),
          "/api/programs/O1/revisions/" + rev + "/toolpath"};
}

TEST(WebToolpathRoute, ASecondRequestIsServedFromTheCache) {
  test::RunningServer server;
  server.start();
  const Uploaded u = upload(server, 2'000);
  const Got first = get_toolpath(server.client().port(), u.route, u.oper);
  ASSERT_EQ(first.status, 200);
  EXPECT_EQ(first.from, "computed");
  const Got second = get_toolpath(server.client().port(), u.route, u.oper);
  ASSERT_EQ(second.status, 200);
  EXPECT_EQ(second.from, "hit");
  EXPECT_EQ(second.body, first.body);
  const Got other = get_toolpath(server.client().port(), u.route + "?max_vertices=100", u.oper);
  EXPECT_EQ(other.from, "computed");  // another budget, another stream
  const ToolpathCounters n = server.on_loop([&] { return server.server().toolpaths().counters(); });
  EXPECT_EQ(n.computed, 2u);
  EXPECT_EQ(n.hits, 1u);
  EXPECT_EQ(get_toolpath(server.client().port(), u.route, "").status, 401);  // the cache asks too
}

TEST(WebToolpathRoute, TheLoopAnswersOtherRoutesWhileAToolpathIsComputed) {
  Gate gate;
  test::RunningServer server;
  server.start();
  server.server().toolpaths().before_run = [&gate] { gate.enter(); };
  const Uploaded u = upload(server, 100'000);
  std::atomic<int> finished{0};
  int toolpath_done = 0;
  Got path;
  std::jthread viewer([&] {
    path = get_toolpath(server.client().port(), u.route, u.oper);
    toolpath_done = ++finished;
  });
  ReleaseOnExit release{gate};        // before the thread is joined
  ASSERT_TRUE(gate.wait_entered(1));  // the run is on the pool, held there
  // The loop is free: a login and the library answer while the run is held.
  const test::ApiClient client = server.client();
  const std::string token = client.log_in("appr", test::kPassword);
  EXPECT_FALSE(token.empty());
  const test::Reply list = client.get("/api/programs", token);
  const int list_done = ++finished;
  EXPECT_EQ(list.status, 200);
  gate.release();
  viewer.join();
  EXPECT_EQ(path.status, 200);
  EXPECT_EQ(path.body.substr(0, 4), "USTP");
  EXPECT_LT(list_done, toolpath_done);
}

TEST(WebToolpathRoute, RequestsForARunInProgressShareIt) {
  Gate gate;
  test::RunningServer server;
  server.start();
  server.server().toolpaths().before_run = [&gate] { gate.enter(); };
  const Uploaded u = upload(server, 2'000);
  Got a;
  Got b;
  std::jthread first([&] { a = get_toolpath(server.client().port(), u.route, u.oper); });
  ReleaseOnExit release_first{gate};
  ASSERT_TRUE(gate.wait_entered(1));
  std::jthread second([&] { b = get_toolpath(server.client().port(), u.route, u.oper); });
  ReleaseOnExit release_second{gate};
  // Until the second request has joined the run (polled; a guard, not a time).
  for (int i = 0; i < 1200; ++i) {
    if (server.on_loop([&] { return server.server().toolpaths().counters().joined; }) == 1) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  gate.release();
  first.join();
  second.join();
  EXPECT_EQ(a.from, "computed");
  EXPECT_EQ(b.from, "joined");
  EXPECT_EQ(a.body, b.body);
  EXPECT_EQ(server.on_loop([&] { return server.server().toolpaths().counters().computed; }), 1u);
}

TEST(WebToolpathRoute, ARunThatThrowsIsA500AndNotKept) {
  test::RunningServer server;
  server.start();
  std::atomic<bool> fail{true};
  server.server().toolpaths().before_run = [&fail] {
    if (fail) throw std::runtime_error("std::bad_alloc");  // as a run past the memory would
  };
  const Uploaded u = upload(server, 100);
  const Got failed = get_toolpath(server.client().port(), u.route, u.oper);
  EXPECT_EQ(failed.status, 500);
  EXPECT_NE(failed.body.find("the tool path could not be computed: std::bad_alloc"),
            std::string::npos)
      << failed.body;
  fail = false;
  const Got next = get_toolpath(server.client().port(), u.route, u.oper);
  EXPECT_EQ(next.status, 200);
  EXPECT_EQ(next.from, "computed");  // the failure was not kept
  EXPECT_EQ(server.on_loop([&] { return server.server().toolpaths().counters().failed; }), 1u);
}

}  // namespace
}  // namespace usina::dnc
