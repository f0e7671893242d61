// The server's jobs, store side: a send or drip feed of one revision to one
// machine, from queued to how it ended (done, interrupted at byte/line/block,
// failed), with the SHA-256 of the bytes put on the wire. Starting and ending
// a job are audit entries. A job the server did not see to its end (a
// SIGTERM, a kill -9) is marked interrupted when the store is next opened by
// the server (`interrupt_unfinished_jobs`): never resent, never resumed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dnc/store.hpp"

namespace usina::dnc {

struct JobRecord {
  std::int64_t id = 0;
  std::string machine;
  std::string program;
  std::string revision;
  std::string mode;   // "send" | "drip"
  std::string state;  // "queued" | "running" | "done" | "interrupted" | "failed"
  std::string actor;
  std::int64_t created_at_us = 0;
  std::int64_t started_at_us = 0;
  std::int64_t ended_at_us = 0;
  std::uint64_t bytes_sent = 0;
  std::uint64_t bytes_total = 0;
  std::uint64_t line = 0;
  std::int64_t block = -1;
  std::string sha256;
  std::string reason;
  bool alarm = false;
};

// A new queued job (its id filled in), with its audit entry.
StoreResult<JobRecord> create_job(Store& store, JobRecord job, const Actor& actor);
// Writes the job's state and progress; an ended job also gets an audit entry.
StoreResult<void> update_job(Store& store, const JobRecord& job, const Actor& actor);
StoreResult<JobRecord> find_job(Store& store, std::int64_t id);
// The machine's jobs, newest first.
StoreResult<std::vector<JobRecord>> list_jobs(Store& store, std::string_view machine,
                                              std::size_t limit);
// Queued and running jobs become interrupted with `reason`; how many. They
// ended when the server was last seen alive (`last_alive_us`, its last
// heartbeat, never before the job's start), else now.
StoreResult<std::int64_t> interrupt_unfinished_jobs(Store& store, std::string_view reason,
                                                    std::optional<std::int64_t> last_alive_us);

// What the drip feeds of a machine say about its parts: each drip feed that
// ran to its end is a part; its start to end is the cycle's time.
struct PartCount {
  std::int64_t parts = 0;
  std::optional<double> last_cycle_seconds;
  std::string last_program;
  std::int64_t last_run_at_us = 0;
};

StoreResult<PartCount> machine_part_count(Store& store, std::string_view machine);

bool job_ended(std::string_view state);

}  // namespace usina::dnc
