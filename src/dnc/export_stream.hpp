// The released set as a ustar archive made piece by piece (GET /api/export):
// its length is known before any blob is read (each member's size is the
// revision's recorded size, the manifest's lines are hashes and names), so
// the answer carries a Content-Length; then each revision is read from the
// store a piece of at most kExportPieceBytes at a time, hashed as it goes
// (store_blobs.hpp's BlobPieces): a revision whose bytes do not hash to its
// address stops the archive before its last piece. Memory: one piece,
// whatever the size of the revisions and of the set.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dnc/store.hpp"
#include "dnc/store_blobs.hpp"
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
  std::optional<std::string> next_body_piece();

  Store& store_;
  std::vector<ExportedFile> files_;
  std::int64_t mtime_s_;
  std::uint64_t size_ = 0;
  std::string manifest_;
  std::size_t file_ = 0;  // the next member to open (files_.size(): the manifest)
  // The member being written: its header, its bytes (a revision's from the
  // store, or the manifest), then its padding (and, after the manifest, the
  // archive's end).
  bool in_member_ = false;
  std::string head_;
  std::optional<BlobPieces> blob_;
  bool manifest_out_ = false;
  std::size_t tail_ = 0;
  std::string error_;
};

}  // namespace usina::dnc
