#include "dnc/store_blobs.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "dnc/sha256.hpp"

namespace usina::dnc {

StoreResult<void> put_blob(Store& store, std::string_view hash, std::string_view bytes) {
  auto r = store.db().query(
      "INSERT INTO blobs (hash, size, bytes) VALUES ($1, $2, $3) ON CONFLICT (hash) DO NOTHING",
      {hash, static_cast<std::int64_t>(bytes.size()), SqlBlob{bytes}});
  if (!r) return tl::unexpected(r.error());
  return {};
}

namespace {

tl::unexpected<StoreError> damaged(std::string_view hash, std::uint64_t size,
                                   std::uint64_t recorded, std::string_view got) {
  return store_error(StoreErrorKind::Damaged,
                     fmt::format("the stored bytes of {} are damaged: {} bytes (recorded {}) "
                                 "that hash to {}; restore the store from a backup",
                                 hash, size, recorded, got));
}

}  // namespace

StoreResult<std::string> read_blob(Store& store, std::string_view hash) {
  auto rows = store.db().query("SELECT size, bytes FROM blobs WHERE hash = $1", {hash});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty())
    return store_error(StoreErrorKind::NotFound, fmt::format("no blob {} in the store", hash));
  SqlRow& row = rows->front();
  std::string bytes = row.columns.at(1).value_or(std::string());
  const auto size = static_cast<std::uint64_t>(row.integer(0));
  if (const std::string h = sha256_hex(bytes); h != hash || size != bytes.size())
    return damaged(hash, bytes.size(), size, h);
  return bytes;
}

BlobPieces::BlobPieces(BlobPieces&&) noexcept = default;
BlobPieces& BlobPieces::operator=(BlobPieces&&) noexcept = default;
BlobPieces::~BlobPieces() = default;

StoreResult<BlobPieces> BlobPieces::open(Store& store, std::string_view hash, std::size_t piece) {
  auto rows = store.db().query("SELECT size FROM blobs WHERE hash = $1", {hash});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty())
    return store_error(StoreErrorKind::NotFound, fmt::format("no blob {} in the store", hash));
  BlobPieces b;
  b.hash_ = hash;
  b.piece_ = std::max<std::size_t>(piece, 1);
  b.size_ = static_cast<std::uint64_t>(rows->front().integer(0));
  if (b.size_ <= b.piece_) {
    // One query, as every other read: no second connection for a small blob.
    auto whole = read_blob(store, hash);
    if (!whole) return tl::unexpected(whole.error());
    b.whole_ = std::move(*whole);
    return b;
  }
  auto reader = store.db().open_blob("blobs", "bytes", "hash", hash);
  if (!reader) return tl::unexpected(reader.error());
  if ((*reader)->size() != b.size_)
    return damaged(hash, (*reader)->size(), b.size_, "(not read: the length is wrong)");
  b.reader_ = std::move(*reader);
  b.sha_ = std::make_unique<Sha256>();
  return b;
}

StoreResult<void> BlobPieces::verify() const {
  if (const std::string h = sha_->hex(); h != hash_) return damaged(hash_, size_, size_, h);
  return {};
}

StoreResult<std::string> BlobPieces::next() {
  if (at_ >= size_) return std::string();
  if (!reader_) {
    at_ = size_;
    return std::move(whole_);
  }
  auto piece = reader_->read(at_, piece_);
  if (!piece) return piece;
  if (piece->empty()) {
    return store_error(StoreErrorKind::Damaged,
                       fmt::format("the stored bytes of {} end at byte {}, before their length {}",
                                   hash_, at_, size_));
  }
  sha_->add(*piece);
  at_ += piece->size();
  if (at_ >= size_) {
    if (auto v = verify(); !v) return tl::unexpected(v.error());
    reader_.reset();  // the read transaction (SQLite) ends with the last piece
  }
  return piece;
}

}  // namespace usina::dnc
