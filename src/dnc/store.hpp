// The program store of `usina serve` (docs/dnc.md): programs with immutable,
// content-addressed revisions and their states, blobs checked on every read,
// a hash-chained audit log, users and sessions. One Store, two back ends:
// a folder (SQLite, WAL) or a `postgresql://` URL, behind store_db.hpp.
//
// The operations are free functions by topic, each over a Store:
//   store_revisions.hpp  programs, revisions, states, diffs
//   store_blobs.hpp      the bytes of a revision, verified on read
//   store_audit.hpp      the audit log and its verification
//   store_users.hpp      accounts, passwords, sessions, login limits
//   store_import.hpp     a folder in, the released set out
// A Store is one connection: use it from one thread at a time (the server
// runs one event loop; a second process opens its own Store).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "dnc/store_db.hpp"
#include "dnc/store_error.hpp"

namespace usina::dnc {

struct StoreOptions {
  // The largest revision accepted (an upload, an imported file).
  std::uint64_t max_program_bytes = 256ull << 20;
  // argon2id's cost (libsodium's "interactive" limits by default; tests lower them).
  std::uint64_t password_ops = 2;
  std::size_t password_memory = 64u << 20;
  // A session's life.
  std::int64_t session_seconds = 8 * 3600;
  // Login limits: this many failures within the window lock the user (or
  // the origin) until the window has passed since the last failure.
  int max_failures_per_user = 5;
  int max_failures_per_origin = 20;
  std::int64_t failure_window_seconds = 15 * 60;
  // Microseconds since 1970 (UTC); tests set a clock of their own.
  std::function<std::int64_t()> now_us;
  // Called at named points of a write ("upload.blob-written",
  // "upload.before-commit"): the crash tests stop a process there.
  std::function<void(std::string_view)> hook;
};

class Store {
 public:
  // `where`: a folder (created when missing) for SQLite, or a
  // postgresql:// (postgres://) URL. Creates or migrates the schema.
  static StoreResult<std::unique_ptr<Store>> open(const std::string& where,
                                                  StoreOptions options = {});

  Database& db() { return *db_; }

  const StoreOptions& options() const { return options_; }

  std::int64_t now_us() const { return options_.now_us(); }

  void hook(std::string_view point) const {
    if (options_.hook) options_.hook(point);
  }

 private:
  Store(std::unique_ptr<Database> db, StoreOptions options);

  std::unique_ptr<Database> db_;
  StoreOptions options_;
};

// Who does something, from where: what the audit log records.
struct Actor {
  std::string user;
  std::string origin;  // "127.0.0.1:53122", "cli", "import"
};

bool is_postgres_url(std::string_view where);

}  // namespace usina::dnc
