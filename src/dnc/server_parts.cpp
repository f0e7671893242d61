// A machine's parts: a drip feed run to its end is a part (the store counts
// them from its jobs); each is a `machine.part` event with the count and
// the cycle's time, for the MTConnect adapter and MQTT.
#include "dnc/server_machines.hpp"

namespace usina::dnc {

void Machines::count_part(MachineRuntime& m, const JobRecord& job) {
  auto parts = machine_part_count(store_, m.config.link.name);
  if (!parts) return;
  nlohmann::json e = {{"machine", m.config.link.name},
                      {"part_count", parts->parts},
                      {"program", job.program},
                      {"job", job.id},
                      {"source", "drip"},
                      {"at_us", job.ended_at_us}};
  e["last_cycle_seconds"] =
      parts->last_cycle_seconds ? nlohmann::json(*parts->last_cycle_seconds) : nullptr;
  events_.publish("machine.part", std::move(e));
}

}  // namespace usina::dnc
