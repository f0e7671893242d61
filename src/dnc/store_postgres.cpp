// The PostgreSQL back end (libpqxx): one connection, one transaction at a
// time. Writers take a transaction-scoped advisory lock, so two servers on
// one database append to the audit chain one after the other. BYTEA goes
// over the wire in its hex text form, which keeps every parameter text and
// lets one dynamic parameter list carry them all.
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
