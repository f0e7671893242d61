// A revision's bytes, stored once under their SHA-256 and checked against
// it on every read: bytes changed on disk or in the database are reported
// (StoreErrorKind::Damaged), never handed to a machine.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "dnc/sha256.hpp"
#include "dnc/store.hpp"

namespace usina::dnc {

// Inside the caller's write transaction; a blob already stored is kept as it is.
StoreResult<void> put_blob(Store& store, std::string_view hash, std::string_view bytes);

// The bytes stored under `hash`, verified.
StoreResult<std::string> read_blob(Store& store, std::string_view hash);

// A blob read a piece at a time and hashed as it goes (the export of a
// revision of up to 256 MiB): memory for one piece, not the blob. A blob of
// at most one piece is read whole and verified at once. Of a larger one,
// what went out before the damage was seen cannot be taken back: the piece
// that would complete the bytes is refused (Damaged) when they do not hash
// to the address, so a reader that stops at the error never has all of
// them. A length that is not the recorded one is refused at `open`.
class BlobPieces {
 public:
  static StoreResult<BlobPieces> open(Store& store, std::string_view hash, std::size_t piece);

  BlobPieces(BlobPieces&&) noexcept;
  BlobPieces& operator=(BlobPieces&&) noexcept;
  ~BlobPieces();

  std::uint64_t size() const { return size_; }

  // The next piece (at most `piece` bytes); empty after the last.
  StoreResult<std::string> next();

 private:
  BlobPieces() = default;
  StoreResult<void> verify() const;

  std::string hash_;
  std::size_t piece_ = 0;
  std::uint64_t size_ = 0;
  std::uint64_t at_ = 0;
  std::string whole_;                   // a blob of one piece at most, verified
  std::unique_ptr<BlobReader> reader_;  // a larger one
  std::unique_ptr<Sha256> sha_;         // of the bytes handed out so far
};

}  // namespace usina::dnc
