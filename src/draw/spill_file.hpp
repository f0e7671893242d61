// What the entity lists of one drawing share (entity_list.hpp): one unnamed
// temporary file their older entities go to, whatever the number of layers
// (a descriptor a layer would run out with a thousand tools), and the bytes
// all of them hold in memory, against one limit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace usina::draw {

class SpillFile {
 public:
  // In `folder`; empty: $TMPDIR or /tmp (core/temporary_file.hpp). The file
  // is made when the first bytes come.
  explicit SpillFile(std::string folder = {});
  SpillFile(const SpillFile&) = delete;
  SpillFile& operator=(const SpillFile&) = delete;
  ~SpillFile();

  // Where `bytes` went in the file; nullopt when the file could not be made
  // or written, and from then on (what was not written stays in memory).
  std::optional<std::uint64_t> append(const std::vector<char>& bytes);

  // Reads `n` bytes at `offset`: 0, or the errno of why not (EIO when the
  // file ends before: it was cut short from outside).
  int read(char* out, std::size_t n, std::uint64_t offset) const;

  const std::string& folder() const { return folder_; }

  // Where the file goes (empty: $TMPDIR or /tmp), until it is made.
  void set_folder(std::string folder);

  // Whether a write failed: nothing more goes to the file.
  bool failed() const { return failed_; }

  // The bytes the lists hold in memory, all together, and the most they
  // may: past it, the list that grows sends its older entities to the file.
  static constexpr std::size_t kHoldLimit = std::size_t{1} << 20;
  std::size_t held = 0;
  std::size_t hold_limit = kHoldLimit;

 private:
  std::string folder_;
  int fd_ = -1;
  bool failed_ = false;
  std::uint64_t size_ = 0;
};

}  // namespace usina::draw
