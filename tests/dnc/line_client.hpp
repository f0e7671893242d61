// A TCP client for the tests that reads text lines (an MTConnect agent's
// side of the SHDR adapter): each wait has a long deadline so a broken
// server fails the test instead of hanging it.
#pragma once

#include <poll.h>

#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <sys/socket.h>

namespace usina::test {

class LineClient {
 public:
  explicit LineClient(const boost::asio::ip::tcp::endpoint& at) : socket_(io_) {
    socket_.connect(at);
  }

  void send(const std::string& text) { boost::asio::write(socket_, boost::asio::buffer(text)); }

  // Reads lines until one satisfies `want` (true), or the deadline or the
  // connection's end (false); the lines read before count too. Every line
  // read is kept in `lines()`.
  bool wait_for(const std::function<bool(const std::string&)>& want,
                std::chrono::seconds deadline = std::chrono::seconds(30)) {
    seen_ = 0;
    for (; seen_ < lines_.size(); ++seen_) {
      if (want(lines_[seen_])) return ++seen_, true;
    }
    const auto end = std::chrono::steady_clock::now() + deadline;
    while (std::chrono::steady_clock::now() < end) {
      if (!read_more(end)) return false;
      for (; seen_ < lines_.size(); ++seen_) {
        if (want(lines_[seen_])) return ++seen_, true;
      }
    }
    return false;
  }

  bool wait_for_text(const std::string& part) {
    return wait_for([&](const std::string& l) { return l.find(part) != std::string::npos; });
  }

  const std::vector<std::string>& lines() const { return lines_; }

  // The line the last successful wait stopped at.
  const std::string& last_match() const { return lines_[seen_ - 1]; }

  void close() { socket_.close(); }

 private:
  bool read_more(std::chrono::steady_clock::time_point end) {
    pollfd p{socket_.native_handle(), POLLIN, 0};
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        end - std::chrono::steady_clock::now());
    if (::poll(&p, 1, static_cast<int>(std::max<long>(left.count(), 1))) <= 0) return false;
    char buf[4096];
    const ssize_t n = ::recv(socket_.native_handle(), buf, sizeof buf, 0);
    if (n <= 0) return false;
    partial_.append(buf, static_cast<std::size_t>(n));
    for (std::size_t nl; (nl = partial_.find('\n')) != std::string::npos;) {
      lines_.push_back(partial_.substr(0, nl));
      partial_.erase(0, nl + 1);
    }
    return true;
  }

  boost::asio::io_context io_;
  boost::asio::ip::tcp::socket socket_;
  std::string partial_;
  std::vector<std::string> lines_;
  std::size_t seen_ = 0;
};

}  // namespace usina::test
