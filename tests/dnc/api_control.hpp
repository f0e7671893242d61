// A simulated control on a pty for the API tests, and a program taken to
// released over HTTP.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "dnc/link_serial.hpp"
#include "dnc/sim_cnc.hpp"
#include "dnc/store_jobs.hpp"
#include "server_fixture.hpp"

namespace usina::dnc {

using test::ApiClient;
using test::RunningServer;

// The control on the master side of a pty; the machine's port is the slave.
struct Control {
  std::unique_ptr<Link> link;
  std::shared_ptr<SimCnc> sim;
};

inline ServerMachine pty_machine(const std::string& name, const std::string& port,
                                 std::uint32_t baud) {
  ServerMachine m;
  m.link.name = name;
  m.link.port = port;
  m.link.baud = baud;
  m.link.code = TapeCode::Ascii;
  m.link.data_bits = 8;
  m.link.parity = Parity::None;
  m.link.leader = 0;
  m.link.trailer = 0;
  return m;
}

// A server with one machine `mill-1` on a pty, its control simulated (and
// `lives`, its tools' lives).
inline Control start_with_control(RunningServer& s, std::uint32_t baud = 115200,
                                  ToolLives lives = {}) {
  auto pair = open_pty_pair(s.io());
  EXPECT_TRUE(pair) << pair.error();
  Control c;
  c.link = std::move(pair->master);
  SimCncConfig sc;
  sc.keep_data = true;
  c.sim = std::make_shared<SimCnc>(s.io(), *c.link, sc);
  c.sim->start();
  ServerConfig config;
  config.machines.push_back(pty_machine("mill-1", pair->slave_path, baud));
  config.machines.back().tool_life = std::move(lives);
  s.start(config);
  return c;
}

// A server with `mill-1` on a pty whose punches end after 0.2 s of silence
// (the machine data tests): `with`'s settings on the pty's link.
inline Control start_punching_mill(RunningServer& s, ServerMachine with = {},
                                   ServerConfig config = {}) {
  auto pair = open_pty_pair(s.io());
  EXPECT_TRUE(pair) << pair.error();
  Control c;
  c.link = std::move(pair->master);
  c.sim = std::make_shared<SimCnc>(s.io(), *c.link, SimCncConfig{});
  c.sim->start();
  with.link = pty_machine("mill-1", pair->slave_path, 115200).link;
  with.link.receive_idle = 0.2;
  config.machines.push_back(with);
  s.start(config);
  return c;
}

// `mill-1` once `ready` holds (polled as a client would), or after 30 s.
template <typename F>
nlohmann::json machine_when(const ApiClient& c, const std::string& token, F ready) {
  nlohmann::json m;
  for (int i = 0; i < 600; ++i) {
    m = c.get("/api/machines/mill-1", token).json();
    if (ready(m)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return m;
}

// The control punches `rows` (on the server's loop, which owns the link).
inline void punch(RunningServer& s, Control& control, const std::string& rows) {
  s.on_loop([&] {
    auto keep = std::make_shared<std::string>(rows);
    control.link->async_write(
        std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(keep->data()),
                                      keep->size()),
        [keep](const ErrorCode&, std::size_t) {});
    return 0;
  });
}

// What the control has received, once it holds `part` (or after 30 s).
inline std::string received_once(RunningServer& s, Control& control, const std::string& part) {
  std::string got;
  for (int i = 0; i < 600; ++i) {
    got = s.on_loop(
        [&] { return std::string(control.sim->data().begin(), control.sim->data().end()); });
    if (got.find(part) != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return got;
}

inline std::string released(const ApiClient& c, const std::string& name, const std::string& text) {
  const std::string boss = c.log_in("boss", test::kPassword);
  const std::string rev =
      c.post("/api/programs", {{"name", name}, {"dialect", "rs274ngc"}, {"text", text}}, boss)
          .json()["revision"];
  for (const char* state : {"checked", "approved", "released"}) {
    c.post("/api/programs/" + name + "/revisions/" + rev + "/state", {{"state", state}}, boss);
  }
  return rev;
}

// The job once it has ended (polled as a client would).
inline nlohmann::json wait_for_end(const ApiClient& c, const std::string& token, std::int64_t job) {
  for (int i = 0; i < 2400; ++i) {
    const auto j = c.get("/api/jobs/" + std::to_string(job), token).json();
    if (job_ended(j.value("state", ""))) return j;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return {};
}

}  // namespace usina::dnc
