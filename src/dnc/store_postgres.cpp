// The PostgreSQL back end (libpqxx): one connection, one transaction at a
// time. Writers take a transaction-scoped advisory lock, so two servers on
// one database append to the audit chain one after the other. BYTEA goes
// over the wire in its hex text form, which keeps every parameter text and
// lets one dynamic parameter list carry them all.
#include <algorithm>
#include <exception>
#include <memory>

#include <fmt/format.h>
#include <pqxx/pqxx>

#include "dnc/store_db.hpp"

namespace usina::dnc {
namespace {

// The advisory lock every write transaction holds ("usina" in ASCII).
constexpr long long kWriteLock = 0x7573696e61;
constexpr pqxx::oid kByteaOid = 17;

std::string bytea_hex(std::string_view bytes) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  out.reserve(2 + bytes.size() * 2);
  out += "\\x";
  for (const char c : bytes) {
    const auto b = static_cast<unsigned char>(c);
    out += kDigits[b >> 4];
    out += kDigits[b & 15];
  }
  return out;
}

tl::unexpected<StoreError> failure(const std::exception& e) {
  std::string what = e.what();
  while (!what.empty() && (what.back() == '\n' || what.back() == ' '))
    what.pop_back();
  return store_error(StoreErrorKind::Backend, "postgresql: " + what);
}

SqlRows read_rows(const pqxx::result& r) {
  SqlRows rows;
  rows.reserve(r.size());
  const auto columns = static_cast<pqxx::row::size_type>(r.columns());
  for (const auto& row : r) {
    SqlRow out;
    out.columns.reserve(static_cast<std::size_t>(columns));
    for (pqxx::row::size_type c = 0; c < columns; ++c) {
      const pqxx::field f = row[c];
      if (f.is_null()) {
        out.columns.emplace_back(std::nullopt);
      } else if (r.column_type(c) == kByteaOid) {
        out.columns.emplace_back(pqxx::binarystring(f).str());
      } else {
        out.columns.emplace_back(std::string(f.c_str(), f.size()));
      }
    }
    rows.push_back(std::move(out));
  }
  return rows;
}

// A BYTEA value in slices: `substring(column FROM offset FOR n)`, which
// PostgreSQL answers from the TOAST chunks the slice covers when the value
// is stored uncompressed (STORAGE EXTERNAL, schema version 8). A value
// stored compressed before that is decompressed from its start for every
// slice, so it is read in 16 slices at most (each decompression stops at its
// slice's end): about 8 times the decompression of one whole read, and a
// 16th of the value in memory.
class PostgresBlobReader final : public BlobReader {
 public:
  PostgresBlobReader(Database& db, std::string slice_sql, std::string key, std::uint64_t size,
                     bool compressed)
      : db_(db),
        slice_sql_(std::move(slice_sql)),
        key_(std::move(key)),
        size_(size),
        least_slice_(compressed ? (size + kCompressedSlices - 1) / kCompressedSlices : 0) {}

  std::uint64_t size() const override { return size_; }

  StoreResult<std::string> read(std::uint64_t offset, std::size_t n) override {
    if (offset >= size_) return std::string();
    n = static_cast<std::size_t>(std::min<std::uint64_t>(n, size_ - offset));
    if (offset < held_at_ || offset + n > held_at_ + held_.size()) {
      const std::uint64_t want = std::min(std::max<std::uint64_t>(n, least_slice_), size_ - offset);
      auto rows =
          db_.query(slice_sql_, {std::string_view(key_), static_cast<std::int64_t>(offset + 1),
                                 static_cast<std::int64_t>(want)});
      if (!rows) return tl::unexpected(rows.error());
      if (rows->empty() || rows->front().is_null(0))
        return store_error(StoreErrorKind::NotFound,
                           fmt::format("{} is gone from the store", key_));
      held_ = std::move(*rows->front().columns[0]);
      held_at_ = offset;
      if (held_.size() < n) {
        return store_error(StoreErrorKind::Damaged,
                           fmt::format("{} ends at byte {}, before its length {}", key_,
                                       offset + held_.size(), size_));
      }
    }
    return held_.substr(static_cast<std::size_t>(offset - held_at_), n);
  }

 private:
  static constexpr std::uint64_t kCompressedSlices = 16;

  Database& db_;
  std::string slice_sql_;
  std::string key_;
  std::uint64_t size_;
  std::uint64_t least_slice_;  // 0: each slice as asked
  std::string held_;           // the last slice asked of the server
  std::uint64_t held_at_ = 0;
};

class PostgresDatabase final : public Database {
 public:
  explicit PostgresDatabase(const std::string& url) : conn_(url) {}

  Backend backend() const override { return Backend::Postgres; }

  StoreResult<SqlRows> query(std::string_view sql, const SqlParams& params) override {
    std::vector<std::string> texts;
    texts.reserve(params.size());
    std::vector<const char*> values;
    values.reserve(params.size());
    for (const SqlValue& v : params)
      values.push_back(text_of(v, texts));
    try {
      return with_transaction([&](pqxx::transaction_base& tx) {
        return read_rows(
            tx.exec_params(std::string(sql), pqxx::prepare::make_dynamic_params(values)));
      });
    } catch (const std::exception& e) {
      return failure(e);
    }
  }

  StoreResult<void> script(std::string_view sql) override {
    try {
      with_transaction([&](pqxx::transaction_base& tx) {
        tx.exec(std::string(sql));
        return SqlRows{};
      });
      return {};
    } catch (const std::exception& e) {
      return failure(e);
    }
  }

  StoreResult<std::unique_ptr<BlobReader>> open_blob(std::string_view table,
                                                     std::string_view column,
                                                     std::string_view key_column,
                                                     std::string_view key) override {
    // octet_length and pg_column_size read the TOAST pointer, not the value;
    // a stored size below the length is a compressed value.
    auto rows = query(fmt::format("SELECT octet_length({0}), pg_column_size({0}) FROM {1} "
                                  "WHERE {2} = $1",
                                  column, table, key_column),
                      {key});
    if (!rows) return tl::unexpected(rows.error());
    if (rows->empty())
      return store_error(StoreErrorKind::NotFound, fmt::format("no blob {} in the store", key));
    const auto size = static_cast<std::uint64_t>(rows->front().integer(0));
    const bool compressed = static_cast<std::uint64_t>(rows->front().integer(1)) < size;
    std::string sql = fmt::format("SELECT substring({} FROM $2 FOR $3) FROM {} WHERE {} = $1",
                                  column, table, key_column);
    return std::unique_ptr<BlobReader>(std::make_unique<PostgresBlobReader>(
        *this, std::move(sql), std::string(key), size, compressed));
  }

  StoreResult<void> begin_write() override {
    try {
      tx_ = std::make_unique<pqxx::work>(conn_);
      tx_->exec(fmt::format("SELECT pg_advisory_xact_lock({})", kWriteLock));
      return {};
    } catch (const std::exception& e) {
      tx_.reset();
      return failure(e);
    }
  }

  // One snapshot for the whole read (a listing, an audit verification).
  StoreResult<void> begin_read() override {
    try {
      tx_ = std::make_unique<pqxx::transaction<pqxx::repeatable_read>>(conn_);
      return {};
    } catch (const std::exception& e) {
      tx_.reset();
      return failure(e);
    }
  }

  StoreResult<void> commit() override {
    if (!tx_) return {};
    try {
      tx_->commit();
      tx_.reset();
      return {};
    } catch (const std::exception& e) {
      tx_.reset();
      return failure(e);
    }
  }

  void rollback() noexcept override {
    try {
      if (tx_) tx_->abort();
    } catch (...) {  // NOLINT(bugprone-empty-catch): a broken connection has nothing to undo
    }
    tx_.reset();
  }

 private:
  static const char* text_of(const SqlValue& v, std::vector<std::string>& texts) {
    if (std::holds_alternative<std::monostate>(v)) return nullptr;
    if (const auto* i = std::get_if<std::int64_t>(&v)) {
      texts.push_back(std::to_string(*i));
    } else if (const auto* t = std::get_if<std::string_view>(&v)) {
      texts.emplace_back(*t);
    } else {
      texts.push_back(bytea_hex(std::get<SqlBlob>(v).bytes));
    }
    return texts.back().c_str();
  }

  template <typename F>
  SqlRows with_transaction(F&& f) {
    if (tx_) return f(*tx_);
    pqxx::nontransaction once(conn_);
    return f(once);
  }

  pqxx::connection conn_;
  std::unique_ptr<pqxx::transaction_base> tx_;
};

}  // namespace

StoreResult<std::unique_ptr<Database>> open_postgres(const std::string& url) {
  try {
    return std::unique_ptr<Database>(std::make_unique<PostgresDatabase>(url));
  } catch (const std::exception& e) {
    return failure(e);
  }
}

}  // namespace usina::dnc
