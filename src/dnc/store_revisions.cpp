#include "dnc/store_revisions.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dnc/sha256.hpp"
#include "dnc/store_audit.hpp"
#include "dnc/store_blobs.hpp"
#include "dnc/store_facts.hpp"
#include "dnc/store_names.hpp"
#include "gcode/dialect.hpp"
#include "gcode/dialect_guess.hpp"

namespace usina::dnc {
namespace {

constexpr std::string_view kRevisionColumns =
    "program, hash, size, author, created_at, reason, dialect, state, state_at, check_errors, "
    "checks";

Revision revision_of(const SqlRow& r) {
  Revision v;
  v.program = r.text(0);
  v.hash = r.text(1);
  v.size = r.integer(2);
  v.author = r.text(3);
  v.created_at_us = r.integer(4);
  v.reason = r.text(5);
  v.dialect = r.text(6);
  v.state = parse_state(r.text(7)).value_or(RevisionState::Rejected);
  v.state_at_us = r.integer(8);
  v.check_blocking = static_cast<std::uint64_t>(r.integer(9));
  v.checks_json = r.text(10);
  return v;
}

std::string subject(std::string_view program, std::string_view hash) {
  return fmt::format("{}@{}", program, hash);
}

StoreResult<void> check_upload(const Store& store, const Upload& u, const Actor& a) {
  if (auto r = check_name("program name", u.name); !r) return r;
  if (!u.machine_class.empty()) {
    if (auto r = check_name("machine class", u.machine_class); !r) return r;
  }
  if (!u.dialect.empty() && gcode::find_dialect(u.dialect) == nullptr)
    return store_error(StoreErrorKind::Invalid, fmt::format("unknown dialect '{}'", u.dialect));
  if (auto r = check_name("user name", a.user); !r) return r;
  if (auto r = check_text("reason", u.reason, kMaxReasonBytes); !r) return r;
  if (auto r = check_text("origin", a.origin, kMaxOriginBytes); !r) return r;
  if (u.text.size() > store.options().max_program_bytes) {
    return store_error(StoreErrorKind::TooLarge,
                       fmt::format("program {} has {} bytes; the store takes at most {}", u.name,
                                   u.text.size(), store.options().max_program_bytes));
  }
  return {};
}

StoreResult<std::optional<Program>> program_if_any(Store& store, std::string_view name) {
  auto p = find_program(store, name);
  if (p) return std::optional<Program>(std::move(*p));
  if (p.error().kind == StoreErrorKind::NotFound) return std::optional<Program>();
  return tl::unexpected(p.error());
}

// The program row: created, or the existing one when its machine class agrees.
StoreResult<void> ensure_program(Store& store, const Upload& u, std::string_view machine_class,
                                 std::string_view dialect) {
  auto existing = program_if_any(store, u.name);
  if (!existing) return tl::unexpected(existing.error());
  if (*existing) {
    if ((*existing)->machine_class == machine_class) return {};
    return store_error(StoreErrorKind::Conflict,
                       fmt::format("program {} is for machine class {}, not {}", u.name,
                                   (*existing)->machine_class, machine_class));
  }
  auto r = store.db().query(
      "INSERT INTO programs (name, machine_class, dialect, created_at) VALUES ($1, $2, $3, $4)",
      {std::string_view(u.name), machine_class, dialect, store.now_us()});
  if (!r) return tl::unexpected(r.error());
  return {};
}

StoreResult<void> set_state(Store& store, const Revision& v, RevisionState to,
                            std::string_view reason, const Actor& actor) {
  auto r = store.db().query(
      "UPDATE revisions SET state = $1, state_at = $2 WHERE program = $3 AND hash = $4",
      {state_name(to), store.now_us(), std::string_view(v.program), std::string_view(v.hash)});
  if (!r) return tl::unexpected(r.error());
  const nlohmann::json detail = {{"from", state_name(v.state)}, {"to", state_name(to)}};
  auto a = append_audit(
      store, actor,
      {"revision.state", subject(v.program, v.hash), std::string(reason), detail.dump()});
  if (!a) return tl::unexpected(a.error());
  return {};
}

StoreResult<void> insert_revision(Store& store, const Revision& v, const Actor& actor) {
  auto r = store.db().query(
      fmt::format(
          "INSERT INTO revisions ({}) VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11)",
          kRevisionColumns),
      {std::string_view(v.program), std::string_view(v.hash), v.size, std::string_view(v.author),
       v.created_at_us, std::string_view(v.reason), std::string_view(v.dialect),
       state_name(v.state), v.state_at_us, static_cast<std::int64_t>(v.check_blocking),
       std::string_view(v.checks_json)});
  if (!r) return tl::unexpected(r.error());
  const nlohmann::json detail = {
      {"size", v.size}, {"dialect", v.dialect}, {"check_blocking", v.check_blocking}};
  auto a = append_audit(store, actor,
                        {"revision.upload", subject(v.program, v.hash), v.reason, detail.dump()});
  if (!a) return tl::unexpected(a.error());
  return {};
}

std::string failed_check_reason(const CheckResults& c) {
  return fmt::format("the check found {} errors and {} moves past the machine's travel", c.errors,
                     c.overtravel);
}

StoreResult<PutResult> write_revision(Store& store, const Upload& u, Revision v,
                                      const CheckResults& checks, const ProgramFacts& facts,
                                      std::string_view machine_class, const Actor& actor) {
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  if (auto p = ensure_program(store, u, machine_class, v.dialect); !p)
    return tl::unexpected(p.error());
  if (auto old = find_revision(store, v.program, v.hash); old) return PutResult{*old, false};
  if (auto b = put_blob(store, v.hash, u.text); !b) return tl::unexpected(b.error());
  store.hook("upload.blob-written");
  if (auto r = insert_revision(store, v, actor); !r) return tl::unexpected(r.error());
  if (auto f = record_facts(store.db(), v.program, v.hash, facts); !f)
    return tl::unexpected(f.error());
  if (checks.blocking() > 0) {
    if (auto s =
            set_state(store, v, RevisionState::CheckFailed, failed_check_reason(checks), actor);
        !s)
      return tl::unexpected(s.error());
    v.state = RevisionState::CheckFailed;
  }
  store.hook("upload.before-commit");
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  return PutResult{std::move(v), true};
}

}  // namespace

StoreResult<PutResult> put_revision(Store& store, const Upload& u, const Actor& actor) {
  if (auto ok = check_upload(store, u, actor); !ok) return tl::unexpected(ok.error());
  auto existing = program_if_any(store, u.name);
  if (!existing) return tl::unexpected(existing.error());
  std::string dialect = u.dialect;
  if (dialect.empty()) {
    dialect = *existing ? (*existing)->dialect : std::string(gcode::guess_dialect(u.text).dialect);
    if (gcode::find_dialect(dialect) == nullptr) dialect = "rs274ngc";
  }
  std::string machine_class = u.machine_class;
  if (machine_class.empty()) machine_class = *existing ? (*existing)->machine_class : "default";
  // The check runs outside the transaction: a long program never holds the writers up.
  const CheckResults checks = check_program(u.text, {dialect, u.profile});
  const ProgramFacts facts = read_facts(u.text, dialect);
  Revision v;
  v.program = u.name;
  v.hash = sha256_hex(u.text);
  v.size = static_cast<std::int64_t>(u.text.size());
  v.author = actor.user;
  v.created_at_us = v.state_at_us = store.now_us();
  v.reason = u.reason;
  v.dialect = dialect;
  v.check_blocking = checks.blocking();
  v.checks_json = checks.to_json();
  return write_revision(store, u, std::move(v), checks, facts, machine_class, actor);
}

StoreResult<Program> find_program(Store& store, std::string_view name) {
  auto rows = store.db().query(
      "SELECT name, machine_class, dialect, created_at FROM programs WHERE name = $1", {name});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty())
    return store_error(StoreErrorKind::NotFound, fmt::format("no program {}", name));
  const SqlRow& r = rows->front();
  return Program{r.text(0), r.text(1), r.text(2), r.integer(3)};
}

StoreResult<std::vector<Program>> list_programs(Store& store) {
  auto rows = store.db().query(
      "SELECT name, machine_class, dialect, created_at FROM programs ORDER BY name");
  if (!rows) return tl::unexpected(rows.error());
  std::vector<Program> out;
  out.reserve(rows->size());
  for (const SqlRow& r : *rows)
    out.push_back({r.text(0), r.text(1), r.text(2), r.integer(3)});
  return out;
}

StoreResult<std::vector<Revision>> list_revisions(Store& store, const RevisionQuery& q) {
  const std::string sql = fmt::format(
      "SELECT {} FROM revisions WHERE ($1 = '' OR program = $1) AND ($2 = '' OR state = $2) "
      "ORDER BY id DESC LIMIT $3 OFFSET $4",
      kRevisionColumns);
  auto rows = store.db().query(
      sql, {std::string_view(q.program), q.state ? state_name(*q.state) : std::string_view(),
            static_cast<std::int64_t>(q.limit), static_cast<std::int64_t>(q.offset)});
  if (!rows) return tl::unexpected(rows.error());
  std::vector<Revision> out;
  out.reserve(rows->size());
  for (const SqlRow& r : *rows)
    out.push_back(revision_of(r));
  return out;
}

StoreResult<Revision> find_revision(Store& store, std::string_view program, std::string_view hash) {
  auto rows = store.db().query(
      fmt::format("SELECT {} FROM revisions WHERE program = $1 AND hash = $2", kRevisionColumns),
      {program, hash});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) {
    return store_error(StoreErrorKind::NotFound,
                       fmt::format("program {} has no revision {}", program, hash));
  }
  return revision_of(rows->front());
}

StoreResult<std::string> revision_bytes(Store& store, std::string_view program,
                                        std::string_view hash) {
  auto v = find_revision(store, program, hash);
  if (!v) return tl::unexpected(v.error());
  return read_blob(store, v->hash);
}

namespace {

std::optional<std::string> precondition(const Revision& v, RevisionState to) {
  if (!transition_exists(v.state, to)) {
    return fmt::format("{} → {} is not allowed: {}", state_name(v.state), state_name(to),
                       why_not(v.state, to));
  }
  if (to == RevisionState::Checked && v.check_blocking > 0) {
    return fmt::format(
        "the check of this revision failed ({} errors or moves past travel); "
        "it can become check-failed or rejected",
        v.check_blocking);
  }
  if (to == RevisionState::CheckFailed && v.check_blocking == 0)
    return std::string("the check of this revision found nothing to fail it");
  return std::nullopt;
}

}  // namespace

StoreResult<Revision> change_state(Store& store, std::string_view program, std::string_view hash,
                                   RevisionState to, std::string_view reason, const Actor& actor) {
  if (auto r = check_text("reason", reason, kMaxReasonBytes); !r) return tl::unexpected(r.error());
  if (auto r = check_name("user name", actor.user); !r) return tl::unexpected(r.error());
  if (auto r = check_text("origin", actor.origin, kMaxOriginBytes); !r)
    return tl::unexpected(r.error());
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  auto v = find_revision(store, program, hash);
  if (!v) return tl::unexpected(v.error());
  if (auto why = precondition(*v, to)) return store_error(StoreErrorKind::Refused, *why);
  if (auto s = set_state(store, *v, to, reason, actor); !s) return tl::unexpected(s.error());
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  v->state = to;
  return v;
}

StoreResult<std::optional<Revision>> released_revision(Store& store, std::string_view program) {
  auto rows = store.db().query(
      fmt::format("SELECT {} FROM revisions WHERE program = $1 AND state = 'released' "
                  "ORDER BY state_at DESC, id DESC LIMIT 1",
                  kRevisionColumns),
      {program});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return std::optional<Revision>();
  return std::optional<Revision>(revision_of(rows->front()));
}

}  // namespace usina::dnc
