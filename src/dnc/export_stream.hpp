// The released set as a ustar archive made piece by piece (GET /api/export):
// its length is known before any blob is read (each member's size is the
// revision's recorded size, the manifest's lines are hashes and names), so
// the answer carries a Content-Length; then each revision is read, verified
// against its hash, and handed out in pieces of at most kExportPieceBytes.
// Memory: the revision being written (at most the store's revision limit)
// and one piece, whatever the size of the set.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dnc/store.hpp"
#include "dnc/store_import.hpp"

namespace usina::dnc {

inline constexpr std::size_t kExportPieceBytes = 64 * 1024;

class ReleasedTar {
 public:
  ReleasedTar(Store& store, std::vector<ExportedFile> files, std::int64_t mtime_s);

  // The whole archive's bytes.
  std::uint64_t size() const { return size_; }

  // The next piece; empty after the end. Nothing when a revision cannot be
  // read, is damaged, or is not the size recorded: `error()` says why.
  std::optional<std::string> next();

  const std::string& error() const { return error_; }

 private:
  bool open_next_file();

  Store& store_;
  std::vector<ExportedFile> files_;
  std::int64_t mtime_s_;
  std::uint64_t size_ = 0;
  std::string manifest_;
  std::size_t file_ = 0;  // the next member to open (files_.size(): the manifest)
  // The member being written: its header, its bytes (how much of them is
  // out), then its padding (and, after the manifest, the archive's end).
  std::string head_;
  std::string body_;
  std::size_t at_ = 0;
  std::size_t tail_ = 0;
  std::string error_;
};

}  // namespace usina::dnc
