// Machines added, changed and retired by an admin while the server runs
// (docs/dnc-server.md, "Machines added from the page"). The store keeps
// them (store_machines.hpp); here their stations open and close.
#include <algorithm>

#include <fmt/format.h>

#include "dnc/server_machines.hpp"

namespace usina::dnc {

MachineRuntime& Machines::add(ServerMachine config) {
  auto m = std::make_unique<MachineRuntime>();
  if (!config.calendar) config.calendar = calendar_;
  m->config = std::move(config);
  load_reports(*m);
  MachineRuntime& added = *m;
  machines_.push_back(std::move(m));
  if (started_ && !stopping_) open_station(added);
  return added;
}

StoreResult<void> Machines::may_change(const MachineRuntime& m) const {
  const std::string& name = m.config.link.name;
  if (m.current)
    return store_error(
        StoreErrorKind::Conflict,
        fmt::format("{} is running job {}; stop it or wait for its end", name, m.current->id));
  if (!m.queue.empty())
    return store_error(
        StoreErrorKind::Conflict,
        fmt::format("{} has {} queued job(s); remove them first", name, m.queue.size()));
  const StationState s = m.station ? m.station->state() : StationState::Offline;
  if (s == StationState::Receiving || s == StationState::Sending || m.answering)
    return store_error(StoreErrorKind::Conflict,
                       fmt::format("{} is {}; wait until it is idle", name, station_state_name(s)));
  return {};
}

void Machines::replace(MachineRuntime& m, ServerMachine config) {
  if (!config.calendar) config.calendar = calendar_;
  if (m.station) m.station->shutdown();
  m.config = std::move(config);
  m.link_error.clear();
  if (started_ && !stopping_) open_station(m);
}

void Machines::retire(MachineRuntime& m) {
  if (m.station) m.station->shutdown();
  note_activity(m, true);
  const auto it = std::find_if(machines_.begin(), machines_.end(),
                               [&m](const auto& p) { return p.get() == &m; });
  if (it == machines_.end()) return;
  retired_.push_back(std::move(*it));
  machines_.erase(it);
}

}  // namespace usina::dnc
