// Where a transfer reads the program it sends, a slice at a time, so a
// program of any size (a 100 MB drip feed) goes out in constant memory.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include <tl/expected.hpp>

namespace usina::dnc {

class ProgramSource {
 public:
  virtual ~ProgramSource() = default;
  // Up to out.size() bytes; 0 at the end (or after an error).
  virtual std::size_t read(std::span<char> out) = 0;

  // Why reading stopped early (an I/O error), empty otherwise.
  virtual std::string error() const { return {}; }

  // The program's size, when known (progress: bytes of bytes).
  virtual std::optional<std::uint64_t> size() const { return std::nullopt; }
};

// A program held in memory.
std::unique_ptr<ProgramSource> string_source(std::string text);

// A program read from a file (a revision's blob).
tl::expected<std::unique_ptr<ProgramSource>, std::string> file_source(const std::string& path);

}  // namespace usina::dnc
