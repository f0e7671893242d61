// `GET /api/events`: a WebSocket on which the server puts one JSON text
// message per change (a revision uploaded or moved, a job queued, started,
// ended, a machine's state, a punch received; a running job's progress at
// most once a second). A client that falls more than `kMaxQueued` messages
// behind is closed rather than let the server's memory grow.
#pragma once

#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dnc/api_http.hpp"

namespace usina::dnc {

struct HttpStream;  // http_stream.hpp

class EventSession : public std::enable_shared_from_this<EventSession> {
 public:
  static constexpr std::size_t kMaxQueued = 4096;

  // Takes the upgraded connection's stream: WS on plain TCP, WSS on TLS.
  explicit EventSession(HttpStream&& stream);
  static std::shared_ptr<EventSession> over(HttpStream& upgraded);
  ~EventSession();

  EventSession(const EventSession&) = delete;
  EventSession& operator=(const EventSession&) = delete;

  void accept(HttpRequest upgrade);
  void send(std::shared_ptr<const std::string> text);
  void close();

  bool open() const { return open_; }

 private:
  void read_loop();
  void write_next();

  struct Ws;  // the WebSocket and its read buffer (api_events.cpp)
  std::unique_ptr<Ws> ws_;
  std::deque<std::shared_ptr<const std::string>> queue_;
  bool open_ = false;
  bool writing_ = false;
};

// What else hears the events on the loop (the MTConnect adapter, MQTT):
// the event's type and its JSON, "type" and "seq" included.
using EventListener = std::function<void(std::string_view type, const nlohmann::json& event)>;

class EventHub {
 public:
  void add(std::shared_ptr<EventSession> s);

  void listen(EventListener l) { listeners_.push_back(std::move(l)); }

  // `event` gets a "type", a "seq" (one more per event) and "server_us", the
  // server's clock when it was sent (microseconds since 1970, UTC): a page
  // times a running job by the server's clock, not its own.
  void publish(std::string_view type, nlohmann::json event);
  void close_all();

  std::uint64_t published() const { return seq_; }

 private:
  std::vector<std::weak_ptr<EventSession>> sessions_;
  std::vector<EventListener> listeners_;
  std::uint64_t seq_ = 0;
};

}  // namespace usina::dnc
