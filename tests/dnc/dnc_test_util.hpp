// Shared bits of the dnc tests: a program of a given size made on the fly
// (constant memory), and running the event loop until a job ends.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include <boost/asio/io_context.hpp>
#include <fmt/format.h>

#include "dnc/program_source.hpp"

namespace usina::dnc::test {

// Lines "N<n> G1 X<n>.5 Y-<n>.25 F1200" until `bytes` bytes, made as read.
class GeneratedProgram final : public ProgramSource {
 public:
  explicit GeneratedProgram(std::uint64_t bytes) : total_(bytes) {}

  std::size_t read(std::span<char> out) override {
    std::size_t n = 0;
    while (n < out.size() && made_ < total_) {
      if (at_ == line_.size()) {
        ++number_;
        line_ = fmt::format("N{} G1 X{}.5 Y-{}.25 F1200\n", number_, number_ % 1000, number_ % 777);
        at_ = 0;
      }
      out[n++] = line_[at_++];
      ++made_;
    }
    return n;
  }

  std::optional<std::uint64_t> size() const override { return total_; }

 private:
  std::uint64_t total_;
  std::uint64_t made_ = 0;
  std::uint64_t number_ = 0;
  std::string line_;
  std::size_t at_ = 0;
};

// Runs the loop until `done()` or a guard of `limit` (the guard keeps a
// broken test from hanging the suite; no test asserts a time).
template <typename Pred>
void run_until(boost::asio::io_context& io, Pred done,
               std::chrono::seconds limit = std::chrono::seconds(120)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  io.restart();
  while (!done() && std::chrono::steady_clock::now() < end) {
    io.run_one_for(std::chrono::milliseconds(50));
  }
}

}  // namespace usina::dnc::test
