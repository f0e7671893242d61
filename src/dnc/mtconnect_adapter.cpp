#include "dnc/mtconnect_adapter.hpp"

#include <boost/asio/read_until.hpp>
#include <boost/asio/write.hpp>
#include <fmt/format.h>

#include "dnc/server.hpp"

namespace usina::dnc {

namespace ip = boost::asio::ip;

std::string shdr_lines(const std::string& ts, const std::vector<ShdrItem>& items) {
  std::string plain;
  std::string messages;
  for (const ShdrItem& i : items) {
    std::string& into = i.key.ends_with(":message") ? messages : plain;
    if (&into == &messages) into += ts;
    into += '|' + i.key + '|' + i.value;
    if (&into == &messages) into += '\n';
  }
  return (plain.empty() ? std::string() : ts + plain + '\n') + messages;
}

ShdrClient::ShdrClient(ip::tcp::socket socket, std::uint32_t heartbeat_ms)
    : socket_(std::move(socket)), in_(4096), heartbeat_ms_(heartbeat_ms) {}

void ShdrClient::start(std::string first) {
  boost::system::error_code ignored;
  socket_.set_option(ip::tcp::no_delay(true), ignored);
  send(std::move(first));
  read_loop();
}

// The agent sends `* PING` (a heartbeat request); nothing else is read.
void ShdrClient::read_loop() {
  boost::asio::async_read_until(
      socket_, in_, '\n',
      [self = shared_from_this()](const boost::system::error_code& ec, std::size_t n) {
        if (ec) {  // closed, or a line longer than the buffer
          self->close();
          return;
        }
        std::string line(
            boost::asio::buffers_begin(self->in_.data()),
            boost::asio::buffers_begin(self->in_.data()) + static_cast<std::ptrdiff_t>(n));
        self->in_.consume(n);
        while (!line.empty() && (line.back() == '\n' || line.back() == '\r'))
          line.pop_back();
        if (line.starts_with("* PING")) self->send(fmt::format("* PONG {}\n", self->heartbeat_ms_));
        self->read_loop();
      });
}

void ShdrClient::send(std::string line) {
  if (!open_ || line.empty()) return;
  if (queue_.size() >= kMaxQueued) {
    close();
    return;
  }
  queue_.push_back(std::move(line));
  write_next();
}

void ShdrClient::write_next() {
  if (!open_ || writing_ || queue_.empty()) return;
  writing_ = true;
  boost::asio::async_write(
      socket_, boost::asio::buffer(queue_.front()),
      [self = shared_from_this()](const boost::system::error_code& ec, std::size_t) {
        self->writing_ = false;
        if (ec) {
          self->close();
          return;
        }
        self->queue_.pop_front();
        self->write_next();
      });
}

void ShdrClient::close() {
  if (!open_) return;
  open_ = false;
  queue_.clear();
  boost::system::error_code ignored;
  socket_.shutdown(ip::tcp::socket::shutdown_both, ignored);
  socket_.close(ignored);
}

ShdrAdapter::ShdrAdapter(boost::asio::io_context& io, MtconnectConfig config)
    : io_(io), config_(std::move(config)), acceptor_(io) {}

std::string ShdrAdapter::start() {
  const auto at = parse_listen(config_.listen);
  if (!at) return fmt::format("cannot read mtconnect.listen `{}`; give host:port", config_.listen);
  boost::system::error_code ec;
  acceptor_.open(at->protocol(), ec);
  if (!ec) acceptor_.set_option(ip::tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor_.bind(*at, ec);
  if (!ec) acceptor_.listen(ip::tcp::socket::max_listen_connections, ec);
  if (ec) return fmt::format("cannot listen on {} (mtconnect): {}", config_.listen, ec.message());
  accept();
  return {};
}

void ShdrAdapter::accept() {
  acceptor_.async_accept([this](const boost::system::error_code& ec, ip::tcp::socket socket) {
    if (ec) return;  // stopped
    auto client = std::make_shared<ShdrClient>(std::move(socket), config_.heartbeat_ms);
    std::erase_if(clients_, [](const std::weak_ptr<ShdrClient>& w) {
      auto c = w.lock();
      return !c || !c->open();
    });
    clients_.push_back(client);
    client->start(shdr_lines(shdr_timestamp(), items_.all()));
    accept();
  });
}

void ShdrAdapter::on_event(std::string_view type, const nlohmann::json& event) {
  broadcast(items_.apply(type, event));
}

void ShdrAdapter::broadcast(const std::vector<ShdrItem>& items) {
  if (items.empty()) return;
  const std::string lines = shdr_lines(shdr_timestamp(), items);
  for (const auto& w : clients_) {
    if (auto c = w.lock()) c->send(lines);
  }
}

void ShdrAdapter::stop() {
  boost::system::error_code ignored;
  acceptor_.close(ignored);
  for (const auto& w : clients_) {
    if (auto c = w.lock()) c->close();
  }
  clients_.clear();
}

}  // namespace usina::dnc
