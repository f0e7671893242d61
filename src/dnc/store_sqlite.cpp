// The SQLite back end: one file, DIR/usina.db, in WAL mode (readers never
// wait for the writer; a crash mid-transaction leaves the last commit),
// synchronous=FULL (a committed revision survives a power cut), foreign keys
// on, and a busy timeout so two processes on one folder wait, not fail.
#include <sqlite3.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <fmt/format.h>
#include <sys/stat.h>

#include "dnc/store_db.hpp"

namespace usina::dnc {
namespace {

constexpr int kBusyTimeoutMs = 10'000;

class Statement {
 public:
  Statement(sqlite3* db, std::string_view sql) {
    rc_ = sqlite3_prepare_v2(db, sql.data(), static_cast<int>(sql.size()), &stmt_, nullptr);
  }

  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  ~Statement() { sqlite3_finalize(stmt_); }

  int prepared() const { return rc_; }

  sqlite3_stmt* get() const { return stmt_; }

 private:
  sqlite3_stmt* stmt_ = nullptr;
  int rc_ = SQLITE_OK;
};

int bind_one(sqlite3_stmt* s, int index, const SqlValue& v) {
  if (std::holds_alternative<std::monostate>(v)) return sqlite3_bind_null(s, index);
  if (const auto* i = std::get_if<std::int64_t>(&v)) return sqlite3_bind_int64(s, index, *i);
  if (const auto* t = std::get_if<std::string_view>(&v)) {
    // An empty view may have no data; SQLite would bind NULL for it.
    return sqlite3_bind_text64(s, index, t->empty() ? "" : t->data(), t->size(), SQLITE_STATIC,
                               SQLITE_UTF8);
  }
  const SqlBlob& b = std::get<SqlBlob>(v);
  // A zero-length blob is still a blob, not NULL.
  if (b.bytes.empty()) return sqlite3_bind_zeroblob(s, index, 0);
  return sqlite3_bind_blob64(s, index, b.bytes.data(), b.bytes.size(), SQLITE_STATIC);
}

SqlRow read_row(sqlite3_stmt* s) {
  SqlRow row;
  const int n = sqlite3_column_count(s);
  row.columns.reserve(static_cast<std::size_t>(n));
  for (int c = 0; c < n; ++c) {
    if (sqlite3_column_type(s, c) == SQLITE_NULL) {
      row.columns.emplace_back(std::nullopt);
      continue;
    }
    const void* p = sqlite3_column_blob(s, c);
    const auto len = static_cast<std::size_t>(sqlite3_column_bytes(s, c));
    row.columns.emplace_back(std::string(static_cast<const char*>(p), p == nullptr ? 0 : len));
  }
  return row;
}

// A connection closed with its owner: the blob reader's own.
struct Connection {
  sqlite3* db = nullptr;

  Connection() = default;
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  ~Connection() { sqlite3_close_v2(db); }
};

// Incremental BLOB I/O (sqlite3_blob_read) on a read-only connection of its
// own, inside one read transaction: the handle keeps the row's overflow
// pages' list, so each slice costs its own pages only, and the store's
// connection keeps no statement open (its own snapshot moves on).
class SqliteBlobReader final : public BlobReader {
 public:
  SqliteBlobReader(std::unique_ptr<Connection> connection, sqlite3_blob* blob)
      : connection_(std::move(connection)), blob_(blob) {}

  SqliteBlobReader(const SqliteBlobReader&) = delete;
  SqliteBlobReader& operator=(const SqliteBlobReader&) = delete;

  ~SqliteBlobReader() override {
    sqlite3_blob_close(blob_);
    sqlite3_exec(connection_->db, "ROLLBACK", nullptr, nullptr, nullptr);
  }

  std::uint64_t size() const override {
    return static_cast<std::uint64_t>(sqlite3_blob_bytes(blob_));
  }

  StoreResult<std::string> read(std::uint64_t offset, std::size_t n) override {
    if (offset >= size()) return std::string();
    n = static_cast<std::size_t>(std::min<std::uint64_t>(n, size() - offset));
    std::string out(n, '\0');
    const int rc =
        sqlite3_blob_read(blob_, out.data(), static_cast<int>(n), static_cast<int>(offset));
    if (rc != SQLITE_OK) {
      return store_error(StoreErrorKind::Backend,
                         fmt::format("sqlite blob read at {}: {}", offset, sqlite3_errstr(rc)));
    }
    return out;
  }

 private:
  std::unique_ptr<Connection> connection_;
  sqlite3_blob* blob_;
};

class SqliteDatabase final : public Database {
 public:
  SqliteDatabase(sqlite3* db, std::string path) : db_(db), path_(std::move(path)) {}

  SqliteDatabase(const SqliteDatabase&) = delete;
  SqliteDatabase& operator=(const SqliteDatabase&) = delete;

  ~SqliteDatabase() override { sqlite3_close_v2(db_); }

  Backend backend() const override { return Backend::Sqlite; }

  StoreResult<SqlRows> query(std::string_view sql, const SqlParams& params) override {
    Statement st(db_, sql);
    if (st.prepared() != SQLITE_OK) return failure("prepare");
    if (auto bound = bind(st.get(), params); !bound) return tl::unexpected(bound.error());
    SqlRows rows;
    for (;;) {
      const int rc = sqlite3_step(st.get());
      if (rc == SQLITE_DONE) break;
      if (rc != SQLITE_ROW) return failure("step");
      rows.push_back(read_row(st.get()));
    }
    return rows;
  }

  StoreResult<void> script(std::string_view sql) override {
    const std::string text(sql);
    char* err = nullptr;
    if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
      std::string msg = err != nullptr ? err : "unknown error";
      sqlite3_free(err);
      return store_error(StoreErrorKind::Backend, "sqlite: " + msg);
    }
    return {};
  }

  StoreResult<std::unique_ptr<BlobReader>> open_blob(std::string_view table,
                                                     std::string_view column,
                                                     std::string_view key_column,
                                                     std::string_view key) override {
    auto c = std::make_unique<Connection>();
    const int rc =
        sqlite3_open_v2(path_.c_str(), &c->db, SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX, nullptr);
    if (rc != SQLITE_OK) {
      return store_error(StoreErrorKind::Backend, fmt::format("cannot open {} to read a blob: {}",
                                                              path_, sqlite3_errstr(rc)));
    }
    sqlite3_busy_timeout(c->db, kBusyTimeoutMs);
    // One snapshot from the row's look-up to the last slice.
    if (sqlite3_exec(c->db, "BEGIN", nullptr, nullptr, nullptr) != SQLITE_OK)
      return failure_of(c->db, "begin");
    auto rowid =
        rowid_of(c->db, fmt::format("SELECT rowid FROM {} WHERE {} = $1", table, key_column), key);
    if (!rowid) return tl::unexpected(rowid.error());
    sqlite3_blob* blob = nullptr;
    if (sqlite3_blob_open(c->db, "main", std::string(table).c_str(), std::string(column).c_str(),
                          *rowid, 0, &blob) != SQLITE_OK) {
      sqlite3_blob_close(blob);
      return failure_of(c->db, "blob open");
    }
    return std::unique_ptr<BlobReader>(std::make_unique<SqliteBlobReader>(std::move(c), blob));
  }

  StoreResult<void> begin_write() override { return script("BEGIN IMMEDIATE"); }

  StoreResult<void> begin_read() override { return script("BEGIN"); }

  StoreResult<void> commit() override { return script("COMMIT"); }

  void rollback() noexcept override {
    if (sqlite3_get_autocommit(db_) == 0) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
  }

 private:
  StoreResult<void> bind(sqlite3_stmt* s, const SqlParams& params) {
    for (std::size_t i = 0; i < params.size(); ++i) {
      const std::string name = fmt::format("${}", i + 1);
      const int index = sqlite3_bind_parameter_index(s, name.c_str());
      if (index == 0) continue;  // a parameter the statement does not use
      if (bind_one(s, index, params[i]) != SQLITE_OK) return failure("bind");
    }
    return {};
  }

  static tl::unexpected<StoreError> failure_of(sqlite3* db, const char* what) {
    return store_error(StoreErrorKind::Backend,
                       fmt::format("sqlite {}: {}", what, sqlite3_errmsg(db)));
  }

  tl::unexpected<StoreError> failure(const char* what) const { return failure_of(db_, what); }

  // The rowid `sql` answers for `key`; NotFound without a row.
  static StoreResult<sqlite3_int64> rowid_of(sqlite3* db, const std::string& sql,
                                             std::string_view key) {
    Statement st(db, sql);
    if (st.prepared() != SQLITE_OK) return failure_of(db, "prepare");
    if (bind_one(st.get(), 1, key) != SQLITE_OK) return failure_of(db, "bind");
    const int rc = sqlite3_step(st.get());
    if (rc == SQLITE_DONE)
      return store_error(StoreErrorKind::NotFound, fmt::format("no blob {} in the store", key));
    if (rc != SQLITE_ROW) return failure_of(db, "step");
    return sqlite3_column_int64(st.get(), 0);
  }

  sqlite3* db_;
  std::string path_;
};

StoreResult<void> make_folder(const std::string& folder) {
  if (::mkdir(folder.c_str(), 0700) == 0 || errno == EEXIST) {
    struct stat st {};

    if (::stat(folder.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) return {};
    return store_error(StoreErrorKind::Invalid, fmt::format("{} is not a folder", folder));
  }
  return store_error(StoreErrorKind::Backend, fmt::format("cannot create the store folder {}: {}",
                                                          folder, std::strerror(errno)));
}

}  // namespace

StoreResult<std::unique_ptr<Database>> open_sqlite(const std::string& folder) {
  if (auto made = make_folder(folder); !made) return tl::unexpected(made.error());
  const std::string path = folder + "/usina.db";
  sqlite3* raw = nullptr;
  const int rc =
      sqlite3_open_v2(path.c_str(), &raw,
                      SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX, nullptr);
  auto db = std::make_unique<SqliteDatabase>(raw, path);
  if (rc != SQLITE_OK) {
    return store_error(StoreErrorKind::Backend,
                       fmt::format("cannot open {}: {}", path, sqlite3_errstr(rc)));
  }
  sqlite3_busy_timeout(raw, kBusyTimeoutMs);
  auto set =
      db->script("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL; PRAGMA foreign_keys=ON;");
  if (!set) return tl::unexpected(set.error());
  return std::unique_ptr<Database>(std::move(db));
}

}  // namespace usina::dnc
