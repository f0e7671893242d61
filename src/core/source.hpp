// Program text: a file mapped read-only (no copy, pages released behind the
// reader so a long program streams in constant memory) or a string (stdin).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.hpp"

namespace usina::core {

class SourceFile {
 public:
  // Maps `path`; nullptr and `error` set when it cannot be read. A pipe, a
  // FIFO or a character device (`-`'s standard input, /dev/stdin, a shell's
  // <(...)) is read whole when `max_stream_bytes` > 0, up to that many bytes;
  // with 0, only regular files are read.
  static std::unique_ptr<SourceFile> open(const std::string& path, std::string& error,
                                          std::uint64_t max_stream_bytes = 0);
  // The same for an open descriptor (standard input), named `name`.
  static std::unique_ptr<SourceFile> open_descriptor(int fd, std::string name, std::string& error,
                                                     std::uint64_t max_stream_bytes);
  static std::unique_ptr<SourceFile> from_string(std::string name, std::string text);

  SourceFile(const SourceFile&) = delete;
  SourceFile& operator=(const SourceFile&) = delete;
  ~SourceFile();

  std::string_view text() const { return text_; }

  const std::string& name() const { return name_; }

  // The line that starts at `offset`, without its end-of-line characters.
  std::string_view line_at(std::uint64_t offset) const;
  // Tells the OS it may drop the mapped pages before `offset`; the text stays
  // readable (pages come back from the file when touched again).
  void release_before(std::uint64_t offset);

 private:
  SourceFile() = default;
  static std::unique_ptr<SourceFile> read_stream(int fd, std::string name, std::string& error,
                                                 std::uint64_t max_bytes);
  std::string name_;
  std::string owned_;
  void* map_ = nullptr;
  std::size_t map_len_ = 0;
  std::uint64_t released_ = 0;
  std::string_view text_;
};

// Owns every source of a run; a SourceLoc's `file` is an index here.
class SourceManager {
 public:
  std::uint32_t add(std::unique_ptr<SourceFile> file);
  const SourceFile* get(std::uint32_t id) const;
  SourceFile* get(std::uint32_t id);

  std::size_t size() const { return files_.size(); }

 private:
  std::vector<std::unique_ptr<SourceFile>> files_;
};

// "file:line:col: error: message [E_CODE]", the line and a caret under it.
std::string render(const Diagnostic& d, const SourceManager& sources);

}  // namespace usina::core
