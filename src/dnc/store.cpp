#include "dnc/store.hpp"

#include <sodium.h>

#include <chrono>

#include "dnc/store_schema.hpp"

namespace usina::dnc {

bool is_postgres_url(std::string_view where) {
  return where.starts_with("postgresql://") || where.starts_with("postgres://");
}

Store::Store(std::unique_ptr<Database> db, StoreOptions options)
    : db_(std::move(db)), options_(std::move(options)) {
  if (!options_.now_us) {
    options_.now_us = [] {
      return std::chrono::duration_cast<std::chrono::microseconds>(
                 std::chrono::system_clock::now().time_since_epoch())
          .count();
    };
  }
}

StoreResult<std::unique_ptr<Store>> Store::open(const std::string& where, StoreOptions options) {
  if (sodium_init() < 0)
    return store_error(StoreErrorKind::Backend, "libsodium cannot start (no random source)");
  if (where.empty()) return store_error(StoreErrorKind::Invalid, "no store folder or URL given");
  auto db = is_postgres_url(where) ? open_postgres(where) : open_sqlite(where);
  if (!db) return tl::unexpected(db.error());
  if (auto m = migrate(**db); !m) return tl::unexpected(m.error());
  return std::unique_ptr<Store>(new Store(std::move(*db), std::move(options)));
}

}  // namespace usina::dnc
