#include "dnc/server_machines.hpp"

#include <fmt/format.h>

namespace usina::dnc {
namespace {

constexpr auto kTick = std::chrono::seconds(1);
constexpr unsigned kSaveEveryTicks = 5;  // progress written to the store every 5 s

nlohmann::json optional_time(std::int64_t us) {
  return us == 0 ? nlohmann::json(nullptr) : nlohmann::json(us);
}

}  // namespace

nlohmann::json job_json(const JobRecord& j) {
  return {{"job", j.id},
          {"machine", j.machine},
          {"program", j.program},
          {"revision", j.revision},
          {"mode", j.mode},
          {"state", j.state},
          {"user", j.actor},
          {"bytes_sent", j.bytes_sent},
          {"bytes_total", j.bytes_total},
          {"line", j.line},
          {"block", j.block >= 0 ? nlohmann::json(j.block) : nlohmann::json(nullptr)},
          {"sha256", j.sha256},
          {"hash", j.sha256},
          {"reason", j.reason},
          {"alarm", j.alarm},
          {"created_at_us", j.created_at_us},
          {"started_at_us", optional_time(j.started_at_us)},
          {"ended_at_us", optional_time(j.ended_at_us)}};
}

Machines::Machines(asio::io_context& io, Store& store, EventHub& events,
                   std::vector<ServerMachine> config)
    : io_(io), store_(store), events_(events), ticker_(io) {
  for (ServerMachine& c : config) {
    auto m = std::make_unique<MachineRuntime>();
    m->config = std::move(c);
    load_reports(*m);
    machines_.push_back(std::move(m));
  }
}

void Machines::start() {
  started_ = true;
  for (auto& m : machines_)
    open_station(*m);
  tick();
}

void Machines::open_station(MachineRuntime& m) {
  m.station = std::make_shared<Station>(io_, m.config.link, station_events(m));
  m.station->start();
  note_activity(m);
}

StationEvents Machines::station_events(MachineRuntime& m) {
  StationEvents e;
  e.state = [this, &m](StationState s) {
    events_.publish("machine.state",
                    {{"machine", m.config.link.name}, {"state", station_state_name(s)}});
    note_activity(m);
    if (s == StationState::Idle) start_next(m);
  };
  e.punched = [this, &m](const ReceivedProgram& r) {
    if (!machine_data(m, r)) on_punch(m, r);
  };
  e.request = [this, &m](const LinkConfig&, const RemoteRequest& r, AnswerFunction answer) {
    on_request(m, r, answer);
  };
  e.request_answered = [this, &m](const JobReport& r) { on_request_answered(m, r); };
  e.link_error = [this, &m](const std::string& why) {
    m.link_error = why;
    events_.publish("machine.link_error", {{"machine", m.config.link.name}, {"error", why}});
  };
  return e;
}

MachineRuntime* Machines::find(std::string_view name) {
  for (auto& m : machines_) {
    if (m->config.link.name == name) return m.get();
  }
  return nullptr;
}

StoreResult<JobRecord> Machines::job(std::int64_t id) {
  for (auto& m : machines_) {
    if (m->current && m->current->id == id) {
      JobRecord live = *m->current;
      if (const JobReport* r = m->station->job()) apply_report(live, *r);
      live.state = "running";
      return live;
    }
  }
  return find_job(store_, id);
}

void Machines::save(const JobRecord& job, const Actor& actor) {
  if (auto r = update_job(store_, job, actor); !r) {
    events_.publish("server.error", {{"job", job.id}, {"error", r.error().message}});
  }
}

void Machines::publish_job(const JobRecord& job) {
  events_.publish("job." + job.state, job_json(job));
}

// Once a second: a progress event for each job that moved, and now and
// then its progress written (what a restart after kill -9 shows).
void Machines::tick() {
  heartbeat();
  for (auto& m : machines_) {
    if (!m->current) continue;
    const JobReport* r = m->station->job();
    if (r == nullptr || r->bytes_sent == m->progress_seen) continue;
    m->progress_seen = r->bytes_sent;
    JobRecord live = *m->current;
    apply_report(live, *r);
    live.state = "running";
    events_.publish("job.progress", job_json(live));
    if (++m->ticks_since_saved >= kSaveEveryTicks) {
      m->ticks_since_saved = 0;
      save(live, Actor{"usina", "server"});
    }
  }
  ticker_.expires_after(kTick);
  ticker_.async_wait([this](const boost::system::error_code& ec) {
    if (!ec && !stopping_) tick();
  });
}

void Machines::stop(const std::string& reason, std::function<void()> stopped) {
  stopping_ = true;
  stopped_ = std::move(stopped);
  ticker_.cancel();
  for (auto& m : machines_) {
    for (const std::int64_t id : m->queue) {
      if (auto j = find_job(store_, id)) {
        j->state = "interrupted";
        j->ended_at_us = store_.now_us();
        j->reason = fmt::format("never started: {}", reason);
        save(*j, Actor{"usina", "server"});
        publish_job(*j);
      }
    }
    m->queue.clear();
    if (m->current) m->station->stop_job(reason);
  }
  finish_stop();
}

// The ports close once no job is left running (their ends are written).
void Machines::finish_stop() {
  if (!stopping_ || !stopped_) return;
  for (auto& m : machines_) {
    if (m->current) return;
  }
  for (auto& m : machines_) {
    if (m->station) m->station->shutdown();
    note_activity(*m, true);
  }
  auto stopped = std::move(stopped_);
  stopped_ = nullptr;
  stopped();
}

}  // namespace usina::dnc
