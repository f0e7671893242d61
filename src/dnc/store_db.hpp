// The one seam between the store and its two back ends (SQLite, PostgreSQL):
// a connection that runs parameterised SQL and transactions. Everything above
// it (revisions, audit, users) is written once, so both back ends behave
// alike and one test suite runs against both.
//
// SQL is written once too: parameters are `$1`, `$2`, ... (both back ends
// read them), and the few words the back ends spell differently are the
// migrations' business (store_schema.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "dnc/store_error.hpp"

namespace usina::dnc {

enum class Backend { Sqlite, Postgres };

// Bytes for a BLOB / BYTEA column (a std::string is TEXT).
struct SqlBlob {
  std::string_view bytes;
};

using SqlValue = std::variant<std::monostate, std::int64_t, std::string_view, SqlBlob>;
using SqlParams = std::vector<SqlValue>;

// One row of a result; a NULL column is nullopt. A BYTEA / BLOB column holds
// its bytes as they are.
struct SqlRow {
  std::vector<std::optional<std::string>> columns;

  const std::string& text(std::size_t i) const;  // "" for NULL
  std::int64_t integer(std::size_t i) const;     // 0 for NULL or not a number

  bool is_null(std::size_t i) const { return !columns.at(i).has_value(); }
};

using SqlRows = std::vector<SqlRow>;

// One BLOB / BYTEA value read a slice at a time, so a large one (a revision
// of up to 256 MiB) is never whole in memory. The value is immutable while
// it is read (the store's triggers refuse UPDATE and DELETE of blobs).
class BlobReader {
 public:
  virtual ~BlobReader() = default;

  // The value's length in bytes, as stored.
  virtual std::uint64_t size() const = 0;
  // Up to `n` bytes from `offset`: fewer only at the end.
  virtual StoreResult<std::string> read(std::uint64_t offset, std::size_t n) = 0;
};

class Database {
 public:
  virtual ~Database() = default;

  virtual Backend backend() const = 0;

  // Runs one statement; its rows (none for a statement without a result).
  virtual StoreResult<SqlRows> query(std::string_view sql, const SqlParams& params = {}) = 0;
  // Runs several statements without parameters (a migration).
  virtual StoreResult<void> script(std::string_view sql) = 0;

  // The `column` of the `table` row whose `key_column` is `key`, to read in
  // slices (NotFound without such a row). Names are the caller's constants,
  // never a user's text. SQLite reads it through a connection of its own
  // (incremental BLOB I/O), so the store's connection stays free for other
  // requests between slices; PostgreSQL asks for each slice on the store's
  // connection, outside any transaction.
  virtual StoreResult<std::unique_ptr<BlobReader>> open_blob(std::string_view table,
                                                             std::string_view column,
                                                             std::string_view key_column,
                                                             std::string_view key) = 0;

  // A write transaction: writers are serialised (SQLite BEGIN IMMEDIATE,
  // PostgreSQL a transaction-scoped advisory lock), so the audit chain and
  // revision numbers are never raced.
  virtual StoreResult<void> begin_write() = 0;
  virtual StoreResult<void> begin_read() = 0;
  virtual StoreResult<void> commit() = 0;
  // Never fails: a rollback of a broken connection is a no-op.
  virtual void rollback() noexcept = 0;
};

// SQLite in `folder`/usina.db (the folder is created), WAL mode.
StoreResult<std::unique_ptr<Database>> open_sqlite(const std::string& folder);
// PostgreSQL at a `postgresql://` URL.
StoreResult<std::unique_ptr<Database>> open_postgres(const std::string& url);

}  // namespace usina::dnc

namespace usina::dnc {

// Rolls back unless committed: an early return or an error mid-way leaves
// nothing half-written.
class Transaction {
 public:
  explicit Transaction(Database& db) : db_(db) {}

  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;

  ~Transaction() {
    if (open_) db_.rollback();
  }

  StoreResult<void> begin_write() { return begin(db_.begin_write()); }

  StoreResult<void> begin_read() { return begin(db_.begin_read()); }

  StoreResult<void> commit() {
    open_ = false;
    return db_.commit();
  }

 private:
  StoreResult<void> begin(StoreResult<void> r) {
    open_ = r.has_value();
    return r;
  }

  Database& db_;
  bool open_ = false;
};

}  // namespace usina::dnc
