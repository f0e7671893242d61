#include "dnc/store_blobs.hpp"

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

StoreResult<std::string> read_blob(Store& store, std::string_view hash) {
  auto rows = store.db().query("SELECT size, bytes FROM blobs WHERE hash = $1", {hash});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty())
    return store_error(StoreErrorKind::NotFound, fmt::format("no blob {} in the store", hash));
  SqlRow& row = rows->front();
  std::string bytes = row.columns.at(1).value_or(std::string());
  const auto size = static_cast<std::uint64_t>(row.integer(0));
  if (const std::string h = sha256_hex(bytes); h != hash || size != bytes.size()) {
    return store_error(StoreErrorKind::Damaged,
                       fmt::format("the stored bytes of {} are damaged: {} bytes (recorded {}) "
                                   "that hash to {}; restore the store from a backup",
                                   hash, bytes.size(), size, h));
  }
  return bytes;
}

}  // namespace usina::dnc
