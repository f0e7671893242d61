#include "dnc/store_jobs.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "dnc/store_audit.hpp"

namespace usina::dnc {
namespace {

constexpr std::string_view kJobColumns =
    "id, machine, program, revision, mode, state, actor, created_at, started_at, ended_at, "
    "bytes_sent, bytes_total, line, block, sha256, reason, alarm";

JobRecord job_of(const SqlRow& r) {
  JobRecord j;
  j.id = r.integer(0);
  j.machine = r.text(1);
  j.program = r.text(2);
  j.revision = r.text(3);
  j.mode = r.text(4);
  j.state = r.text(5);
  j.actor = r.text(6);
  j.created_at_us = r.integer(7);
  j.started_at_us = r.integer(8);
  j.ended_at_us = r.integer(9);
  j.bytes_sent = static_cast<std::uint64_t>(r.integer(10));
  j.bytes_total = static_cast<std::uint64_t>(r.integer(11));
  j.line = static_cast<std::uint64_t>(r.integer(12));
  j.block = r.integer(13);
  j.sha256 = r.text(14);
  j.reason = r.text(15);
  j.alarm = r.integer(16) != 0;
  return j;
}

std::int64_t i64(std::uint64_t v) {
  return static_cast<std::int64_t>(v);
}

std::string job_subject(const JobRecord& j) {
  return fmt::format("job {} {}@{} to {}", j.id, j.program, j.revision, j.machine);
}

StoreResult<void> audit_job(Store& store, const Actor& actor, std::string_view action,
                            const JobRecord& j) {
  const nlohmann::json detail = {
      {"job", j.id},    {"mode", j.mode},   {"state", j.state},  {"bytes_sent", j.bytes_sent},
      {"line", j.line}, {"block", j.block}, {"sha256", j.sha256}};
  auto a =
      append_audit(store, actor, {std::string(action), job_subject(j), j.reason, detail.dump()});
  if (!a) return tl::unexpected(a.error());
  return {};
}

}  // namespace

bool job_ended(std::string_view state) {
  return state == "done" || state == "interrupted" || state == "failed";
}

StoreResult<JobRecord> create_job(Store& store, JobRecord job, const Actor& actor) {
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return tl::unexpected(b.error());
  job.created_at_us = store.now_us();
  auto rows = store.db().query(
      "INSERT INTO jobs (machine, program, revision, mode, state, actor, created_at, bytes_total) "
      "VALUES ($1, $2, $3, $4, $5, $6, $7, $8) RETURNING id",
      {std::string_view(job.machine), std::string_view(job.program), std::string_view(job.revision),
       std::string_view(job.mode), std::string_view(job.state), std::string_view(job.actor),
       job.created_at_us, i64(job.bytes_total)});
  if (!rows) return tl::unexpected(rows.error());
  job.id = rows->front().integer(0);
  if (auto a = audit_job(store, actor, "job.create", job); !a) return tl::unexpected(a.error());
  if (auto c = tx.commit(); !c) return tl::unexpected(c.error());
  return job;
}

StoreResult<void> update_job(Store& store, const JobRecord& j, const Actor& actor) {
  Transaction tx(store.db());
  if (auto b = tx.begin_write(); !b) return b;
  auto r = store.db().query(
      "UPDATE jobs SET state = $2, started_at = $3, ended_at = $4, bytes_sent = $5, "
      "bytes_total = $6, line = $7, block = $8, sha256 = $9, reason = $10, alarm = $11 "
      "WHERE id = $1",
      {j.id, std::string_view(j.state), j.started_at_us, j.ended_at_us, i64(j.bytes_sent),
       i64(j.bytes_total), i64(j.line), j.block, std::string_view(j.sha256),
       std::string_view(j.reason), std::int64_t{j.alarm ? 1 : 0}});
  if (!r) return tl::unexpected(r.error());
  if (job_ended(j.state)) {
    if (auto a = audit_job(store, actor, "job." + j.state, j); !a) return a;
  }
  return tx.commit();
}

StoreResult<JobRecord> find_job(Store& store, std::int64_t id) {
  auto rows = store.db().query(fmt::format("SELECT {} FROM jobs WHERE id = $1", kJobColumns), {id});
  if (!rows) return tl::unexpected(rows.error());
  if (rows->empty()) return store_error(StoreErrorKind::NotFound, fmt::format("no job {}", id));
  return job_of(rows->front());
}

StoreResult<std::vector<JobRecord>> list_jobs(Store& store, std::string_view machine,
                                              std::size_t limit) {
  auto rows = store.db().query(
      fmt::format("SELECT {} FROM jobs WHERE machine = $1 ORDER BY id DESC LIMIT $2", kJobColumns),
      {machine, static_cast<std::int64_t>(limit)});
  if (!rows) return tl::unexpected(rows.error());
  std::vector<JobRecord> out;
  for (const SqlRow& r : *rows)
    out.push_back(job_of(r));
  return out;
}

StoreResult<std::int64_t> interrupt_unfinished_jobs(Store& store, std::string_view reason,
                                                    std::optional<std::int64_t> last_alive_us) {
  auto rows =
      store.db().query(fmt::format("SELECT {} FROM jobs WHERE state IN ('queued', "
                                   "'running') ORDER BY id",
                                   kJobColumns));
  if (!rows) return tl::unexpected(rows.error());
  const Actor server{"usina", "server"};
  for (const SqlRow& r : *rows) {
    JobRecord j = job_of(r);
    j.state = "interrupted";
    j.ended_at_us = last_alive_us ? std::max({*last_alive_us, j.started_at_us, j.created_at_us})
                                  : store.now_us();
    j.reason = fmt::format("interrupted at byte {}, line {}: {}", j.bytes_sent, j.line, reason);
    if (auto u = update_job(store, j, server); !u) return tl::unexpected(u.error());
  }
  return static_cast<std::int64_t>(rows->size());
}

StoreResult<PartCount> machine_part_count(Store& store, std::string_view machine) {
  auto rows = store.db().query(
      "SELECT COUNT(*), MAX(id) FROM jobs WHERE machine = $1 AND mode = 'drip' AND state = 'done'",
      {machine});
  if (!rows) return tl::unexpected(rows.error());
  PartCount p;
  p.parts = rows->front().integer(0);
  if (p.parts == 0) return p;
  auto last = find_job(store, rows->front().integer(1));
  if (!last) return tl::unexpected(last.error());
  p.last_cycle_seconds = static_cast<double>(last->ended_at_us - last->started_at_us) / 1e6;
  p.last_program = last->program;
  p.last_run_at_us = last->ended_at_us;
  return p;
}

}  // namespace usina::dnc
