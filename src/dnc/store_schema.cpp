#include "dnc/store_schema.hpp"

#include <string>
#include <string_view>

#include <fmt/format.h>

#include "dnc/store_facts.hpp"

namespace usina::dnc {
namespace {

// One migration: its SQL for both back ends with `@ID@` (an integer key the
// database numbers) and `@BYTES@` (a byte column) spelled per back end, then
// what only one back end needs (triggers differ), then what fills the new
// tables from the rows already there (nullptr: nothing), in the same
// transaction.
struct Migration {
  int version;
  std::string_view common;
  std::string_view sqlite_only;
  std::string_view postgres_only;
  StoreResult<void> (*fill)(Database&);
};

// Version 1: programs, content-addressed blobs, immutable revisions, the
// hash-chained audit log (append-only: triggers refuse UPDATE and DELETE, so
// only someone who drops them can rewrite it, and the chain shows that;
// blobs and revisions are immutable the same way, but for a revision's state),
// users, sessions (only a token's hash is kept) and login attempts.
constexpr std::string_view kV1 = R"SQL(
CREATE TABLE blobs (
  hash TEXT PRIMARY KEY,
  size BIGINT NOT NULL,
  bytes @BYTES@ NOT NULL
);
CREATE TABLE programs (
  name TEXT PRIMARY KEY,
  machine_class TEXT NOT NULL,
  dialect TEXT NOT NULL,
  created_at BIGINT NOT NULL
);
CREATE TABLE revisions (
  id @ID@,
  program TEXT NOT NULL REFERENCES programs(name),
  hash TEXT NOT NULL REFERENCES blobs(hash),
  size BIGINT NOT NULL,
  author TEXT NOT NULL,
  created_at BIGINT NOT NULL,
  reason TEXT NOT NULL,
  dialect TEXT NOT NULL,
  state TEXT NOT NULL,
  state_at BIGINT NOT NULL,
  check_errors BIGINT NOT NULL,
  checks TEXT NOT NULL,
  UNIQUE (program, hash)
);
CREATE INDEX revisions_by_program ON revisions (program, id);
CREATE TABLE audit (
  seq BIGINT PRIMARY KEY,
  at BIGINT NOT NULL,
  actor TEXT NOT NULL,
  action TEXT NOT NULL,
  subject TEXT NOT NULL,
  reason TEXT NOT NULL,
  origin TEXT NOT NULL,
  detail TEXT NOT NULL,
  prev_hash TEXT NOT NULL,
  hash TEXT NOT NULL
);
CREATE TABLE users (
  name TEXT PRIMARY KEY,
  role TEXT NOT NULL,
  password_hash TEXT NOT NULL,
  created_at BIGINT NOT NULL,
  disabled BIGINT NOT NULL DEFAULT 0
);
CREATE TABLE sessions (
  token_hash TEXT PRIMARY KEY,
  user_name TEXT NOT NULL REFERENCES users(name),
  created_at BIGINT NOT NULL,
  expires_at BIGINT NOT NULL
);
CREATE TABLE login_attempts (
  id @ID@,
  user_name TEXT NOT NULL,
  origin TEXT NOT NULL,
  at BIGINT NOT NULL,
  ok BIGINT NOT NULL
);
CREATE INDEX login_attempts_by_user ON login_attempts (user_name, at);
CREATE INDEX login_attempts_by_origin ON login_attempts (origin, at);
)SQL";

constexpr std::string_view kV1Sqlite = R"SQL(
CREATE TRIGGER audit_no_update BEFORE UPDATE ON audit
  BEGIN SELECT RAISE(ABORT, 'the audit log is append-only'); END;
CREATE TRIGGER audit_no_delete BEFORE DELETE ON audit
  BEGIN SELECT RAISE(ABORT, 'the audit log is append-only'); END;
CREATE TRIGGER blobs_no_update BEFORE UPDATE ON blobs
  BEGIN SELECT RAISE(ABORT, 'a blob is immutable'); END;
CREATE TRIGGER blobs_no_delete BEFORE DELETE ON blobs
  BEGIN SELECT RAISE(ABORT, 'a blob is never deleted'); END;
CREATE TRIGGER revisions_immutable BEFORE UPDATE OF program, hash, size, author, created_at,
  reason, dialect, check_errors, checks ON revisions
  BEGIN SELECT RAISE(ABORT, 'a revision is immutable; only its state changes'); END;
CREATE TRIGGER revisions_no_delete BEFORE DELETE ON revisions
  BEGIN SELECT RAISE(ABORT, 'a revision is never deleted'); END;
)SQL";

constexpr std::string_view kV1Postgres = R"SQL(
CREATE FUNCTION usina_refuse() RETURNS trigger LANGUAGE plpgsql AS $$
BEGIN RAISE EXCEPTION '% on %: refused (append-only or immutable)', TG_OP, TG_TABLE_NAME; END $$;
CREATE TRIGGER audit_no_update BEFORE UPDATE OR DELETE ON audit
  FOR EACH ROW EXECUTE FUNCTION usina_refuse();
CREATE TRIGGER blobs_no_update BEFORE UPDATE OR DELETE ON blobs
  FOR EACH ROW EXECUTE FUNCTION usina_refuse();
CREATE TRIGGER revisions_immutable BEFORE UPDATE OF program, hash, size, author, created_at,
  reason, dialect, check_errors, checks ON revisions
  FOR EACH ROW EXECUTE FUNCTION usina_refuse();
CREATE TRIGGER revisions_no_delete BEFORE DELETE ON revisions
  FOR EACH ROW EXECUTE FUNCTION usina_refuse();
)SQL";

// Version 2: the server's jobs (a send or drip feed of a revision to a
// machine) and how each ended, so a job the server did not see to its end
// (SIGTERM, kill -9) is shown interrupted after a restart, never resent.
constexpr std::string_view kV2 = R"SQL(
CREATE TABLE jobs (
  id @ID@,
  machine TEXT NOT NULL,
  program TEXT NOT NULL,
  revision TEXT NOT NULL,
  mode TEXT NOT NULL,
  state TEXT NOT NULL,
  actor TEXT NOT NULL,
  created_at BIGINT NOT NULL,
  started_at BIGINT NOT NULL DEFAULT 0,
  ended_at BIGINT NOT NULL DEFAULT 0,
  bytes_sent BIGINT NOT NULL DEFAULT 0,
  bytes_total BIGINT NOT NULL DEFAULT 0,
  line BIGINT NOT NULL DEFAULT 0,
  block BIGINT NOT NULL DEFAULT -1,
  sha256 TEXT NOT NULL DEFAULT '',
  reason TEXT NOT NULL DEFAULT '',
  alarm BIGINT NOT NULL DEFAULT 0
);
CREATE INDEX jobs_by_machine ON jobs (machine, id);
)SQL";

// Version 3: what the controls print (store_parts.hpp): each part line with
// its cycle's time and the control's count, and each machine's last message,
// so the counts survive a restart of the server.
constexpr std::string_view kV3 = R"SQL(
CREATE TABLE control_parts (
  id @ID@,
  machine TEXT NOT NULL,
  at BIGINT NOT NULL,
  cycle_us BIGINT,
  control_count BIGINT,
  program TEXT NOT NULL,
  revision TEXT NOT NULL
);
CREATE INDEX control_parts_by_machine ON control_parts (machine, id);
CREATE INDEX control_parts_by_time ON control_parts (machine, at);
CREATE TABLE control_messages (
  machine TEXT PRIMARY KEY,
  text TEXT NOT NULL,
  at BIGINT NOT NULL
);
)SQL";

// Version 4: each machine's activity changes (store_utilisation.hpp), the
// ground of its utilisation per day.
constexpr std::string_view kV4 = R"SQL(
CREATE TABLE machine_activity (
  id @ID@,
  machine TEXT NOT NULL,
  activity TEXT NOT NULL,
  at BIGINT NOT NULL
);
CREATE INDEX machine_activity_by_time ON machine_activity (machine, at, id);
)SQL";

// Version 5: the server's last sign of life (store_utilisation.hpp), written
// every few seconds while it runs, so a server killed without a word (kill
// -9, a power cut) still has its machines' activity end near its death.
constexpr std::string_view kV5 = R"SQL(
CREATE TABLE server_heartbeat (
  server TEXT PRIMARY KEY,
  at BIGINT NOT NULL
);
)SQL";

// Version 6: what the library's search reads of each revision
// (store_facts.hpp): its program numbers and comments, and the tools it
// calls (indexed by tool). The revisions stored before it get theirs as the
// migration runs, read from their blobs, so every revision has its facts.
constexpr std::string_view kV6 = R"SQL(
CREATE TABLE revision_facts (
  revision BIGINT PRIMARY KEY REFERENCES revisions(id),
  o_numbers TEXT NOT NULL,
  comments TEXT NOT NULL
);
CREATE TABLE revision_tools (
  revision BIGINT NOT NULL REFERENCES revisions(id),
  tool BIGINT NOT NULL,
  PRIMARY KEY (revision, tool)
);
CREATE INDEX revision_tools_by_tool ON revision_tools (tool, revision);
CREATE INDEX programs_by_class ON programs (machine_class);
)SQL";

// Version 7: tool-life count resets (store_tool_resets.hpp): the tools'
// answer counts each tool's parts from its last reset.
constexpr std::string_view kV7 = R"SQL(
CREATE TABLE tool_resets (
  id @ID@,
  machine TEXT NOT NULL,
  tool BIGINT NOT NULL,
  at BIGINT NOT NULL,
  by_user TEXT NOT NULL,
  reason TEXT NOT NULL
);
CREATE INDEX tool_resets_by_machine ON tool_resets (machine, at, id);
)SQL";

// Version 8: PostgreSQL keeps new blobs uncompressed (STORAGE EXTERNAL), so
// the export reads a large revision in slices that fetch only their own
// TOAST chunks (a compressed value is decompressed from its start for each
// slice). The blobs stored before stay compressed and are read in fewer,
// larger slices (store_postgres.cpp). SQLite has nothing to change.
constexpr std::string_view kV8Postgres = R"SQL(
ALTER TABLE blobs ALTER COLUMN bytes SET STORAGE EXTERNAL;
)SQL";

// Version 9: a revision's setup sheet (store_sheets.hpp), HTML or PDF, its
// bytes a blob like the revision's own; one of each format a revision, a
// later one replacing it (each an audit entry naming the one before).
constexpr std::string_view kV9 = R"SQL(
CREATE TABLE revision_sheets (
  program TEXT NOT NULL,
  revision TEXT NOT NULL,
  format TEXT NOT NULL,
  blob TEXT NOT NULL REFERENCES blobs(hash),
  size BIGINT NOT NULL,
  author TEXT NOT NULL,
  created_at BIGINT NOT NULL,
  PRIMARY KEY (program, revision, format),
  FOREIGN KEY (program, revision) REFERENCES revisions(program, hash)
);
)SQL";

// Version 10: quality records (store_quality.hpp), measurements entered
// through the API for a machine's parts: append-only, as the audit log,
// since a record is evidence.
constexpr std::string_view kV10 = R"SQL(
CREATE TABLE quality_records (
  id @ID@,
  machine TEXT NOT NULL,
  at BIGINT NOT NULL,
  by_user TEXT NOT NULL,
  characteristic TEXT NOT NULL,
  measured TEXT NOT NULL,
  nominal TEXT NOT NULL,
  min_value TEXT NOT NULL,
  max_value TEXT NOT NULL,
  unit TEXT NOT NULL,
  part TEXT NOT NULL,
  program TEXT NOT NULL,
  job BIGINT NOT NULL,
  note TEXT NOT NULL
);
CREATE INDEX quality_by_machine ON quality_records (machine, id);
)SQL";

constexpr std::string_view kV10Sqlite = R"SQL(
CREATE TRIGGER quality_no_update BEFORE UPDATE ON quality_records
  BEGIN SELECT RAISE(ABORT, 'quality records are append-only'); END;
CREATE TRIGGER quality_no_delete BEFORE DELETE ON quality_records
  BEGIN SELECT RAISE(ABORT, 'quality records are append-only'); END;
)SQL";

constexpr std::string_view kV10Postgres = R"SQL(
CREATE TRIGGER quality_no_change BEFORE UPDATE OR DELETE ON quality_records
  FOR EACH ROW EXECUTE FUNCTION usina_refuse();
)SQL";

// Version 11: machines an admin added through the API (store_machines.hpp),
// beside the configuration file's: each one's settings as the API took them
// (JSON with the [[machine]] table's keys), and when it was retired. A
// retired machine's row stays, so its name keeps its history (jobs,
// utilisation, quality records) and is not given to another machine.
constexpr std::string_view kV11 = R"SQL(
CREATE TABLE machines (
  name TEXT PRIMARY KEY,
  settings TEXT NOT NULL,
  created_at BIGINT NOT NULL,
  created_by TEXT NOT NULL,
  changed_at BIGINT NOT NULL,
  retired_at BIGINT NOT NULL DEFAULT 0,
  retired_by TEXT NOT NULL DEFAULT '',
  retire_reason TEXT NOT NULL DEFAULT ''
);
)SQL";

constexpr Migration kMigrations[] = {
    {1, kV1, kV1Sqlite, kV1Postgres, nullptr},
    {2, kV2, "SELECT 1", "SELECT 1", nullptr},
    {3, kV3, "SELECT 1", "SELECT 1", nullptr},
    {4, kV4, "SELECT 1", "SELECT 1", nullptr},
    {5, kV5, "SELECT 1", "SELECT 1", nullptr},
    {6, kV6, "SELECT 1", "SELECT 1", &record_missing_facts},
    {7, kV7, "SELECT 1", "SELECT 1", nullptr},
    {8, "SELECT 1", "SELECT 1", kV8Postgres, nullptr},
    {9, kV9, "SELECT 1", "SELECT 1", nullptr},
    {10, kV10, kV10Sqlite, kV10Postgres, nullptr},
    {11, kV11, "SELECT 1", "SELECT 1", nullptr},
};

std::string spelled(std::string_view sql, Backend b) {
  std::string out(sql);
  const auto replace = [&out](std::string_view from, std::string_view to) {
    for (std::size_t at = out.find(from); at != std::string::npos; at = out.find(from, at))
      out.replace(at, from.size(), to);
  };
  replace("@ID@", b == Backend::Sqlite ? "INTEGER PRIMARY KEY"
                                       : "BIGINT GENERATED BY DEFAULT AS IDENTITY PRIMARY KEY");
  replace("@BYTES@", b == Backend::Sqlite ? "BLOB" : "BYTEA");
  return out;
}

StoreResult<int> read_version(Database& db) {
  auto made = db.script("CREATE TABLE IF NOT EXISTS schema_version (version BIGINT NOT NULL)");
  if (!made) return tl::unexpected(made.error());
  auto rows = db.query("SELECT MAX(version) FROM schema_version");
  if (!rows) return tl::unexpected(rows.error());
  return rows->empty() ? 0 : static_cast<int>(rows->front().integer(0));
}

StoreResult<void> run(Database& db, const Migration& m) {
  Transaction tx(db);
  if (auto b = tx.begin_write(); !b) return b;
  // Another process may have run it while this one waited for the lock.
  auto version = read_version(db);
  if (!version) return tl::unexpected(version.error());
  if (*version >= m.version) return tx.commit();
  const Backend b = db.backend();
  if (auto r = db.script(spelled(m.common, b)); !r) return r;
  if (auto r = db.script(b == Backend::Sqlite ? m.sqlite_only : m.postgres_only); !r) return r;
  if (m.fill != nullptr) {
    if (auto r = m.fill(db); !r) return r;
  }
  auto r = db.query("INSERT INTO schema_version (version) VALUES ($1)",
                    {static_cast<std::int64_t>(m.version)});
  if (!r) return tl::unexpected(r.error());
  return tx.commit();
}

}  // namespace

int current_schema_version() {
  return kMigrations[std::size(kMigrations) - 1].version;
}

StoreResult<int> migrate(Database& db) {
  auto before = read_version(db);
  if (!before) return before;
  if (*before > current_schema_version()) {
    return store_error(StoreErrorKind::Conflict,
                       fmt::format("the store has schema version {}, newer than this usina's {}; "
                                   "use the usina that wrote it",
                                   *before, current_schema_version()));
  }
  for (const Migration& m : kMigrations) {
    if (m.version <= *before) continue;
    if (auto r = run(db, m); !r) return tl::unexpected(r.error());
  }
  return *before;
}

}  // namespace usina::dnc
