#include "dnc/api_events.hpp"

#include <algorithm>
#include <chrono>
#include <variant>

#include <boost/beast/websocket.hpp>
#include <boost/beast/websocket/ssl.hpp>

#include "dnc/http_stream.hpp"

namespace usina::dnc {

namespace beast = boost::beast;
namespace websocket = beast::websocket;

struct EventSession::Ws {
  using PlainWs = websocket::stream<PlainStream>;
  using TlsWs = websocket::stream<TlsStream>;

  explicit Ws(HttpStream&& s)
      : v(s.tls() ? over<TlsWs>(std::move(s)) : over<PlainWs>(std::move(s))) {}

  template <typename W>
  static std::variant<PlainWs, TlsWs> over(HttpStream&& s) {
    using Next = typename W::next_layer_type;
    return std::variant<PlainWs, TlsWs>(std::in_place_type<W>, std::move(std::get<Next>(s.v)));
  }

  std::variant<PlainWs, TlsWs> v;
  beast::flat_buffer in;
};

EventSession::EventSession(HttpStream&& stream) : ws_(std::make_unique<Ws>(std::move(stream))) {}

EventSession::~EventSession() = default;

std::shared_ptr<EventSession> EventSession::over(HttpStream& upgraded) {
  return std::make_shared<EventSession>(std::move(upgraded));
}

void EventSession::accept(HttpRequest upgrade) {
  std::visit(
      [&](auto& ws) {
        ws.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
        ws.set_option(websocket::stream_base::decorator(
            [](websocket::response_type& res) { res.set(http::field::server, "usina"); }));
        ws.read_message_max(64 * 1024);
        ws.async_accept(upgrade, [self = shared_from_this(), &ws](const beast::error_code& ec) {
          if (ec) return;
          self->open_ = true;
          ws.text(true);
          self->read_loop();
          self->write_next();
        });
      },
      ws_->v);
}

// The client sends nothing we use; reading notices its close (and answers pings).
void EventSession::read_loop() {
  std::visit(
      [this](auto& ws) {
        ws.async_read(ws_->in,
                      [self = shared_from_this()](const beast::error_code& ec, std::size_t) {
                        if (ec) {
                          self->open_ = false;
                          return;
                        }
                        self->ws_->in.consume(self->ws_->in.size());
                        self->read_loop();
                      });
      },
      ws_->v);
}

void EventSession::send(std::shared_ptr<const std::string> text) {
  if (queue_.size() >= kMaxQueued) {
    close();
    return;
  }
  queue_.push_back(std::move(text));
  write_next();
}

void EventSession::write_next() {
  if (!open_ || writing_ || queue_.empty()) return;
  writing_ = true;
  std::visit(
      [this](auto& ws) {
        ws.async_write(boost::asio::buffer(*queue_.front()),
                       [self = shared_from_this()](const beast::error_code& ec, std::size_t) {
                         self->writing_ = false;
                         if (ec) {
                           self->open_ = false;
                           return;
                         }
                         self->queue_.pop_front();
                         self->write_next();
                       });
      },
      ws_->v);
}

void EventSession::close() {
  if (!open_) return;
  open_ = false;
  queue_.clear();
  std::visit(
      [this](auto& ws) {
        ws.async_close(websocket::close_code::going_away,
                       [self = shared_from_this()](const beast::error_code&) {});
      },
      ws_->v);
}

void EventHub::add(std::shared_ptr<EventSession> s) {
  std::erase_if(sessions_, [](const std::weak_ptr<EventSession>& w) { return w.expired(); });
  sessions_.push_back(std::move(s));
}

void EventHub::publish(std::string_view type, nlohmann::json event) {
  event["type"] = std::string(type);
  event["seq"] = ++seq_;
  event["server_us"] = std::chrono::duration_cast<std::chrono::microseconds>(
                           std::chrono::system_clock::now().time_since_epoch())
                           .count();
  const auto text = std::make_shared<const std::string>(
      event.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  std::erase_if(sessions_, [](const std::weak_ptr<EventSession>& w) { return w.expired(); });
  for (const auto& w : sessions_) {
    if (auto s = w.lock()) s->send(text);
  }
  for (const EventListener& l : listeners_)
    l(type, event);
}

void EventHub::close_all() {
  for (const auto& w : sessions_) {
    if (auto s = w.lock()) s->close();
  }
  sessions_.clear();
}

}  // namespace usina::dnc
