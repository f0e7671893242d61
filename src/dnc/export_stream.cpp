#include "dnc/export_stream.hpp"

#include <utility>

#include <fmt/format.h>

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

// Loads the next member: a revision, or after the last one the manifest.
bool ReleasedTar::open_next_file() {
  at_ = 0;
  if (file_ == files_.size()) {
    ++file_;
    head_ = tar_header("released.sha256", manifest_.size(), mtime_s_);
    body_ = manifest_;
    tail_ = tar_padding(manifest_.size()) + kTarEndBytes;
    return true;
  }
  const ExportedFile& f = files_[file_++];
  auto text = revision_bytes(store_, f.program, f.hash);  // verified against its hash
  if (!text) {
    error_ = text.error().message;
    return false;
  }
  if (text->size() != static_cast<std::uint64_t>(f.size)) {
    // The length announced would be wrong: stop rather than send a bad archive.
    error_ = fmt::format("{} has {} bytes, recorded {}", f.file, text->size(), f.size);
    return false;
  }
  head_ = tar_header(f.file, text->size(), mtime_s_);
  body_ = std::move(*text);
  tail_ = tar_padding(body_.size());
  return true;
}

std::optional<std::string> ReleasedTar::next() {
  if (!error_.empty()) return std::nullopt;
  if (head_.empty() && at_ == body_.size() && tail_ == 0) {
    std::string().swap(body_);  // the member's memory back before the next is read
    at_ = 0;
    if (file_ > files_.size()) return std::string();  // the end is out
    if (!open_next_file()) return std::nullopt;
  }
  if (!head_.empty()) return std::exchange(head_, std::string());
  if (at_ < body_.size()) {
    const std::size_t n = std::min(kExportPieceBytes, body_.size() - at_);
    std::string piece = body_.substr(at_, n);
    at_ += n;
    return piece;
  }
  return std::string(std::exchange(tail_, 0), '\0');
}

}  // namespace usina::dnc
