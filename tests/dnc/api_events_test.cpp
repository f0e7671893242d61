// `GET /api/events`: a WebSocket that carries one JSON event per change,
// open only with a valid token.
#include <chrono>

#include <gtest/gtest.h>

#include "server_fixture.hpp"

namespace usina::dnc {
namespace {

namespace websocket = boost::beast::websocket;

TEST(ApiEvents, AnUploadAndAStateChangeAreEventsOnTheWebSocket) {
  test::RunningServer s;
  s.start();
  const test::ApiClient c = s.client();
  const std::string boss = c.log_in("boss", test::kPassword);
  boost::asio::io_context io;
  websocket::stream<boost::beast::tcp_stream> ws(io);
  ws.next_layer().connect(
      boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), c.port()));
  ws.set_option(websocket::stream_base::decorator([&](websocket::request_type& req) {
    req.set(boost::beast::http::field::authorization, "Bearer " + boss);
  }));
  ws.handshake("127.0.0.1", "/api/events");
  const auto clock_us = [] {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
  };
  const std::int64_t before_us = clock_us();
  const std::string text = "G0 X1\nM2\n";
  const auto up = c.post("/api/programs", {{"name", "O800"}, {"text", text}}, boss).json();
  c.post("/api/programs/O800/revisions/" + up["revision"].get<std::string>() + "/state",
         {{"state", "checked"}}, boss);
  std::vector<nlohmann::json> events;
  while (events.size() < 2) {
    boost::beast::flat_buffer b;
    ws.read(b);
    events.push_back(nlohmann::json::parse(boost::beast::buffers_to_string(b.data())));
  }
  EXPECT_EQ(events[0]["type"], "revision.created");
  EXPECT_EQ(events[0]["name"], "O800");
  EXPECT_EQ(events[1]["type"], "revision.state");
  EXPECT_EQ(events[1]["state"], "checked");
  EXPECT_EQ(events[1]["seq"].get<int>(), events[0]["seq"].get<int>() + 1);
  // Each event says when the server sent it, by its clock (here the test's).
  const std::int64_t after_us = clock_us();
  for (const nlohmann::json& e : events) {
    EXPECT_GE(e["server_us"].get<std::int64_t>(), before_us) << e;
    EXPECT_LE(e["server_us"].get<std::int64_t>(), after_us) << e;
  }
  EXPECT_LE(events[0]["server_us"].get<std::int64_t>(), events[1]["server_us"].get<std::int64_t>());
}

TEST(ApiEvents, TheWebSocketIsRefusedWithoutAValidToken) {
  test::RunningServer s;
  s.start();
  boost::asio::io_context io;
  websocket::stream<boost::beast::tcp_stream> ws(io);
  ws.next_layer().connect(boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"),
                                                         s.client().port()));
  websocket::response_type res;
  boost::beast::error_code ec;
  ws.handshake(res, "127.0.0.1", "/api/events?token=" + std::string(64, 'b'), ec);
  // Beast's client does not keep the refusal's status (curl shows the 401).
  EXPECT_EQ(ec, websocket::error::upgrade_declined) << ec.message();
}

}  // namespace
}  // namespace usina::dnc
