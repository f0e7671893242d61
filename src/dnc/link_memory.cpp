#include "dnc/link_memory.hpp"

#include <algorithm>
#include <vector>

#include <boost/asio/error.hpp>
#include <boost/asio/post.hpp>

namespace usina::dnc {
namespace {

// One direction of the pipe: a ring of `capacity` bytes, at most one reader
// and one writer waiting.
struct Channel {
  explicit Channel(std::size_t capacity) : ring(capacity) {}

  std::vector<std::uint8_t> ring;
  std::size_t head = 0;  // next byte to read
  std::size_t size = 0;
  std::span<std::uint8_t> read_buffer;
  IoHandler reader;
  std::span<const std::uint8_t> write_rest;
  std::size_t write_done = 0;
  IoHandler writer;

  std::size_t push(std::span<const std::uint8_t> bytes) {
    const std::size_t n = std::min(bytes.size(), ring.size() - size);
    for (std::size_t i = 0; i < n; ++i)
      ring[(head + size + i) % ring.size()] = bytes[i];
    size += n;
    return n;
  }

  std::size_t pop(std::span<std::uint8_t> out) {
    const std::size_t n = std::min(out.size(), size);
    for (std::size_t i = 0; i < n; ++i)
      out[i] = ring[(head + i) % ring.size()];
    head = (head + n) % ring.size();
    size -= n;
    return n;
  }
};

struct Pipe {
  Pipe(asio::io_context& context, std::size_t capacity)
      : io(context), channels{Channel(capacity), Channel(capacity)} {}

  asio::io_context& io;
  Channel channels[2];  // [0]: a → b, [1]: b → a
  bool closed = false;
};

void complete(asio::io_context& io, IoHandler& h, ErrorCode ec, std::size_t n) {
  if (!h) return;
  asio::post(io, [h = std::move(h), ec, n] { h(ec, n); });
  h = nullptr;
}

// Moves what can move: waiting writer into the ring, the ring to a waiting reader.
void pump(Pipe& p, Channel& c) {
  if (p.closed) {
    complete(p.io, c.reader, asio::error::eof, 0);
    complete(p.io, c.writer, asio::error::broken_pipe, c.write_done);
    return;
  }
  if (c.writer) {
    const std::size_t n = c.push(c.write_rest);
    c.write_rest = c.write_rest.subspan(n);
    c.write_done += n;
    if (c.write_rest.empty()) complete(p.io, c.writer, {}, c.write_done);
  }
  if (c.reader && c.size > 0) {
    const std::size_t n = c.pop(c.read_buffer);
    complete(p.io, c.reader, {}, n);
    if (c.writer) pump(p, c);  // room for a waiting writer
  }
}

class MemoryLink final : public Link {
 public:
  MemoryLink(std::shared_ptr<Pipe> pipe, int side) : pipe_(std::move(pipe)), side_(side) {}

  ~MemoryLink() override { MemoryLink::close(); }

  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    Channel& c = pipe_->channels[1 - side_];
    c.read_buffer = buffer;
    c.reader = std::move(handler);
    pump(*pipe_, c);
  }

  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    Channel& c = pipe_->channels[side_];
    c.write_rest = bytes;
    c.write_done = 0;
    c.writer = std::move(handler);
    pump(*pipe_, c);
  }

  void cancel() override {
    complete(pipe_->io, pipe_->channels[1 - side_].reader, asio::error::operation_aborted, 0);
    Channel& out = pipe_->channels[side_];
    complete(pipe_->io, out.writer, asio::error::operation_aborted, out.write_done);
    out.write_rest = {};
  }

  void close() override {
    if (pipe_->closed) return;
    pipe_->closed = true;
    pump(*pipe_, pipe_->channels[0]);
    pump(*pipe_, pipe_->channels[1]);
  }

  std::optional<std::size_t> output_queue() const override {
    const Channel& c = pipe_->channels[side_];
    return c.size + c.write_rest.size();
  }

  std::string describe() const override { return side_ == 0 ? "memory:a" : "memory:b"; }

 private:
  std::shared_ptr<Pipe> pipe_;
  int side_;
};

}  // namespace

LinkPair memory_link_pair(asio::io_context& io, std::size_t capacity) {
  auto pipe = std::make_shared<Pipe>(io, std::max<std::size_t>(capacity, 1));
  return LinkPair{std::make_unique<MemoryLink>(pipe, 0), std::make_unique<MemoryLink>(pipe, 1)};
}

}  // namespace usina::dnc
