// The MTConnect SHDR adapter of `usina serve`: a TCP server a stock
// cppagent connects to (its `Adapters { mill { Port = 7878 } }`). On
// connect it sends every machine's items (mtconnect_items.hpp); then one
// line per change, `timestamp|MACHINE:key|value`; it answers the agent's
// `* PING` with `* PONG <heartbeat ms>`. It runs on the server's loop and
// hears the server's events (api_events.hpp); a client that falls
// `kMaxQueued` lines behind is closed.
#pragma once

#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/streambuf.hpp>

#include "dnc/api_events.hpp"
#include "dnc/data_config.hpp"
#include "dnc/mtconnect_items.hpp"

namespace usina::dnc {

class ShdrClient : public std::enable_shared_from_this<ShdrClient> {
 public:
  static constexpr std::size_t kMaxQueued = 4096;

  ShdrClient(boost::asio::ip::tcp::socket socket, std::uint32_t heartbeat_ms);
  void start(std::string first);
  void send(std::string line);
  void close();

  bool open() const { return open_; }

 private:
  void read_loop();
  void write_next();

  boost::asio::ip::tcp::socket socket_;
  boost::asio::streambuf in_;
  std::deque<std::string> queue_;
  std::uint32_t heartbeat_ms_;
  bool open_ = true;
  bool writing_ = false;
};

class ShdrAdapter {
 public:
  ShdrAdapter(boost::asio::io_context& io, MtconnectConfig config);

  void add_machine(const std::string& name, const MachineItems& start) {
    items_.add_machine(name, start);
  }

  void on_event(std::string_view type, const nlohmann::json& event);

  // Listens; an error message when it cannot.
  std::string start();
  void stop();

  boost::asio::ip::tcp::endpoint endpoint() const { return acceptor_.local_endpoint(); }

 private:
  void accept();
  void broadcast(const std::vector<ShdrItem>& items);

  boost::asio::io_context& io_;
  MtconnectConfig config_;
  boost::asio::ip::tcp::acceptor acceptor_;
  MtconnectItems items_;
  std::vector<std::weak_ptr<ShdrClient>> clients_;
};

// The SHDR lines of `items` stamped `ts`: the plain items on one line,
// each message on a line of its own (SHDR version 1 wants it so).
std::string shdr_lines(const std::string& ts, const std::vector<ShdrItem>& items);

}  // namespace usina::dnc
