#include "dnc/export_stream.hpp"

#include <utility>

#include <fmt/format.h>

#include "dnc/store_blobs.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/tar_writer.hpp"

namespace usina::dnc {

ReleasedTar::ReleasedTar(Store& store, std::vector<ExportedFile> files, std::int64_t mtime_s)
    : store_(store), files_(std::move(files)), mtime_s_(mtime_s) {
  for (const ExportedFile& f : files_) {
    size_ += tar_member_bytes(static_cast<std::uint64_t>(f.size));
    manifest_ += fmt::format("{}  {}\n", f.hash, f.file);
  }
  size_ += tar_member_bytes(manifest_.size()) + kTarEndBytes;
}

// Opens the next member: a revision, or after the last one the manifest.
bool ReleasedTar::open_next_file() {
  if (file_ == files_.size()) {
    ++file_;
    head_ = tar_header("released.sha256", manifest_.size(), mtime_s_);
    manifest_out_ = false;
    tail_ = tar_padding(manifest_.size()) + kTarEndBytes;
    return true;
  }
  const ExportedFile& f = files_[file_++];
  auto v = find_revision(store_, f.program, f.hash);
  auto blob = v ? BlobPieces::open(store_, v->hash, kExportPieceBytes)
                : StoreResult<BlobPieces>(tl::unexpected(v.error()));
  if (!blob) {
    error_ = blob.error().message;
    return false;
  }
  if (blob->size() != static_cast<std::uint64_t>(f.size)) {
    // The length announced would be wrong: stop rather than send a bad archive.
    error_ = fmt::format("{} has {} bytes, recorded {}", f.file, blob->size(), f.size);
    return false;
  }
  head_ = tar_header(f.file, blob->size(), mtime_s_);
  tail_ = tar_padding(blob->size());
  blob_ = std::move(*blob);
  return true;
}

// The next piece of the member's bytes; empty when they are all out.
std::optional<std::string> ReleasedTar::next_body_piece() {
  if (file_ > files_.size()) {  // the manifest
    if (manifest_out_) return std::string();
    manifest_out_ = true;
    return manifest_;
  }
  if (!blob_) return std::string();
  auto piece = blob_->next();
  if (!piece) {
    error_ = piece.error().message;
    return std::nullopt;
  }
  if (piece->empty()) blob_.reset();
  return std::move(*piece);
}

std::optional<std::string> ReleasedTar::next() {
  while (error_.empty()) {
    if (!in_member_) {
      if (file_ > files_.size()) return std::string();  // the end is out
      if (!open_next_file()) return std::nullopt;
      in_member_ = true;
      return std::exchange(head_, std::string());
    }
    auto piece = next_body_piece();
    if (!piece) return std::nullopt;
    if (!piece->empty()) return piece;
    in_member_ = false;
    if (tail_ > 0) return std::string(std::exchange(tail_, 0), '\0');
  }
  return std::nullopt;
}

}  // namespace usina::dnc
