// Machines' jobs: what a machine may take, the queue, a job's start and end.
#include <algorithm>

#include <fmt/format.h>

#include "dnc/program_source.hpp"
#include "dnc/server_machines.hpp"
#include "dnc/store_revisions.hpp"
#include "dnc/tape_writer.hpp"

namespace usina::dnc {
namespace {

const Actor kServer{"usina", "server"};

}  // namespace

void apply_report(JobRecord& job, const JobReport& r) {
  job.state = std::string(job_state_name(r.state));
  job.bytes_sent = r.bytes_sent;
  job.line = r.line;
  job.block = r.block;
  job.sha256 = r.sha256;
  job.reason = r.reason;
  job.alarm = r.alarm;
}

tl::expected<std::uint64_t, std::string> wire_bytes(const LinkConfig& link, std::string_view text) {
  TapeWriter writer(tape_format(link));
  std::vector<std::uint8_t> rows;
  std::vector<BlockMark> marks;
  std::uint64_t total = 0;
  constexpr std::size_t kSlice = 1 << 16;
  for (std::size_t at = 0; at < text.size(); at += kSlice) {
    if (!writer.write(text.substr(at, kSlice), rows, marks))
      return tl::unexpected(writer.diagnostic().message);
    total += rows.size();
    rows.clear();
    marks.clear();
  }
  if (!writer.finish(rows, marks)) return tl::unexpected(writer.diagnostic().message);
  return total + rows.size();
}

// Production machines take the program's released revision only; try-out
// machines approved ones too. A machine of a class takes that class's programs.
StoreResult<void> Machines::may_take(const MachineRuntime& m, const JobOrder& order) {
  auto program = find_program(store_, order.program);
  if (!program) return tl::unexpected(program.error());
  auto rev = find_revision(store_, order.program, order.revision);
  if (!rev) return tl::unexpected(rev.error());
  const std::string& name = m.config.link.name;
  if (!m.config.machine_class.empty() && program->machine_class != m.config.machine_class) {
    return store_error(
        StoreErrorKind::Refused,
        fmt::format("{} is a program of machine class `{}`; machine {} is of "
                    "class `{}`",
                    order.program, program->machine_class, name, m.config.machine_class));
  }
  const bool tryout = m.config.link.mode == MachineMode::Tryout;
  if (!sendable(rev->state, tryout)) {
    return store_error(
        StoreErrorKind::Refused,
        fmt::format("revision {} of {} is {}; machine {} ({}) takes {} revisions only",
                    order.revision.substr(0, 12), order.program, state_name(rev->state), name,
                    mode_name(m.config.link.mode), tryout ? "approved or released" : "released"));
  }
  if (tryout || rev->state != RevisionState::Released) return {};
  auto released = released_revision(store_, order.program);
  if (!released) return tl::unexpected(released.error());
  if (!*released || (*released)->hash != rev->hash) {
    return store_error(StoreErrorKind::Refused,
                       fmt::format("revision {} of {} is not the program's released revision "
                                   "(a newer one is); a production machine takes only that one",
                                   order.revision.substr(0, 12), order.program));
  }
  return {};
}

StoreResult<JobRecord> Machines::submit(MachineRuntime& m, const JobOrder& order,
                                        const Actor& actor) {
  if (stopping_) return store_error(StoreErrorKind::Refused, "the server is stopping");
  if (auto ok = may_take(m, order); !ok) return tl::unexpected(ok.error());
  JobRecord job;
  job.machine = m.config.link.name;
  job.program = order.program;
  job.revision = order.revision;
  job.mode = order.mode == JobMode::Drip ? "drip" : "send";
  job.state = "queued";
  job.actor = actor.user;
  auto made = create_job(store_, job, actor);
  if (!made) return made;
  if (order.restart) restarts_[made->id] = order.restart;
  publish_job(*made);
  m.queue.push_back(made->id);
  start_next(m);
  if (m.current && m.current->id == made->id) return *m.current;
  return find_job(store_, made->id);
}

void Machines::start_next(MachineRuntime& m) {
  while (!stopping_ && !m.current && !m.queue.empty() && m.station &&
         m.station->state() == StationState::Idle) {
    auto job = find_job(store_, m.queue.front());
    m.queue.pop_front();
    if (job) launch(m, *job);
  }
}

StoreResult<JobRecord> Machines::cancel_queued(MachineRuntime& m, std::int64_t id,
                                               const std::string& reason, const Actor& actor) {
  const auto at = std::find(m.queue.begin(), m.queue.end(), id);
  if (at == m.queue.end())
    return store_error(StoreErrorKind::Conflict,
                       fmt::format("job {} is not queued on {}", id, m.config.link.name));
  auto job = find_job(store_, id);
  if (!job) return job;
  m.queue.erase(at);
  restarts_.erase(id);
  job->state = "interrupted";
  job->reason = reason;
  job->ended_at_us = store_.now_us();
  save(*job, actor);
  publish_job(*job);
  return job;
}

void Machines::fail_job(JobRecord job, const std::string& reason) {
  job.state = "failed";
  job.reason = reason;
  job.ended_at_us = store_.now_us();
  save(job, kServer);
  publish_job(job);
}

// Reads the revision (verified against its hash), checks it may still go,
// and hands it to the station; false when the job failed instead.
bool Machines::launch(MachineRuntime& m, JobRecord job) {
  const JobOrder order{job.program, job.revision,
                       job.mode == "drip" ? JobMode::Drip : JobMode::Send, nullptr};
  if (auto ok = may_take(m, order); !ok) {
    fail_job(job, ok.error().message);
    return false;
  }
  auto bytes = revision_bytes(store_, job.program, job.revision);
  if (!bytes) {
    fail_job(job, bytes.error().message);
    return false;
  }
  if (auto restart = restarts_.find(job.id); restart != restarts_.end()) {
    *bytes = *restart->second;  // checked against the revision when it was asked for
    restarts_.erase(restart);
  }
  auto total = wire_bytes(m.config.link, *bytes);
  if (!total) {
    fail_job(job, *total.error().c_str() ? total.error() : "the program cannot be put on tape");
    return false;
  }
  job.bytes_total = *total;
  std::string why;
  const bool started = m.station->submit(
      string_source(std::move(*bytes)), order.mode,
      [this, &m](const JobReport& r) { on_job_done(m, r); }, &why);
  if (!started) {
    fail_job(job, why);
    return false;
  }
  job.state = "running";
  job.started_at_us = store_.now_us();
  m.current = job;
  m.alarmed = false;
  note_activity(m);
  m.progress_seen = 0;
  m.ticks_since_saved = 0;
  save(job, kServer);
  publish_job(job);
  return true;
}

void Machines::on_job_done(MachineRuntime& m, const JobReport& r) {
  if (!m.current) return;
  JobRecord job = *m.current;
  apply_report(job, r);
  job.ended_at_us = store_.now_us();
  m.current.reset();
  if (job.alarm) m.alarmed = true;
  note_activity(m);
  save(job, Actor{job.actor, "server"});
  publish_job(job);
  if (job.mode == "drip" && job.state == "done") count_part(m, job);
  finish_stop();  // when the server is stopping, this may have been the last job
}

}  // namespace usina::dnc
