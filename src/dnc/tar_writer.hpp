// A POSIX ustar archive: regular files only, names of at most 100 bytes,
// mode 0644, owner 0. What `GET /api/export` answers (streamed member by
// member with the functions below), so a shop unpacks the released set with
// `tar x` and checks it with `sha256sum -c released.sha256`.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace usina::dnc {

inline constexpr std::size_t kTarBlock = 512;

// A member's header block; empty when the name does not fit (more than 100
// bytes, or empty). The member's bytes follow, then tar_padding(size) NULs.
std::string tar_header(std::string_view name, std::uint64_t size, std::int64_t mtime_s);
std::size_t tar_padding(std::uint64_t size);
// What a member of `size` bytes takes in the archive: its header, bytes and padding.
std::uint64_t tar_member_bytes(std::uint64_t size);
// The archive's end: two zero blocks.
inline constexpr std::size_t kTarEndBytes = 2 * kTarBlock;

// An archive written into memory.
class TarWriter {
 public:
  // False when the name does not fit a ustar header (more than 100 bytes, or empty).
  bool add(std::string_view name, std::string_view bytes, std::int64_t mtime_s);
  // The archive with its end (two zero blocks); the writer is spent.
  std::string finish();

  std::size_t size() const { return out_.size(); }

 private:
  std::string out_;
};

}  // namespace usina::dnc
