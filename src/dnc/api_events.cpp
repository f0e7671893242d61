#include "dnc/api_events.hpp"

#include <algorithm>

namespace usina::dnc {

namespace beast = boost::beast;
namespace websocket = beast::websocket;

EventSession::EventSession(boost::asio::ip::tcp::socket socket) : ws_(std::move(socket)) {}

void EventSession::accept(HttpRequest upgrade) {
  ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
  ws_.set_option(websocket::stream_base::decorator(
      [](websocket::response_type& res) { res.set(http::field::server, "usina"); }));
  ws_.read_message_max(64 * 1024);
  ws_.async_accept(upgrade, [self = shared_from_this()](const beast::error_code& ec) {
    if (ec) return;
    self->open_ = true;
    self->ws_.text(true);
    self->read_loop();
    self->write_next();
  });
}

// The client sends nothing we use; reading notices its close (and answers pings).
void EventSession::read_loop() {
  ws_.async_read(in_, [self = shared_from_this()](const beast::error_code& ec, std::size_t) {
    if (ec) {
      self->open_ = false;
      return;
    }
    self->in_.consume(self->in_.size());
    self->read_loop();
  });
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
  ws_.async_write(boost::asio::buffer(*queue_.front()),
                  [self = shared_from_this()](const beast::error_code& ec, std::size_t) {
                    self->writing_ = false;
                    if (ec) {
                      self->open_ = false;
                      return;
                    }
                    self->queue_.pop_front();
                    self->write_next();
                  });
}

void EventSession::close() {
  if (!open_) return;
  open_ = false;
  queue_.clear();
  ws_.async_close(websocket::close_code::going_away,
                  [self = shared_from_this()](const beast::error_code&) {});
}

void EventHub::add(std::shared_ptr<EventSession> s) {
  std::erase_if(sessions_, [](const std::weak_ptr<EventSession>& w) { return w.expired(); });
  sessions_.push_back(std::move(s));
}

void EventHub::publish(std::string_view type, nlohmann::json event) {
  event["type"] = std::string(type);
  event["seq"] = ++seq_;
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
