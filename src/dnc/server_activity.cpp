// A machine's activity for its utilisation (store_utilisation.hpp), from
// its station's state, its running job and its last alarm: recorded in the
// store each time it changes, so the days can be summed after a restart.
#include "dnc/server_machines.hpp"
#include "dnc/store_utilisation.hpp"

namespace usina::dnc {
namespace {

// Seconds between heartbeats: after a kill -9 at most this much of the
// machines' last activity is counted past the server's death.
constexpr unsigned kHeartbeatTicks = 10;

std::string_view activity_of(const MachineRuntime& m) {
  const StationState s = m.station ? m.station->state() : StationState::Offline;
  switch (s) {
  case StationState::Offline: return "down";
  case StationState::Receiving: return "transfer";
  case StationState::Sending:
    if (m.current) return m.current->mode == "drip" ? "feeding" : "transfer";
    // A remote request's answer is a transfer; a refusal's few bytes, or
    // the moments between a job's start or end and the station's state, are not.
    return m.answering ? "transfer" : "idle";
  case StationState::Idle: return m.alarmed ? "alarm" : "idle";
  }
  return "idle";
}

}  // namespace

void Machines::note_activity(MachineRuntime& m, bool server_stopped) {
  const std::string_view now = server_stopped ? "off" : activity_of(m);
  if (m.activity == now) return;
  m.activity = now;
  keep(m, record_activity(store_, m.config.link.name, now, store_.now_us()));
}

void Machines::heartbeat() {
  if (ticks_since_heartbeat_++ % kHeartbeatTicks != 0) return;
  if (auto r = record_heartbeat(store_, store_.now_us()); !r)
    events_.publish("server.error", {{"error", r.error().message}});
}

}  // namespace usina::dnc
