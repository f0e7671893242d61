// Tool-life count resets: stored with their audit entry on SQLite and
// PostgreSQL, each tool counted from its last reset (and from the range
// when one is given), and POST /api/machines/{m}/tools/{t}/reset over HTTP.
#include <algorithm>

#include <gtest/gtest.h>

#include "api_control.hpp"
#include "dnc/api_router.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_parts.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/store_tool_resets.hpp"
#include "dnc/store_utilisation.hpp"
#include "store_fixture.hpp"

namespace usina::dnc {
namespace {

constexpr std::int64_t kDay = 86'400'000'000;
constexpr std::int64_t kHour = 3'600'000'000;
constexpr std::int64_t kMinute = 60'000'000;
constexpr std::int64_t kMay28 = 20601;  // 2026-05-28 in days since 1970

// T1 then T2, each a short cut.
const std::string kTwoTools = "T1 M6\nG1 X10 F100\nT2 M6\nG1 X-10 F100\nM2\n";

class ToolResetOnBothStores : public test::StoreTest {};

const ToolUse* tool(const ToolLife& life, int number) {
  const auto it = std::find_if(life.tools.begin(), life.tools.end(),
                               [number](const ToolUse& t) { return t.tool == number; });
  return it == life.tools.end() ? nullptr : &*it;
}

TEST_P(ToolResetOnBothStores, EachToolCountsFromItsLastResetUnlessARangeIsGiven) {
  now_us = kMay28 * kDay;
  auto store = open();
  ASSERT_TRUE(store);
  auto put = put_revision(*store, {"O1", "", "rs274ngc", kTwoTools, "r", nullptr}, {"ana", "t"});
  ASSERT_TRUE(put) << put.error().message;
  const std::string rev = put->revision.hash;
  // Parts at 01:00, 02:00, 03:00; T1 reset at 01:30 and again at 02:30; T7 reset, never used.
  for (int h : {1, 2, 3})
    ASSERT_TRUE(record_control_part(*store, {"m1", now_us + h * kHour, {}, {}, "O1", rev}));
  ASSERT_TRUE(record_control_part(*store, {"m2", now_us + 2 * kHour, {}, {}, "O1", rev}));
  const Actor oper{"olga", "127.0.0.1"};
  now_us = kMay28 * kDay + 90 * kMinute;
  ASSERT_TRUE(reset_tool(*store, oper, "m1", 1, "insert chipped"));
  now_us = kMay28 * kDay + 150 * kMinute;
  auto last = reset_tool(*store, oper, "m1", 1, "new insert");
  ASSERT_TRUE(last) << last.error().message;
  ASSERT_TRUE(reset_tool(*store, oper, "m1", 7, ""));
  now_us = (kMay28 + 1) * kDay;

  auto life = tool_life(*store, "m1", 0, now_us, true);
  ASSERT_TRUE(life) << life.error().message;
  EXPECT_EQ(life->parts, 3);
  ASSERT_NE(tool(*life, 1), nullptr);
  EXPECT_EQ(tool(*life, 1)->parts, 1);  // the 03:00 part only
  EXPECT_TRUE(tool(*life, 1)->from_reset);
  EXPECT_EQ(tool(*life, 1)->reset->at_us, last->at_us);
  EXPECT_EQ(tool(*life, 1)->reset->reason, "new insert");
  EXPECT_EQ(tool(*life, 1)->reset->by, "olga");
  ASSERT_NE(tool(*life, 2), nullptr);
  EXPECT_EQ(tool(*life, 2)->parts, 3);  // never reset
  EXPECT_FALSE(tool(*life, 2)->reset.has_value());
  ASSERT_NE(tool(*life, 7), nullptr);
  EXPECT_EQ(tool(*life, 7)->parts, 0);  // reset, not used since

  // A range counts every part in it, the resets only shown.
  auto ranged = tool_life(*store, "m1", 0, now_us, false);
  ASSERT_TRUE(ranged);
  EXPECT_EQ(tool(*ranged, 1)->parts, 3);
  EXPECT_FALSE(tool(*ranged, 1)->from_reset);
  EXPECT_TRUE(tool(*ranged, 1)->reset.has_value());
  // Another machine's resets are its own.
  auto other = tool_life(*store, "m2", 0, now_us, true);
  ASSERT_TRUE(other);
  EXPECT_EQ(tool(*other, 1)->parts, 1);
  EXPECT_FALSE(tool(*other, 1)->reset.has_value());
}

TEST_P(ToolResetOnBothStores, AResetIsAnAuditEntryAndABadOneWritesNothing) {
  auto store = open();
  ASSERT_TRUE(store);
  ASSERT_TRUE(reset_tool(*store, {"olga", "10.0.0.7"}, "m1", 12, "cutter changed"));
  EXPECT_EQ(reset_tool(*store, {"olga", ""}, "m1", -1, "").error().kind, StoreErrorKind::Invalid);
  EXPECT_EQ(reset_tool(*store, {"olga", ""}, "m1", kMaxToolNumber + 1, "").error().kind,
            StoreErrorKind::Invalid);
  EXPECT_EQ(reset_tool(*store, {"olga", ""}, "m1", 3, std::string("a\0b", 3)).error().kind,
            StoreErrorKind::Invalid);
  auto entries = read_audit(*store, 0, 100);
  ASSERT_TRUE(entries);
  ASSERT_EQ(entries->size(), 1u);
  EXPECT_EQ(entries->back().action, "tool.reset");
  EXPECT_EQ(entries->back().subject, "m1/T12");
  EXPECT_EQ(entries->back().reason, "cutter changed");
  EXPECT_EQ(entries->back().origin, "10.0.0.7");
  auto resets = last_tool_resets(*store, "m1", now_us);
  ASSERT_TRUE(resets);
  EXPECT_EQ(resets->size(), 1u);
  auto verdict = verify_audit(*store);
  ASSERT_TRUE(verdict);
  EXPECT_TRUE(verdict->ok);
}

USINA_STORE_BACKENDS(ToolResetOnBothStores);

std::int64_t drip(const ApiClient& c, const std::string& token, const std::string& rev) {
  const auto job = c.post("/api/machines/mill-1/jobs",
                          {{"program", "O777"}, {"revision", rev}, {"mode", "drip"}}, token);
  EXPECT_EQ(job.status, 201) << job.body;
  return job.json().value("job", std::int64_t{0});
}

nlohmann::json tool_of(const nlohmann::json& answer, int number) {
  for (const auto& t : answer["tools"])
    if (t["tool"] == number) return t;
  return nullptr;
}

TEST(ApiToolReset, TheCountStartsAgainAtTheResetAndARangeCountsEverything) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string rev = released(c, "O777", kTwoTools);
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  ASSERT_EQ(wait_for_end(c, oper, drip(c, oper, rev))["state"], "done");
  const auto reset =
      c.post("/api/machines/mill-1/tools/T1/reset", {{"reason", "new insert"}}, oper);
  ASSERT_EQ(reset.status, 200) << reset.body;
  EXPECT_EQ(reset.json()["tool"], 1);
  EXPECT_EQ(reset.json()["reset_by"], "oper");
  ASSERT_EQ(wait_for_end(c, oper, drip(c, oper, rev))["state"], "done");

  const auto t = c.get("/api/machines/mill-1/tools", oper).json();
  EXPECT_EQ(t["parts"], 2);
  EXPECT_EQ(tool_of(t, 1)["parts"], 1);
  EXPECT_EQ(tool_of(t, 1)["counted_from"], "reset");
  EXPECT_EQ(tool_of(t, 1)["since_us"], reset.json()["reset_at_us"]);
  EXPECT_EQ(tool_of(t, 1)["reset_reason"], "new insert");
  EXPECT_EQ(tool_of(t, 2)["parts"], 2);
  EXPECT_TRUE(tool_of(t, 2)["reset_at_us"].is_null());
  EXPECT_EQ(tool_of(t, 2)["counted_from"], "range");

  const auto ranged = c.get("/api/machines/mill-1/tools?from=1970-01-01", oper).json();
  EXPECT_EQ(tool_of(ranged, 1)["parts"], 2);
  EXPECT_EQ(tool_of(ranged, 1)["counted_from"], "range");

  // Without a body the reason is empty; the audit log has both.
  EXPECT_EQ(
      c.call(usina::test::bhttp::verb::post, "/api/machines/mill-1/tools/2/reset", "", oper).status,
      200);
  const std::string boss = c.log_in("boss", usina::test::kPassword);
  const auto audit = c.get("/api/audit?limit=1000", boss).json();
  int resets = 0;
  for (const auto& e : audit["entries"])
    resets += e["action"] == "tool.reset" ? 1 : 0;
  EXPECT_EQ(resets, 2);
}

TEST(ApiToolReset, AResetIsAnEventOnTheWebSocket) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  namespace websocket = boost::beast::websocket;
  boost::asio::io_context io;
  websocket::stream<boost::beast::tcp_stream> ws(io);
  ws.next_layer().connect(
      boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), c.port()));
  ws.set_option(websocket::stream_base::decorator([&](websocket::request_type& req) {
    req.set(boost::beast::http::field::authorization, "Bearer " + oper);
  }));
  ws.handshake("127.0.0.1", "/api/events");
  ASSERT_EQ(c.post("/api/machines/mill-1/tools/T4/reset", {{"reason", "cutter"}}, oper).status,
            200);
  nlohmann::json event = nlohmann::json::object();
  for (int i = 0; i < 100 && event.value("type", "") != "machine.tool_reset"; ++i) {
    boost::beast::flat_buffer b;
    ws.read(b);
    event = nlohmann::json::parse(boost::beast::buffers_to_string(b.data()));
  }
  EXPECT_EQ(event["type"], "machine.tool_reset");
  EXPECT_EQ(event["machine"], "mill-1");
  EXPECT_EQ(event["tool"], 4);
  EXPECT_EQ(event["reset_by"], "oper");
  EXPECT_EQ(event["reset_reason"], "cutter");
}

TEST(ApiToolReset, BadToolsAndBodiesAre400AnUnknownMachine404AndTheRouteIsWalked) {
  RunningServer s;
  Control control = start_with_control(s);
  const ApiClient c = s.client();
  const std::string oper = c.log_in("oper", usina::test::kPassword);
  const std::string base = "/api/machines/mill-1/tools/";
  for (const char* bad : {"X1", "T", "-1", "100000000", "1.5", "T5a"})
    EXPECT_EQ(c.post(base + bad + "/reset", nlohmann::json::object(), oper).status, 400) << bad;
  EXPECT_EQ(c.call(usina::test::bhttp::verb::post, base + "1/reset", "{", oper).status, 400);
  EXPECT_EQ(c.post(base + "1/reset", {{"reason", 5}}, oper).status, 400);
  EXPECT_EQ(c.post(base + "1/reset", {{"reason", std::string(3000, 'x')}}, oper).status, 413);
  EXPECT_EQ(c.post("/api/machines/lathe-9/tools/1/reset", nlohmann::json::object(), oper).status,
            404);
  const std::string appr = c.log_in("appr", usina::test::kPassword);
  EXPECT_EQ(c.post(base + "1/reset", nlohmann::json::object(), appr).status, 403);
  const auto routes = api_routes();
  EXPECT_TRUE(std::any_of(routes.begin(), routes.end(), [](const ApiRoute& r) {
    return r.pattern == "/api/machines/{}/tools/{}/reset" && r.method == http::verb::post &&
           r.permission == Permission::ResetToolLife;
  }));
}

}  // namespace
}  // namespace usina::dnc
