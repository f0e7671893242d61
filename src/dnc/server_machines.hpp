// The server's machines: one station per `[[machine]]` (station.hpp), each
// with its queue of jobs. A job is a row of the store (store_jobs.hpp) from
// queued to how it ended; only a revision the machine may take is queued
// (production: the program's released revision; try-out: approved ones
// too). A queued job starts when its machine is idle; when it ends the
// machine's next starts. Punches become draft revisions; remote requests
// are answered from the store. Every change is an event (api_events.hpp).
#pragma once

#include <chrono>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <boost/asio/steady_timer.hpp>

#include "dnc/api_events.hpp"
#include "dnc/server_config.hpp"
#include "dnc/station.hpp"
#include "dnc/store.hpp"
#include "dnc/store_jobs.hpp"

namespace usina::dnc {

// What the control itself said (DPRNT lines, `(MSG` comments): server_mdc.cpp;
// kept in the store (store_parts.hpp) and read back when the server starts.
struct ControlReports {
  std::int64_t parts = 0;                     // part lines seen
  std::optional<std::int64_t> control_count;  // the count the control printed last
  std::optional<double> last_cycle_seconds;   // printed, or between two part lines
  std::int64_t last_part_at_us = 0;
  std::string last_message;
};

struct MachineRuntime {
  ServerMachine config;
  std::shared_ptr<Station> station;
  std::deque<std::int64_t> queue;      // queued jobs, oldest first
  std::optional<JobRecord> current;    // the running job
  std::uint64_t progress_seen = 0;     // bytes at the last progress event
  unsigned ticks_since_saved = 0;      // progress is written every few seconds
  std::optional<JobRecord> answering;  // the job of a remote request being answered
  std::string link_error;              // why the port did not open, last time
  ControlReports reported;
  std::string activity;  // the last recorded (store_utilisation.hpp), "" before the first
  bool alarmed = false;  // the last job ended on an alarm; until the next one starts
};

struct JobOrder {
  std::string program;
  std::string revision;
  JobMode mode = JobMode::Send;
  // A restart (start_block / start_tool): the restart program (dnc/resume.hpp)
  // that goes on the wire instead of the revision's bytes; null: the revision.
  std::shared_ptr<const std::string> restart;
};

class Machines {
 public:
  Machines(asio::io_context& io, Store& store, EventHub& events, std::vector<ServerMachine> config);

  // Opens every machine's port and listens.
  void start();
  // Stops every running job (interrupted, with `reason`), marks queued jobs
  // interrupted, closes the ports; `stopped` runs when all is written.
  void stop(const std::string& reason, std::function<void()> stopped);

  MachineRuntime* find(std::string_view name);

  // The machine classes' profiles, for the check of what the machines punch.
  void use_profiles(const std::map<std::string, sim::MachineProfile>* profiles) {
    profiles_ = profiles;
  }

  const std::vector<std::unique_ptr<MachineRuntime>>& all() const { return machines_; }

  // The calendar of a machine added without one (the server's [calendar]).
  void use_calendar(std::optional<ShiftCalendar> calendar) { calendar_ = std::move(calendar); }

  // An admin's changes (server_machine_admin.cpp). A machine added, its
  // port opened; a machine's settings replaced, its port opened again; a
  // machine retired, its port closed and it is no longer listed (its
  // runtime is kept: its old station's handlers still name it). Change and
  // retire only a machine `may_change` allows.
  MachineRuntime& add(ServerMachine config);
  // Refused while the machine has a job queued or running, or is receiving
  // or answering a punch: what is on its wire is left alone.
  StoreResult<void> may_change(const MachineRuntime& m) const;
  void replace(MachineRuntime& m, ServerMachine config);
  void retire(MachineRuntime& m);

  // Queues a job (and starts it when the machine is idle). NotFound for an
  // unknown program or revision; Refused when the machine may not take it.
  StoreResult<JobRecord> submit(MachineRuntime& m, const JobOrder& order, const Actor& actor);
  // Whether the machine may take the revision (production: released only).
  StoreResult<void> may_take(const MachineRuntime& m, const JobOrder& order);
  // The job as stored, with the running job's live progress.
  StoreResult<JobRecord> job(std::int64_t id);
  // Takes a queued job off its machine's queue: it ends interrupted with
  // `reason`, nothing of it sent. Refused when the job is not queued there.
  StoreResult<JobRecord> cancel_queued(MachineRuntime& m, std::int64_t id,
                                       const std::string& reason, const Actor& actor);

 private:
  StationEvents station_events(MachineRuntime& m);
  void start_next(MachineRuntime& m);
  bool launch(MachineRuntime& m, JobRecord job);
  void fail_job(JobRecord job, const std::string& reason);
  void on_job_done(MachineRuntime& m, const JobReport& r);
  void count_part(MachineRuntime& m, const JobRecord& job);  // server_parts.cpp
  // A punch without an O number read as machine data; false when nothing in it was.
  bool machine_data(MachineRuntime& m, const ReceivedProgram& r);  // server_mdc.cpp
  void load_reports(MachineRuntime& m);  // what the control said before a restart
  void keep(const MachineRuntime& m, StoreResult<void> written);
  // Records the machine's activity when it changed (server_activity.cpp);
  // `off` when the server stops.
  void note_activity(MachineRuntime& m, bool server_stopped = false);
  // Every kHeartbeatTicks ticks, the server's sign of life in the store
  // (server_activity.cpp): where a kill -9 ends the machines' activity.
  void heartbeat();
  void on_punch(MachineRuntime& m, const ReceivedProgram& r);
  void on_request(MachineRuntime& m, const RemoteRequest& r, const AnswerFunction& answer);
  void on_request_answered(MachineRuntime& m, const JobReport& r);
  void save(const JobRecord& job, const Actor& actor);
  void publish_job(const JobRecord& job);
  void tick();
  void finish_stop();
  void open_station(MachineRuntime& m);

  asio::io_context& io_;
  Store& store_;
  EventHub& events_;
  std::vector<std::unique_ptr<MachineRuntime>> machines_;
  asio::steady_timer ticker_;
  std::function<void()> stopped_;
  const std::map<std::string, sim::MachineProfile>* profiles_ = nullptr;
  bool stopping_ = false;
  bool started_ = false;
  std::optional<ShiftCalendar> calendar_;
  std::vector<std::unique_ptr<MachineRuntime>> retired_;
  unsigned ticks_since_heartbeat_ = 0;
  // The restart programs of queued restart jobs, by job id (a job queued
  // before a restart of the server is interrupted, so memory is enough).
  std::map<std::int64_t, std::shared_ptr<const std::string>> restarts_;
};

// The job's record updated from the sender's report (state, bytes, line,
// block, hash, reason).
void apply_report(JobRecord& job, const JobReport& r);
// The rows a revision makes on the machine's wire; or why it cannot be sent.
tl::expected<std::uint64_t, std::string> wire_bytes(const LinkConfig& link, std::string_view text);

nlohmann::json job_json(const JobRecord& j);
// The part count and last cycle of the machine: its drip feeds (the store)
// and what its control reported.
nlohmann::json parts_json(Store& store, const MachineRuntime& m);

}  // namespace usina::dnc
